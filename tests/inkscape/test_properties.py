"""What users rely on, checked on the extension's output with the independent geometry of
support.py (inkex parses the written SVG; arc lengths by Gauss-Legendre quadrature here):

- Normalize: every selected piece ends with the same perimeter, equal to the chosen target
  (closed forms for the fixtures: rect 2(w+h), circle 2 pi r, triangle sides), in place.
- Connectors: same count and numbers on both pieces; hole k on A at arc length
  sA + (k + slide) pitch walking A counter-clockwise (y up) and on B walking clockwise, its
  centre at `inset` from that point (beside a corner sharper than square: on the inset line,
  `inset` from the edge) and inside the piece, its diameter as asked.
- Errors (unequal perimeters, wrong selection, compound path) abort with the core's message
  and write no document, so Inkscape keeps the document unchanged.
"""

import io
import math
import os
import re
import unittest
from contextlib import redirect_stderr

import support
from support import distance, inside, perimeter, point_at, rel, reverse, segments, signed_area_y_up

import inkex

from dformer_bridge import call
from dformer_connect import Connect
from dformer_measure import Measure
from dformer_normalize import Normalize

DATA = os.path.join(support.HERE, "data", "svg")


def run(effect_class, fixture, *args):
    """Runs an effect as Inkscape would; returns (output document or None, stderr text)."""
    out, err = io.BytesIO(), io.StringIO()
    with redirect_stderr(err):
        try:
            effect_class().run([os.path.join(DATA, fixture), *args], output=out)
        except SystemExit as exit_:
            if exit_.code not in (0, None):
                return None, err.getvalue(), out.getvalue()
    if not out.getvalue():  # inkex writes nothing when the document did not change
        return None, err.getvalue(), b""
    return inkex.load_svg(io.BytesIO(out.getvalue())).getroot(), err.getvalue(), out.getvalue()


def source(fixture):
    return inkex.load_svg(os.path.join(DATA, fixture)).getroot()


class NormalizeProperties(unittest.TestCase):
    def assert_all(self, svg, ids, wanted, tol):
        for eid in ids:
            got = perimeter(svg.getElementById(eid))
            self.assertLess(rel(got, wanted), tol, f"#{eid}: wanted perimeter {wanted!r}, got {got!r}")

    def test_largest_target_gives_every_piece_the_largest_perimeter_in_mm_document(self):
        svg, err, _ = run(Normalize, "pieces_mm.svg", "--id=A", "--id=B", "--id=C")
        self.assertEqual(err, "", "no message expected")
        # A: rect 40 x 20 scaled 1.5 -> 180 mm; B: circle r 25 -> 157.08; C: 120.
        self.assert_all(svg, "ABC", 180.0, 1e-10)

    def test_exact_length_in_another_unit_is_converted_through_the_viewbox(self):
        svg, _, _ = run(Normalize, "pieces_mm.svg", "--id=A", "--id=C", "--target=length", "--length=10", "--unit=in")
        self.assert_all(svg, "AC", 254.0, 1e-10)  # 10 in = 254 mm = 254 user units here

    def test_first_target_follows_the_selection_order(self):
        svg, _, _ = run(Normalize, "pieces_mm.svg", "--id=C", "--id=A", "--target=first")
        self.assert_all(svg, "AC", 120.0, 1e-10)

    def test_px_document_smallest_target_matches_the_ellipse_closed_form(self):
        svg, _, _ = run(Normalize, "pieces_px.svg", "--id=D", "--id=E", "--target=smallest")
        # Ellipse a = 60, b = 30: closed form by the Gauss-Kummer series (ellipse_perimeter).
        a, b = 60.0, 30.0
        wanted = ellipse_perimeter(a, b)
        before = perimeter(source("pieces_px.svg").getElementById("E"))
        self.assertGreater(before, wanted, "the blob must be the larger piece for this test to mean anything")
        # The core turns the ellipse's arcs into cubics to 1e-6 of the radius: allow 1e-6.
        self.assert_all(svg, "DE", wanted, 1e-6)
        got_d, got_e = perimeter(svg.getElementById("D")), perimeter(svg.getElementById("E"))
        self.assertLess(rel(got_d, got_e), 1e-10, f"wanted equal perimeters, got {got_d!r} and {got_e!r}")

    def test_shapes_keep_their_id_style_and_transform_and_become_paths(self):
        before = source("pieces_mm.svg")
        svg, _, _ = run(Normalize, "pieces_mm.svg", "--id=A", "--id=C")
        for eid in "AC":
            old, new = before.getElementById(eid), svg.getElementById(eid)
            self.assertIsInstance(new, inkex.PathElement, f"#{eid} should now be a path")
            self.assertEqual(str(new.style), str(old.style), f"#{eid} style changed")
            self.assertEqual(new.getparent().get("id"), old.getparent().get("id"), f"#{eid} moved")


def ellipse_perimeter(a, b):
    """Perimeter of an ellipse: pi (a + b) sum_n (binom(1/2, n))^2 h^n, h = ((a-b)/(a+b))^2
    (Gauss-Kummer series; terms shrink like h^n, h = 1/9 here)."""
    h = ((a - b) / (a + b)) ** 2
    total, term, n = 0.0, 1.0, 0
    coeff = 1.0
    while True:
        total += coeff * coeff * h**n
        n += 1
        coeff *= (0.5 - (n - 1)) / n
        if coeff * coeff * h**n < 1e-18:
            return math.pi * (a + b) * total


class ConnectProperties(unittest.TestCase):
    def holes(self, svg, eid):
        group = svg.getElementById(f"dformer-cut-{eid}")
        self.assertIsNotNone(group, f"no hole group for #{eid}")
        return [h.bounding_box() for h in group]

    def labels(self, svg, eid):
        group = svg.getElementById(f"dformer-engrave-{eid}")
        return [t.text for t in group]

    @staticmethod
    def flagged(err, piece):
        """Connector numbers a warning names as crossing the edge or outside ``piece``
        ("first piece" / "second piece")."""
        found = set()
        for line in err.splitlines():
            if f"the {piece}," in line and ("cross the edge" in line or "lie outside" in line):
                found.update(int(n) for n in re.findall(r"\d+", line.split("connectors", 1)[1].split(" cross")[0].split(" lie")[0]))
        return found

    def check_stitch(self, fixture, args, count, inset, diameter, slide, start=(0.0, 0.0)):
        svg, err, _ = run(Connect, fixture, "--id=A", "--id=B", "--kind=stitch", *args)
        self.assertIsNotNone(svg, f"connect failed: {err}")
        total = perimeter(svg.getElementById("A"))
        pitch = total / count
        for i, eid in enumerate("AB"):
            segs = segments(svg.getElementById(eid))
            ccw = signed_area_y_up(segs) > 0
            # A is walked counter-clockwise (y up), B clockwise: the pieces face each other.
            walk = segs if ccw == (eid == "A") else reverse(segs)
            boxes = self.holes(svg, eid)
            warned = self.flagged(err, ("first piece", "second piece")[i])
            self.assertEqual(len(boxes), count, f"#{eid}: wanted {count} holes, got {len(boxes)}")
            self.assertEqual(self.labels(svg, eid), [str(k + 1) for k in range(count)], f"#{eid}: labels not 1..{count}")
            for k, box in enumerate(boxes):
                centre = (box.center.x, box.center.y)
                station = point_at(walk, start[i] + (k + slide) * pitch)
                dist = math.dist(centre, station)
                # Beside a corner sharper than square the hole keeps to the inset line instead
                # (`inset` from the nearer edge, moved along it away from the corner).
                edge = distance(segs, centre)
                self.assertTrue(
                    abs(dist - inset) < 1e-6 * pitch or abs(edge - inset) < 1e-6 * pitch or k + 1 in warned,
                    f"#{eid} hole {k + 1}: wanted inset {inset} from its connector point or on the inset line, "
                    f"got {dist} from the point and {edge} from the edge",
                )
                # Inside the piece, or named in a warning: the user is never left unaware.
                self.assertTrue(
                    inside(segs, centre) or k + 1 in warned,
                    f"#{eid} hole {k + 1} at {centre} is outside the piece and no warning names it (warned: {sorted(warned)})",
                )
                self.assertLess(abs(box.width - diameter), 1e-6 * diameter, f"#{eid} hole {k + 1}: wanted diameter {diameter}, got {box.width}")
        return svg, err

    def test_stitch_holes_are_paired_evenly_spaced_at_the_inset_in_mm(self):
        # 120 mm / 12 = 10 mm pitch; defaults: diameter p/4 = 2.5, inset p/2 = 5.
        self.check_stitch("connect_mm.svg", ["--count=12", "--slide=0.25"], 12, 5.0, 2.5, 0.25)

    def test_explicit_sizes_in_another_unit_are_converted(self):
        # 0.2 cm = 2 mm; 0.35 cm = 3.5 mm; pitch 15 mm -> 8 connectors.
        args = ["--spacing=pitch", "--pitch=1.5", "--diameter=0.2", "--inset=0.35", "--slide=0.5", "--unit=cm"]
        self.check_stitch("connect_mm.svg", args, 8, 3.5, 2.0, 0.5)

    def test_pitch_0_spaces_by_the_perimeter_over_the_cores_default_count(self):
        # Before, the dialog's pitch default was a fixed 10 display units (10 in in an inch
        # document). 0 now means the pitch the core's default count gives: 120 mm / count.
        count = int(next(d["value"] for d in call("defaults")["options"] if d["name"] == "count"))
        pitch = 120.0 / count
        self.check_stitch("connect_mm.svg", ["--spacing=pitch", "--pitch=0", "--slide=0.5"], count, pitch / 2, pitch / 4, 0.5)

    def test_start_offsets_move_connector_one_on_each_piece(self):
        args = ["--count=6", "--slide=0", "--start_a=7", "--start_b=13", "--inset=4", "--diameter=2"]
        self.check_stitch("connect_mm.svg", args, 6, 4.0, 2.0, 0.0, start=(7.0, 13.0))

    def test_px_document_with_warnings_still_writes_and_reports_them(self):
        # Holes 30 px deep in a triangle whose inscribed circle has a radius of 40 px: near its
        # 37° corner the piece is narrower than the inset (3 mm holes 8 deep fit since holes
        # keep to the inset line beside sharp corners).
        svg, err = self.check_stitch("connect_px.svg", ["--count=12", "--diameter=12", "--inset=30", "--slide=0.25"], 12, 30.0, 12.0, 0.25)
        self.assertIn("D-former warnings", err, "the core's warnings must reach the user")
        # check_stitch has matched the holes it names against the ones it measures off the piece.
        self.assertTrue("cross the edge" in err or "lie outside" in err, err)

    def test_layers_follow_the_laser_colour_convention(self):
        svg, _, _ = run(Connect, "connect_mm.svg", "--id=A", "--id=B", "--count=12", "--slide=0.25")
        for lid, colour, label in [("dformer-cut", "#ff0000", "D-former cut"), ("dformer-score", "#0000ff", "D-former score")]:
            layer = svg.getElementById(lid)
            self.assertEqual(layer.get("inkscape:groupmode"), "layer", f"{lid} must be an Inkscape layer")
            self.assertEqual(layer.label, label)
            for elem in layer.descendants().filter(inkex.PathElement):
                self.assertEqual(elem.style.get("stroke"), colour, f"{elem.get_id()} in {lid}")
                width = float(elem.style.get("stroke-width"))
                self.assertAlmostEqual(width, 0.0254, 9, f"hairline: wanted 0.0254 mm, got {width}")
        for text in svg.getElementById("dformer-engrave").descendants().filter(inkex.TextElement):
            self.assertEqual(text.style.get("fill"), "#000000")

    def test_running_again_replaces_the_pieces_groups(self):
        once, _, data = run(Connect, "connect_mm.svg", "--id=A", "--id=B", "--count=12", "--slide=0.25")
        path = os.path.join(support.HERE, "data", "_twice.svg")
        try:
            with open(path, "wb") as fh:
                fh.write(data)
            out, err = io.BytesIO(), io.StringIO()
            with redirect_stderr(err):
                Connect().run([path, "--id=A", "--id=B", "--count=6", "--slide=0.25"], output=out)
            twice = inkex.load_svg(io.BytesIO(out.getvalue())).getroot()
        finally:
            os.remove(path)
        self.assertEqual(len(self.holes(twice, "A")), 6, "the second run must replace, not add to, the holes")
        self.assertEqual(len(twice.xpath("//svg:g[@id='dformer-cut']")), 1, "one cut layer")

    def test_teeth_change_both_outlines_and_keep_them_closed(self):
        svg, err, _ = run(Connect, "connect_mm.svg", "--id=A", "--id=B", "--kind=teeth", "--count=16", "--slide=0.5", "--length=2")
        self.assertEqual(err, "", "these teeth fit: no warning expected")
        for eid in "AB":
            elem = svg.getElementById(eid)
            self.assertIsInstance(elem, inkex.PathElement)
            self.assertTrue(str(elem.path).strip().upper().endswith("Z"), f"#{eid} outline must stay closed")
            self.assertGreater(len(elem.path), 4 * 16, f"#{eid} should carry the teeth")


class Errors(unittest.TestCase):
    def assert_refused(self, effect, fixture, args, *wanted):
        svg, err, out = run(effect, fixture, *args)
        self.assertIsNone(svg, f"wanted an abort, got a document (stderr {err!r})")
        self.assertEqual(out, b"", "an aborted effect must write no document")
        for text in wanted:
            self.assertIn(text, err, f"wanted {text!r} in the message, got {err!r}")

    def test_unequal_perimeters_name_both_and_say_normalize(self):
        self.assert_refused(Connect, "pieces_mm.svg", ["--id=A", "--id=C"], "180", "120", "Normalize")

    def test_wrong_selection_counts_are_explained(self):
        self.assert_refused(Connect, "pieces_mm.svg", ["--id=A"], "exactly 2", "1 selected")
        self.assert_refused(Normalize, "pieces_mm.svg", [], "at least 1", "0 selected")

    def test_core_option_errors_come_through(self):
        self.assert_refused(Connect, "connect_mm.svg", ["--id=A", "--id=B", "--kind=rivets"], "kind", "rivets")
        self.assert_refused(Connect, "connect_mm.svg", ["--id=A", "--id=B", "--count=20000"], "count")

    def test_compound_paths_are_refused_by_name(self):
        svg = source("connect_mm.svg")
        path = os.path.join(support.HERE, "data", "_compound.svg")
        svg.getElementById("B").set("d", "M 0 0 H 10 V 10 Z M 20 20 H 30 V 30 Z")
        try:
            with open(path, "wb") as fh:
                fh.write(svg.tostring())
            err = io.StringIO()
            with redirect_stderr(err), self.assertRaises(SystemExit):
                Connect().run([path, "--id=A", "--id=B"], output=io.BytesIO())
        finally:
            os.remove(path)
        self.assertIn("#B has 2 subpaths", err.getvalue())

    def test_a_missing_core_binary_is_an_install_hint(self):
        saved = os.environ["DFORMER_BIN"]
        os.environ["DFORMER_BIN"] = "/nonexistent/dformer"
        try:
            self.assert_refused(Measure, "connect_mm.svg", ["--id=A"], "DFORMER_BIN", "/nonexistent/dformer")
        finally:
            os.environ["DFORMER_BIN"] = saved


class Measurements(unittest.TestCase):
    def test_reported_perimeters_match_closed_forms_in_the_chosen_unit(self):
        _, err, _ = run(Measure, "pieces_mm.svg", "--id=A", "--id=B", "--id=C", "--unit=cm")
        self.assertIn("#A: perimeter 18.0000 cm", err)
        self.assertIn(f"#B: perimeter {5 * math.pi:.4f} cm", err)
        self.assertIn("#C: perimeter 12.0000 cm", err)
        self.assertIn("drawn clockwise", err.splitlines()[0], "A (a rect) runs clockwise on screen")
        self.assertIn("counter-clockwise", err.splitlines()[1], "B is drawn counter-clockwise")

    def test_one_selected_outline_is_measured_alone(self):
        # Issue 15 req. 4: Measure on a single selection. B is a circle of radius 2.5 cm.
        _, err, _ = run(Measure, "pieces_mm.svg", "--id=B", "--unit=cm")
        self.assertIn(f"#B: perimeter {5 * math.pi:.4f} cm", err)
        self.assertNotIn("differ", err, "no comparison with a single outline")


if __name__ == "__main__":
    unittest.main()


class InxFiles(unittest.TestCase):
    """Every .inx matches its script (inkex's own InxMixin: each parameter is an argument of the
    right type, each option of the right choices) and sits in the D-former submenu."""

    def test_each_inx_matches_its_script(self):
        from inkex.tester import TestCase as InkexCase
        from inkex.tester.inx import InxMixin

        class Check(InxMixin, InkexCase):
            def runTest(self):
                pass

        checker = Check()
        self.addCleanup(os.chdir, os.getcwd())
        os.chdir(support.EXTENSION)  # inkex resolves the .inx's script relative to the cwd
        for name in ("dformer_measure.inx", "dformer_normalize.inx", "dformer_connect.inx", "dformer_export3d.inx"):
            with self.subTest(inx=name):
                path = os.path.join(support.EXTENSION, name)
                checker.assertInxIsGood(path)
                with open(path, encoding="utf-8") as fh:
                    self.assertIn('<submenu name="D-former"/>', fh.read())
