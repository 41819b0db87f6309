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



if __name__ == "__main__":
    unittest.main()
