"""3D export: the file holds exactly the D-form the core computed, in the unit asked, and the
volume and area in the message are those of the written mesh (recomputed here from the file:
volume by the divergence theorem, sum of signed tetrahedra; area by cross products)."""

import io
import math
import os
import re
import struct
import tempfile
import unittest
from contextlib import redirect_stderr

import support

from dformer_export3d import Export3D

DATA = os.path.join(support.HERE, "data", "svg")


def read_obj(path):
    verts, groups = read_obj_groups(path)
    return verts, [f for faces in groups.values() for f in faces]


def read_stl(path):
    with open(path, "rb") as fh:
        data = fh.read()
    (n,) = struct.unpack_from("<I", data, 80)
    assert len(data) == 84 + 50 * n, f"binary STL size: wanted {84 + 50 * n}, got {len(data)}"
    tris = [struct.unpack_from("<12f", data, 84 + 50 * t)[3:] for t in range(n)]
    return [(t[0:3], t[3:6], t[6:9]) for t in tris]


def volume_area(tris):
    vol = area = 0.0
    for a, b, c in tris:
        cross = (
            (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
            (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
            (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]),
        )
        area += 0.5 * sum(x * x for x in cross) ** 0.5
        vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    return abs(vol), area


class Export3dFiles(unittest.TestCase):
    def export(self, name, *args):
        path = os.path.join(tempfile.mkdtemp(prefix="dformer-3d-"), name)
        err = io.StringIO()
        with redirect_stderr(err):
            Export3D().run([os.path.join(DATA, "connect_mm.svg"), "--id=A", "--id=B", f"--file={path}", "--resolution=16", *args], output=io.BytesIO())
        return path, err.getvalue()

    def reported(self, message):
        m = re.search(r"Volume ([\d.e+-]+) \w+³ \(([\d.e+-]+) L\), surface area ([\d.e+-]+)", message)
        self.assertIsNotNone(m, f"no volume/area in the message: {message!r}")
        return float(m.group(1)), float(m.group(2)), float(m.group(3))

    def test_obj_mesh_is_closed_and_its_volume_and_area_are_the_reported_ones(self):
        path, message = self.export("form.obj")
        verts, faces = read_obj(path)
        self.assertGreater(len(faces), 0)
        edges = {}
        for f in faces:
            for i in range(3):
                e = tuple(sorted((f[i], f[(i + 1) % 3])))
                edges[e] = edges.get(e, 0) + 1
        open_edges = [e for e, n in edges.items() if n != 2]
        self.assertEqual(open_edges, [], "a D-form is a closed surface: every edge in exactly two triangles")
        vol, area = volume_area([(verts[a], verts[b], verts[c]) for a, b, c in faces])
        got_vol, litres, got_area = self.reported(message)
        self.assertLess(support.rel(vol, got_vol), 1e-5, f"volume: file {vol}, message {got_vol}")
        self.assertLess(support.rel(area, got_area), 1e-5, f"area: file {area}, message {got_area}")
        self.assertLess(support.rel(litres, vol / 1e6), 1e-5, f"mm³ to litres: wanted {vol / 1e6}, got {litres}")

    def test_stl_holds_the_same_mesh_and_the_unit_scales_it(self):
        obj, _ = self.export("form.obj")
        stl, message = self.export("form.stl", "--unit=cm")
        verts, faces = read_obj(obj)
        vol_mm, area_mm = volume_area([(verts[a], verts[b], verts[c]) for a, b, c in faces])
        vol_cm, area_cm = volume_area(read_stl(stl))
        self.assertLess(support.rel(vol_cm, vol_mm / 1000), 1e-5, f"cm³ = mm³ / 1000: {vol_cm} vs {vol_mm}")
        self.assertLess(support.rel(area_cm, area_mm / 100), 1e-5, f"cm² = mm² / 100: {area_cm} vs {area_mm}")
        self.assertLess(support.rel(self.reported(message)[0], vol_cm), 1e-5)

    def test_a_missing_or_wrong_file_name_is_an_error(self):
        for name, wanted in (("", "Choose the file"), ("form.ply", ".obj or .stl")):
            err = io.StringIO()
            with redirect_stderr(err), self.assertRaises(SystemExit):
                Export3D().run([os.path.join(DATA, "connect_mm.svg"), "--id=A", "--id=B", f"--file={name}"], output=io.BytesIO())
            self.assertIn(wanted, err.getvalue())


if __name__ == "__main__":
    unittest.main()


def read_obj_groups(path):
    """Vertices, and the faces of each OBJ group (one group per piece)."""
    verts, groups = [], {}
    group = None
    with open(path, encoding="utf-8") as fh:
        for line in fh:
            parts = line.split()
            if parts and parts[0] == "v":
                verts.append(tuple(map(float, parts[1:4])))
            elif parts and parts[0] == "g":
                group = " ".join(parts[1:])
            elif parts and parts[0] == "f":
                groups.setdefault(group, []).append(tuple(int(p.split("/")[0]) - 1 for p in parts[1:4]))
    return verts, groups


def max_bend_degrees(verts, faces):
    """Largest angle between the normals of two faces sharing an edge."""
    def normal(f):
        a, b, c = (verts[i] for i in f)
        u, v = [b[k] - a[k] for k in range(3)], [c[k] - a[k] for k in range(3)]
        return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    owner, worst = {}, 0.0
    for f in faces:
        for q in range(3):
            i, j = f[q], f[(q + 1) % 3]
            g = owner.get((j, i))
            if g is None:
                owner[(i, j)] = f
                continue
            n1, n2 = normal(g), normal(f)
            cross = (n1[1] * n2[2] - n1[2] * n2[1], n1[2] * n2[0] - n1[0] * n2[2], n1[0] * n2[1] - n1[1] * n2[0])
            dot = sum(x * y for x, y in zip(n1, n2))
            worst = max(worst, math.degrees(math.atan2(math.sqrt(sum(x * x for x in cross)), dot)))
    return worst


class Export3dCreased(unittest.TestCase):
    """The message said "did not converge: treat the shape as approximate" for every such shape;
    an L glued to a circle keeps its flat lengths but creases the circle, and is now called
    creased, by the sharpest bend of the written mesh (recomputed here from the OBJ's groups)."""

    def test_an_l_on_a_circle_is_reported_creased_by_the_written_meshs_sharpest_bend(self):
        path = os.path.join(tempfile.mkdtemp(prefix="dformer-3d-"), "l.obj")
        err = io.StringIO()
        with redirect_stderr(err):
            Export3D().run([os.path.join(DATA, "l_circle_mm.svg"), "--id=A", "--id=B", f"--file={path}"], output=io.BytesIO())
        message = err.getvalue()
        verts, groups = read_obj_groups(path)
        self.assertEqual(len(groups), 2, f"wanted one OBJ group per piece, got {list(groups)}")
        bend = max(max_bend_degrees(verts, faces) for faces in groups.values())
        self.assertGreater(bend, 90.0, f"precondition: a creased form, sharpest bend {bend:.1f}°")
        found = re.search(r"creased by (\d+)°", message)
        self.assertIsNotNone(found, message)
        self.assertLessEqual(abs(int(found.group(1)) - bend), 1.0, f"wanted the mesh's {bend:.1f}°, got: {message}")
        self.assertNotIn("stretch", message)



class Export3dSampling(unittest.TestCase):
    """A rectangle with 1 mm corners on a circle was exported without a word at 64 seam
    vertices, its edges 5e-3 off their flat lengths: so few samples cannot follow both the
    corners and the circle. The message now says so and names a resolution to try; at the
    default (256) the same pair converges."""

    def export(self, *args):
        path = os.path.join(tempfile.mkdtemp(prefix="dformer-3d-"), "r.obj")
        err = io.StringIO()
        with redirect_stderr(err):
            Export3D().run([os.path.join(DATA, "rounded_rect_circle_mm.svg"), "--id=A", "--id=B", f"--file={path}", *args], output=io.BytesIO())
        return err.getvalue()

    def test_a_tight_corner_at_few_seam_vertices_asks_for_more(self):
        message = self.export("--resolution=64")
        strain = float(re.search(r"Max edge strain ([\d.]+)%", message).group(1)) / 100
        self.assertGreater(strain, 1e-3, f"precondition: edges over 1e-3 off: {message}")
        self.assertIn("too tightly somewhere for 64 seam vertices", message)
        self.assertIn("Raise Seam vertices (try 128)", message)
        self.assertNotIn("stretch", message)

    def test_at_the_default_resolution_the_same_pair_converges(self):
        message = self.export()
        strain = float(re.search(r"Max edge strain ([\d.]+)%", message).group(1)) / 100
        self.assertLessEqual(strain, 1e-3, message)
        self.assertNotIn("Approximate", message)
        self.assertNotIn("did not converge", message)
