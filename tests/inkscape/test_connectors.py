"""Issue 15 in the Inkscape extension (through inkex, as Inkscape runs it): locking leaves put
their slots on the cut layer, a seam allowance replaces the outline by the cut line and scores
the seam line, the dialogs' defaults are the core's `defaults()`, Normalize takes one path to
an exact length and keeps the first node with pivot "start", and each new bad input is refused
with its message and no document written. Geometry is measured with support's independent
toolkit (Gauss-Legendre arc length, point-in-polygon)."""

import math
import os
import tempfile
import unittest
import xml.etree.ElementTree as ET

import support
from support import inside, perimeter, rel, segments

from dformer_bridge import call
from dformer_connect import Connect
from dformer_normalize import Normalize
from test_properties import DATA, run, source

EXT = support.EXTENSION


def temp_svg(body):
    """A mm document with the given shapes, written where `run` can find it."""
    handle, path = tempfile.mkstemp(suffix=".svg", dir=DATA)
    with os.fdopen(handle, "w", encoding="utf-8") as fh:
        fh.write('<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 200 100">' + body + "</svg>")
    return os.path.basename(path)


class Connectors(unittest.TestCase):
    def test_locking_leaves_put_their_slots_on_the_cut_layer_inside_the_piece(self):
        svg, err, _ = run(Connect, "connect_mm.svg", "--id=A", "--id=B", "--kind=leaves", "--leaf=lock", "--count=8")
        self.assertIsNotNone(svg, err)
        for eid in "AB":
            group = svg.getElementById(f"dformer-cut-{eid}")
            slots = [e for e in group if e.get("id").startswith(f"dformer-slot-{eid}-")]
            self.assertEqual(len(slots), 4, f"#{eid}: 8 leaves alternate, so 4 slots, got {len(slots)}")
            piece = segments(svg.getElementById(eid))
            for s in slots:
                box = s.bounding_box()
                self.assertTrue(inside(piece, (box.center.x, box.center.y)), f"slot {s.get('id')} is not inside #{eid}")

    def test_allowance_moves_the_cut_line_out_and_scores_the_seam_line(self):
        a = 2.0
        svg, err, _ = run(Connect, "connect_mm.svg", "--id=A", "--id=B", "--count=12", f"--allowance={a}", "--unit=mm")
        self.assertIsNotNone(svg, err)
        # A is a 40 × 20 rectangle: its cut line with sharp (mitred) corners measures 120 + 8a.
        got = perimeter(svg.getElementById("A"))
        self.assertLess(rel(got, 120 + 8 * a), 1e-6, f"cut line of #A: wanted {120 + 8 * a}, got {got}")
        seam = svg.getElementById("dformer-seam-A-1")
        self.assertIsNotNone(seam, "no seam line")
        self.assertEqual(seam.getparent().get("id"), "dformer-score-A", "the seam line belongs on the score layer")
        self.assertLess(rel(perimeter(seam), 120.0), 1e-6, "the seam line is the piece as drawn")

    def test_new_bad_inputs_are_refused_with_their_message_and_no_document(self):
        u = temp_svg(
            '<path id="U" d="M 0,0 H 20 V 20 H 11 V 5 H 9 V 20 H 0 Z"/>'
            '<rect id="S" x="50" y="0" width="27.5" height="27.5"/>'
        )
        try:
            for fixture, args, wanted in [
                ("connect_mm.svg", ["--id=A", "--id=B", "--kind=leaves", "--count=7"], "must be even, got 7: use 6 or 8"),
                ("connect_mm.svg", ["--id=A", "--id=B", "--kind=teeth", "--count=12", "--length=8", "--angle=150"], "dovetails' corners collide"),
                (u, ["--id=U", "--id=S", "--count=20", "--allowance=1.5", "--unit=mm"], "cross itself"),
                ("connect_mm.svg", ["--id=A", "--id=B", "--kind=teeth", "--count=12", "--allowance=1"], "teeth interlock on the seam line"),
            ]:
                svg, err, out = run(Connect, fixture, *args)
                self.assertIsNone(svg, f"{args}: wanted a refusal, got a document")
                self.assertEqual(out, b"", f"{args}: a refused effect must write no document")
                self.assertIn(wanted, err, f"{args}: wanted {wanted!r} in {err!r}")
        finally:
            os.remove(os.path.join(DATA, u))

    def test_the_dialogs_defaults_are_the_cores(self):
        core = {d["name"]: d for d in call("defaults")["options"]}
        ns = {"i": "http://www.inkscape.org/namespace/inkscape/extension"}
        root = ET.parse(os.path.join(EXT, "dformer_connect.inx")).getroot()
        params = {p.get("name"): p for p in root.iter("{http://www.inkscape.org/namespace/inkscape/extension}param")}
        self.assertEqual(int(params["count"].text), core["count"]["value"])
        self.assertEqual(float(params["angle"].text), core["angle"]["value"])
        self.assertEqual(float(params["allowance"].text), core["allowance"]["value"])
        self.assertEqual(float(params["kerf"].text), core["kerf"]["value"])
        self.assertEqual(params["leaf"].find("i:option", ns).get("value"), core["leaf"]["value"])
        self.assertEqual(params["kind"].find("i:option", ns).get("value"), core["kind"]["value"])
        # Sizes are "0: automatic", i.e. the core's fractions of the pitch.
        for name in ("diameter", "inset", "length"):
            self.assertEqual(float(params[name].text), 0.0, f"{name} must default to the core's")


class DisplayUnit(unittest.TestCase):
    """connect_in.svg: one user unit is 0.02 in (viewBox 425 x 550 over 8.5 x 11 in) and the
    display unit is the inch. Before, lengths in messages were user units ("Teeth of length 40
    … a pitch of 50" for 0.8 in teeth at a 1 in pitch)."""

    PITCH_IN = 12 / 12  # A: 200 x 100 user units = 12 in, 12 connectors
    UU_PER_IN = 425 / 8.5

    def test_messages_give_lengths_in_the_display_unit_rounded(self):
        for args, wanted in [
            (["--kind=teeth", "--length=0.8", "--angle=150"],
             f"Teeth of length 0.8 in with 150° flanks do not fit a pitch of {self.PITCH_IN:g} in: the dovetails' corners collide"),
            (["--kind=teeth", "--length=0.8", "--angle=10"], f"Teeth of length 0.8 in with 10° flanks do not fit a pitch of {self.PITCH_IN:g} in: the flanks meet"),
            (["--diameter=1.2"], f"Holes of diameter 1.2 in do not fit between connectors {self.PITCH_IN:g} in apart"),
        ]:
            svg, err, out = run(Connect, "connect_in.svg", "--id=A", "--id=B", "--count=12", *args)
            self.assertIsNone(svg, f"{args}: wanted a refusal")
            self.assertEqual(out, b"", f"{args}: a refused effect must write no document")
            self.assertIn(wanted, err, f"{args}: wanted {wanted!r} in {err!r}")
        # 0.03 in across a slot 2 user units (0.04 in) wide: the allowances of its two sides meet.
        svg, err, _ = run(Connect, "connect_in.svg", "--id=U", "--id=S", "--count=20", "--allowance=0.03")
        self.assertIsNone(svg)
        self.assertIn("A seam allowance of 0.03 in makes the cut line of the first piece cross itself", err)

    def test_lengths_typed_are_in_the_display_unit(self):
        svg, err, _ = run(Connect, "connect_in.svg", "--id=A", "--id=B", "--count=12", "--diameter=0.1", "--inset=0.25")
        self.assertIsNotNone(svg, err)
        for eid in "AB":
            boxes = [h.bounding_box() for h in svg.getElementById(f"dformer-cut-{eid}")]
            self.assertEqual(len(boxes), 12)
            for box in boxes:
                self.assertLess(rel(box.width, 0.1 * self.UU_PER_IN), 1e-6, f"#{eid}: a 0.1 in hole is 5 user units wide, got {box.width}")
        # The numbers come back at the core's sizes, in user units: a quarter of the pitch at most.
        for label in svg.getElementById("dformer-engrave-B"):
            size = float(label.style["font-size"])
            self.assertLessEqual(size, 0.25 * self.PITCH_IN * self.UU_PER_IN * (1 + 1e-9))
            self.assertGreater(size, 0.4 * 0.1 * self.UU_PER_IN * 0.999, "no smaller than 40 % of a hole diameter")


class NormalizeOne(unittest.TestCase):
    def test_one_path_is_scaled_to_the_exact_length_about_its_first_node(self):
        before = segments(source("connect_mm.svg").getElementById("B"))[0][0]
        svg, err, _ = run(Normalize, "connect_mm.svg", "--id=B", "--target=length", "--length=150", "--pivot=start", "--unit=mm")
        self.assertIsNotNone(svg, err)
        b = svg.getElementById("B")
        self.assertLess(rel(perimeter(b), 150.0), 1e-9)
        first = segments(b)[0][0]
        self.assertLess(math.dist(first, before), 1e-9, f"the first node moved from {before} to {first}")

    def test_one_path_without_a_length_is_explained(self):
        svg, err, out = run(Normalize, "connect_mm.svg", "--id=B")
        self.assertIsNone(svg)
        self.assertEqual(out, b"")
        self.assertIn("Only one outline is selected: choose Exact length", err)


if __name__ == "__main__":
    unittest.main()
