"""What a user unit measures on paper: the page's scale when its proportions differ from the
viewBox's (``preserveAspectRatio`` meet, slice, none), and shapes inside nested ``<svg>``
viewports. The extension and the ``dformer`` command are checked against closed forms (a
rectangle's perimeter in mm) and against Inkscape 1.2's own ``--query-all``, which reports the
bounding boxes Inkscape draws, in px."""

import json
import os
import re
import shutil
import subprocess
import unittest

import support  # noqa: F401  (import paths, DFORMER_BIN)
from support import rel

from dformer_measure import Measure
from dformer_normalize import Normalize
from test_reading import Doc

MM = 96 / 25.4
INKSCAPE = shutil.which("inkscape")
NO_INKSCAPE = None if INKSCAPE else "inkscape is not installed"


def page(size):
    return {"size": size, "unit": "mm"}


#: 200 mm x 100 mm page over a 100 x 100 viewBox: Inkscape draws one user unit as 1 mm.
WIDE = page('width="200mm" height="100mm" viewBox="0 0 100 100"')
SLICE = page('width="200mm" height="100mm" viewBox="0 0 100 100" preserveAspectRatio="xMinYMin slice"')
NONE = page('width="200mm" height="100mm" viewBox="0 0 100 100" preserveAspectRatio="none"')
SQUARES = '<rect id="A" x="10" y="10" width="50" height="50"/><rect id="B" x="70" y="10" width="20" height="20"/>'


def dformer(*args):
    return subprocess.run([os.environ["DFORMER_BIN"], *args], capture_output=True, text=True, timeout=60, check=False)


def inkscape_boxes(path):
    """{id: (x, y, width, height)} in mm, as Inkscape 1.2 draws the file."""
    proc = subprocess.run([INKSCAPE, "--query-all", path], capture_output=True, text=True, timeout=120, check=True)
    boxes = {}
    for line in proc.stdout.splitlines():
        parts = line.split(",")
        if len(parts) == 5:
            boxes[parts[0]] = tuple(float(v) / MM for v in parts[1:])
    return boxes


class PageScale(unittest.TestCase):
    def test_measure_uses_the_smaller_scale_like_svg_meet(self):
        # Was 400 mm: inkex's _base_scale takes the larger of the two scales (2 mm per unit).
        doc = Doc(self, WIDE, SQUARES)
        _, err, _ = doc.run(Measure, "--id=A", "--unit=mm")
        self.assertIn(f"#A: perimeter {4 * 50:.4f} mm, area {50 * 50:.4f} mm²", err)
        rows = json.loads(dformer("measure", "--json", "--unit", "mm", "--id", "A", doc.path).stdout)
        self.assertAlmostEqual(rows[0]["perimeter"], 200.0, 9, rows)

    def test_slice_uses_the_larger_scale(self):
        doc = Doc(self, SLICE, SQUARES)
        _, err, _ = doc.run(Measure, "--id=A", "--unit=mm")
        self.assertIn(f"#A: perimeter {4 * 100:.4f} mm", err)
        rows = json.loads(dformer("measure", "--json", "--unit", "mm", "--id", "A", doc.path).stdout)
        self.assertAlmostEqual(rows[0]["perimeter"], 400.0, 9, rows)

    def test_length_options_use_the_same_scale(self):
        # Normalize to 100 mm: each square ends 25 mm a side, 25 user units on this page.
        doc = Doc(self, WIDE, SQUARES)
        svg, err, _ = doc.run(Normalize, "--id=A", "--id=B", "--target=length", "--length=100", "--unit=mm")
        self.assertEqual(err, "")
        for eid in "AB":
            self.assertAlmostEqual(svg.getElementById(eid).bounding_box().width, 25.0, 9)
        out = os.path.join(os.path.dirname(doc.path), os.path.basename(doc.path) + ".cli.svg")
        self.addCleanup(lambda: os.path.exists(out) and os.remove(out))
        proc = dformer("normalize", doc.path, "-o", out, "--id", "A", "--id", "B", "--target", "100mm")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("perimeter 100.000000 mm", proc.stderr)

    def test_a_page_stretched_unequally_is_refused(self):
        doc = Doc(self, NONE, SQUARES)
        for effect, args in ((Measure, ["--id=A"]), (Normalize, ["--id=A", "--id=B"])):
            svg, err, data = doc.run(effect, *args)
            self.assertIsNone(svg)
            self.assertEqual(data, b"")
            self.assertIn('preserveAspectRatio="none"', err)
            self.assertIn("perimeter has no single value", err)
        proc = dformer("measure", doc.path)
        self.assertEqual(proc.returncode, 1)
        self.assertIn('preserveAspectRatio="none"', proc.stderr)

#: A 1 mm-per-unit page. A (4 x 4) sits in a 5x viewport: drawn 20 x 20 mm, perimeter 80 mm.
#: S (8 x 8) in a viewport stretched 4x across and 2x down (none): 32 x 16 mm, 96 mm.
NESTED_PAGE = page('width="200mm" height="200mm" viewBox="0 0 200 200"')
NESTED = (
    '<rect id="B" x="10" y="10" width="30" height="30"/>'
    '<svg id="N" x="100" y="100" width="50" viewBox="0 0 10 10"><rect id="A" x="1" y="1" width="4" height="4"/></svg>'
    '<svg id="M" x="0" y="150" width="40" height="20" viewBox="0 0 10 10" preserveAspectRatio="none">'
    '<g transform="translate(1 1)"><rect id="S" width="8" height="8"/></g></svg>'
)
PERIMETERS = {"A": 80.0, "S": 96.0, "B": 120.0}


def measured(err):
    return {k: float(v) for k, v in re.findall(r"#(\w+): perimeter ([\d.]+) mm", err)}


class NestedViewports(unittest.TestCase):
    def test_shapes_in_nested_svg_are_measured_through_its_viewport(self):
        # Was 16 mm for A (its own coordinates) in the extension; the CLI skipped it.
        doc = Doc(self, NESTED_PAGE, NESTED)
        _, err, _ = doc.run(Measure, "--id=A", "--id=S", "--id=B")
        self.assertEqual(measured(err), PERIMETERS, err)
        proc = dformer("measure", "--json", doc.path)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        rows = {r["id"]: r["perimeter"] for r in json.loads(proc.stdout)}
        for eid, want in PERIMETERS.items():
            self.assertAlmostEqual(rows[eid], want, 9, rows)

    def test_selecting_the_nested_svg_opens_it_like_a_group(self):
        doc = Doc(self, NESTED_PAGE, NESTED)
        _, err, _ = doc.run(Measure, "--id=N")
        self.assertEqual(measured(err), {"A": 80.0}, err)

    def test_normalize_writes_back_through_the_viewport(self):
        doc = Doc(self, NESTED_PAGE, NESTED)
        svg, err, data = doc.run(Normalize, "--id=B", "--id=A", "--target=first")
        self.assertEqual(err, "")
        # Written in the nested square's own coordinates: 6 units there, 30 mm on the page.
        self.assertAlmostEqual(svg.getElementById("A").path.bounding_box().width, 6.0, 9)
        _, err, _ = doc.then(self, data).run(Measure, "--id=A", "--id=B")
        self.assertEqual(measured(err), {"A": 120.0, "B": 120.0}, err)
        out = doc.path + ".cli.svg"
        self.addCleanup(lambda: os.path.exists(out) and os.remove(out))
        proc = dformer("normalize", doc.path, "-o", out, "--id", "B", "--id", "A", "--target", "first")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("perimeter 120.000000 mm", proc.stderr)
        rows = json.loads(dformer("measure", "--json", "--id", "A", out).stdout)
        self.assertAlmostEqual(rows[0]["perimeter"], 120.0, 9)

    def test_a_nested_svg_of_zero_size_is_refused_naming_the_shape(self):
        doc = Doc(self, NESTED_PAGE, '<rect id="B" width="5" height="5"/><svg id="Z" width="0" height="10">'
                                     '<rect id="A" width="5" height="5"/></svg>')
        svg, err, _ = doc.run(Measure, "--id=A", "--id=B")
        self.assertIsNone(svg)
        self.assertIn("#A is inside the nested <svg> #Z, which has zero or negative width", err)
        proc = dformer("measure", "--id", "A", doc.path)
        self.assertEqual(proc.returncode, 1)
        self.assertIn("#A is inside the nested <svg> #Z, which has zero or negative width", proc.stderr)


@unittest.skipIf(NO_INKSCAPE and not os.environ.get("DFORMER_REQUIRE_INKSCAPE"), NO_INKSCAPE or "")
class AgreesWithInkscape(unittest.TestCase):
    """Inkscape's own bounding boxes: the square's perimeter is four times its drawn width."""

    def check(self, size, ids):
        doc = Doc(self, size, SQUARES)
        boxes = inkscape_boxes(doc.path)
        _, err, _ = doc.run(Measure, *[f"--id={i}" for i in ids], "--unit=mm")
        rows = json.loads(dformer("measure", "--json", "--unit", "mm", *sum((["--id", i] for i in ids), []), doc.path).stdout)
        shown = dict(re.findall(r"#(\w+): perimeter ([\d.]+) mm", err))
        for eid, row in zip(ids, rows):
            side = boxes[eid][2]  # Inkscape prints 6 significant digits
            self.assertLess(rel(float(shown[eid]), 4 * side), 1e-5, f"#{eid}: Inkscape draws it {side} mm wide; {err}")
            self.assertLess(rel(row["perimeter"], 4 * side), 1e-5, f"#{eid}: Inkscape draws it {side} mm wide")

    def test_meet_and_slice_pages(self):
        self.check(WIDE, ["A", "B"])
        self.check(SLICE, ["A", "B"])

    def test_nested_viewports(self):
        doc = Doc(self, NESTED_PAGE, NESTED)
        boxes = inkscape_boxes(doc.path)
        for eid, want in PERIMETERS.items():
            self.assertLess(rel(2 * (boxes[eid][2] + boxes[eid][3]), want), 1e-5, f"#{eid}: Inkscape draws {boxes[eid]}")
        # After Normalize (extension and CLI), Inkscape draws the nested square 30 mm wide.
        _, _, data = doc.run(Normalize, "--id=B", "--id=A", "--target=first")
        out = doc.then(self, data).path + ".cli.svg"
        self.addCleanup(lambda: os.path.exists(out) and os.remove(out))
        self.assertEqual(dformer("normalize", doc.path, "-o", out, "--id", "B", "--id", "A", "--target", "first").returncode, 0)
        for path in (doc.then(self, data).path, out):
            box = inkscape_boxes(path)["A"]
            self.assertLess(rel(box[2], 30.0), 1e-5, f"{path}: Inkscape draws A {box}")


if __name__ == "__main__":
    unittest.main()
