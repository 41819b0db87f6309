"""How the extension reads the selected shapes: at full precision, and by SVG's own rules for
<rect>, <circle> and <ellipse> (inkex 1.2 writes path data with 6 significant digits, does not
clamp rect radii, and starts circles at the top turning the other way). Each test writes a
small hand-made document, runs the effects as Inkscape would, and checks the output with the
independent geometry of support.py or against the ``dformer`` batch command."""

import io
import json
import math
import os
import subprocess
import tempfile
import unittest
from contextlib import redirect_stderr

import support
from support import perimeter, rel

import inkex

from dformer_connect import Connect
from dformer_measure import Measure
from dformer_normalize import Normalize

HEAD = (
    '<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" '
    'xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd" {size}>'
    '<sodipodi:namedview id="nv" inkscape:document-units="{unit}"/>'
)
MM = {"size": 'width="210mm" height="297mm" viewBox="0 0 210 297"', "unit": "mm"}
# US Letter the way Inkscape makes it from an A4 document: user unit mm, display unit inch.
LETTER = {"size": 'width="8.5in" height="11in" viewBox="0 0 215.9 279.4"', "unit": "in"}


class Doc:
    """A document written to a temporary file; ``run`` returns (svg or None, stderr, bytes)."""

    def __init__(self, test, page, body):
        fd, self.path = tempfile.mkstemp(suffix=".svg", prefix="dformer-reading-")
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(HEAD.format(**page) + body + "</svg>")
        test.addCleanup(os.remove, self.path)

    def run(self, effect_class, *args):
        out, err = io.BytesIO(), io.StringIO()
        with redirect_stderr(err):
            try:
                effect_class().run([self.path, *args], output=out)
            except SystemExit as exit_:
                if exit_.code not in (0, None):
                    return None, err.getvalue(), out.getvalue()
        data = out.getvalue()
        svg = inkex.load_svg(io.BytesIO(data)).getroot() if data else None
        return svg, err.getvalue(), data

    def then(self, test, data):
        """A follow-up document holding an effect's output (the next effect runs on it)."""
        nxt = Doc.__new__(Doc)
        fd, nxt.path = tempfile.mkstemp(suffix=".svg", prefix="dformer-reading-")
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        test.addCleanup(os.remove, nxt.path)
        return nxt


class FullPrecision(unittest.TestCase):
    def test_normalize_then_connect_works_when_coordinates_have_many_digits(self):
        # Normalize writes shortest round-trip numbers; reading them back through inkex's
        # str(Path) rounded them to 6 digits, so Connect found the perimeters 2e-6 apart.
        doc = Doc(self, LETTER, '<rect id="A" x="20" y="20" width="101.6" height="50.8"/>'
                                '<circle id="B" cx="100" cy="180" r="40"/>')
        svg, err, data = doc.run(Normalize, "--id=A", "--id=B")
        self.assertEqual(err, "")
        self.assertLess(rel(perimeter(svg.getElementById("A")), perimeter(svg.getElementById("B"))), 1e-12)
        _, err, _ = doc.then(self, data).run(Measure, "--id=A", "--id=B")
        self.assertIn("#A: perimeter 12.0000 in", err)
        self.assertIn("#B: perimeter 12.0000 in", err)
        self.assertIn("equal (ready to connect)", err)
        svg, err, _ = doc.then(self, data).run(Connect, "--id=A", "--id=B", "--count=12")
        self.assertIsNotNone(svg, f"Connect refused the normalized pieces: {err}")
        for eid in "AB":
            self.assertEqual(len(svg.getElementById(f"dformer-cut-{eid}")), 12)

    def test_measure_is_not_rounded_to_six_digits(self):
        # 20mm = 75.59055... user units: rounded to 75.5906 the perimeter read 343.1820 mm.
        doc = Doc(self, MM, '<rect id="R" x="100" y="10" width="20mm" height="1in"/>')
        _, err, _ = doc.run(Measure, "--id=R")
        self.assertIn(f"perimeter {2 * (20 + 25.4) * 96 / 25.4:.4f} mm", err)


class SvgShapeRules(unittest.TestCase):
    def test_rect_radii_are_clamped_to_half_the_sides(self):
        # ry 35 > height/2: SVG draws ry = 20, a stadium 100 x 40 with round ends.
        doc = Doc(self, MM, '<rect id="R" x="10" y="10" width="100" height="40" rx="20" ry="35"/>'
                            '<rect id="S" x="10" y="100" width="60" height="40" rx="auto" ry="7"/>'
                            '<rect id="T" x="10" y="150" width="50" height="50"/>')
        _, err, _ = doc.run(Measure, "--id=R", "--id=S")
        self.assertIn(f"#R: perimeter {2 * 60 + 2 * math.pi * 20:.4f} mm", err)
        self.assertIn(f"#S: perimeter {2 * (46 + 26) + 2 * math.pi * 7:.4f} mm", err)
        svg, err, _ = doc.run(Normalize, "--id=T", "--id=R", "--target=first")
        self.assertEqual(err, "")
        self.assertLess(rel(perimeter(svg.getElementById("R")), 200.0), 1e-9)

    def test_circles_start_at_the_right_and_run_clockwise_like_svg_and_the_dformer_command(self):
        doc = Doc(self, MM, '<circle id="C" cx="100" cy="100" r="20"/><ellipse id="E" cx="100" cy="200" rx="30" ry="10"/>')
        _, err, _ = doc.run(Measure, "--id=C", "--id=E")
        batch = json.loads(subprocess.run([os.environ["DFORMER_BIN"], "measure", "--json", doc.path],
                                          capture_output=True, text=True, check=True).stdout)
        for line, row in zip(err.splitlines(), batch):
            self.assertIn("drawn clockwise", line)
            self.assertEqual(row["direction"], "clockwise")
        # Connector 1 sits at the first node, (cx + r, cy): its hole at the inset inwards.
        _, _, data = doc.run(Normalize, "--id=C", "--id=E", "--target=first")
        svg, err, _ = doc.then(self, data).run(Connect, "--id=C", "--id=E", "--count=8", "--inset=3", "--diameter=1")
        hole = svg.getElementById("dformer-hole-C-1").path.to_superpath()[0]
        xs, ys = [p[1][0] for p in hole], [p[1][1] for p in hole]
        centre = ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)
        self.assertAlmostEqual(centre[0], 117.0, places=6)
        self.assertAlmostEqual(centre[1], 100.0, places=6)

    def test_percentage_lengths_are_refused_by_name(self):
        doc = Doc(self, MM, '<rect id="P" x="10" y="10" width="50%" height="10"/><rect id="Q" x="10" y="50" width="5" height="5"/>')
        svg, err, data = doc.run(Normalize, "--id=P", "--id=Q")
        self.assertIsNone(svg)
        self.assertEqual(data, b"")
        self.assertIn('#P: attribute width="50%" is a percentage', err)
        # The extension's own advice in Inkscape's menus, from the one table.
        self.assertIn("convert it to a path (Path > Object to Path) first", err)


class ErrorsNameTheObject(unittest.TestCase):
    def test_core_errors_name_the_object_not_its_position(self):
        doc = Doc(self, MM, '<rect id="ok" x="10" y="10" width="40" height="40"/>'
                            '<path id="bow" d="M 100 100 L 150 150 L 150 100 L 100 150 Z"/>'
                            '<path id="hook" d="M 10 100 h 50 v 50 h -50"/>')
        # Measure asks the core one path at a time: it used to call every one "the first".
        _, err, _ = doc.run(Measure, "--id=ok", "--id=bow")
        self.assertIn("#bow crosses itself", err)
        self.assertNotIn("first", err)
        # A stray open stroke or a bad outline in the selection does not block the others.
        self.assertIn("#ok: perimeter 160.0000 mm", err)
        _, err, _ = doc.run(Measure, "--id=ok", "--id=hook")
        self.assertIn("#ok: perimeter 160.0000 mm", err)
        self.assertIn("Skipped: #hook is open", err)
        self.assertEqual(err.count("Join selected nodes"), 1, err)
        svg, err, data = doc.run(Normalize, "--id=ok", "--id=hook")
        self.assertIsNone(svg)
        self.assertEqual(data, b"")
        self.assertIn("#hook is open", err)
        # Inkscape's own commands, from the one table (the core's words were Illustrator's
        # "Object > Path > Join" in every host).
        self.assertIn("Join selected nodes", err)
        self.assertIn("Path > Combine", err)
        self.assertNotIn("Object > Path", err)


    def test_unequal_perimeters_are_given_in_the_users_unit(self):
        # Letter page: user unit mm, display unit inch; rounded to 4 significant digits.
        doc = Doc(self, LETTER, '<rect id="A" x="20" y="20" width="101.6" height="50.8"/>'
                                '<circle id="B" cx="100" cy="180" r="40"/>')
        _, err, _ = doc.run(Connect, "--id=A", "--id=B")
        self.assertIn(f"#A 12 in and #B {80 * math.pi / 25.4:.4g} in", err)
        self.assertNotIn("304.8", err)


class InPlace(unittest.TestCase):
    def test_normalize_keeps_title_description_and_lock(self):
        doc = Doc(self, MM, '<rect id="A" x="10" y="10" width="60" height="40"><title>Left side</title></rect>'
                            '<path id="B" d="M 100 100 h 30 v 30 h -30 z" sodipodi:insensitive="true" '
                            'sodipodi:nodetypes="cccc"><desc>right</desc></path>')
        svg, err, _ = doc.run(Normalize, "--id=A", "--id=B")
        self.assertEqual(err, "")
        a, b = svg.getElementById("A"), svg.getElementById("B")
        self.assertIsInstance(a, inkex.PathElement)
        self.assertEqual([c.text for c in a], ["Left side"])
        self.assertEqual([c.text for c in b], ["right"])
        self.assertEqual(b.get("sodipodi:insensitive"), "true")
        self.assertIsNone(b.get("sodipodi:nodetypes"), "node types describe the old outline")


if __name__ == "__main__":
    unittest.main()
