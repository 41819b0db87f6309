"""What a user unit measures on paper: the page's scale when its proportions differ from the
viewBox's (``preserveAspectRatio`` meet, slice, none). The extension and the ``dformer``
command are checked against closed forms (a square's perimeter in mm) and against Inkscape
1.2's own ``--query-all``, which reports the bounding boxes Inkscape draws, in px."""

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


if __name__ == "__main__":
    unittest.main()
