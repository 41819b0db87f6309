"""The `dformer` command on its own: the JSON bridge's contract (answers, errors, exit status)
and batch use on SVG files. The batch commands read SVG with their own code (roxmltree and
svgtypes in Rust), the extension with inkex: on the same fixtures both must give the same
pieces and connectors, which checks each reader against an independent one."""

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

DATA = os.path.join(support.HERE, "data", "svg")
BIN = os.environ["DFORMER_BIN"]


def dformer(*args, stdin=None):
    return subprocess.run([BIN, *args], input=stdin, capture_output=True, text=True, timeout=60, check=False)


class JsonBridge(unittest.TestCase):
    def test_a_batch_answers_in_order_and_an_error_sets_the_exit_status(self):
        square = {"closed": True, "points": [{"anchor": [0, 0]}, {"anchor": [3, 0]}, {"anchor": [3, 3]}, {"anchor": [0, 3]}]}
        requests = [{"op": "measure", "path": square}, {"op": "pathToSvg", "path": square}, {"op": "measure", "path": {"closed": True, "points": []}}]
        proc = dformer("json", stdin=json.dumps(requests))
        self.assertEqual(proc.returncode, 1, "one failed request: exit status 1")
        answers = json.loads(proc.stdout)
        self.assertEqual(answers[0]["perimeter"], 12.0)
        self.assertTrue(answers[1].startswith("M"), f"wanted path data, got {answers[1]!r}")
        self.assertIn("0 points", answers[2]["error"])

    def test_a_single_error_is_an_error_object_with_exit_status_1(self):
        proc = dformer("json", stdin='{"op": "connect", "pieces": [], "options": {}}')
        self.assertEqual(proc.returncode, 1)
        self.assertEqual(json.loads(proc.stdout), {"error": "Expected exactly two pieces to connect, got 0."})
        proc = dformer("json", stdin="{")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("not valid JSON", json.loads(proc.stdout)["error"])


class Batch(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="dformer-cli-")

    def out(self, name):
        return os.path.join(self.tmp, name)

    def test_measure_reports_in_the_document_unit_or_the_one_asked(self):
        rows = json.loads(dformer("measure", "--json", os.path.join(DATA, "connect_px.svg")).stdout)
        self.assertEqual([(r["id"], round(r["perimeter"], 9), r["unit"]) for r in rows], [("A", 480.0, "px"), ("B", 480.0, "px")])
        rows = json.loads(dformer("measure", "--json", "--unit", "mm", "--id", "B", os.path.join(DATA, "connect_px.svg")).stdout)
        self.assertAlmostEqual(rows[0]["perimeter"], 480 * 25.4 / 96, 9, f"wanted 127 mm, got {rows}")

    def test_normalize_agrees_with_the_extension_and_keeps_the_rest_of_the_file(self):
        src = os.path.join(DATA, "pieces_mm.svg")
        proc = dformer("normalize", src, "-o", self.out("n.svg"), "--id", "A", "--id", "B", "--id", "C", "--pivot", "centroid")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(self.out("n.svg"), encoding="utf-8") as fh:
            text = fh.read()
        self.assertIn("Normalize fixture, millimetre document", text, "comments must survive")
        self.assertIn('transform="rotate(20 50 50) scale(1.5)"', text, "transforms must be kept as written")
        svg = inkex.load_svg(self.out("n.svg")).getroot()
        for eid in "ABC":
            got = perimeter(svg.getElementById(eid))
            self.assertLess(rel(got, 180.0), 1e-10, f"#{eid}: wanted 180 mm, got {got}")
        # The extension, on the same input and options, gives the same outlines.
        from dformer_normalize import Normalize

        ext_out = io.BytesIO()
        Normalize().run([src, "--id=A", "--id=B", "--id=C", "--pivot=centroid"], output=ext_out)
        ext = inkex.load_svg(io.BytesIO(ext_out.getvalue())).getroot()
        for eid in "ABC":
            a = support.segments(svg.getElementById(eid))
            b = support.segments(ext.getElementById(eid))
            worst = max(math.dist(p, q) for sa, sb in zip(a, b) for p, q in zip(sa, sb))
            # B's arcs: the CLI writes the circle path as given; C: both see the same polygon.
            self.assertLess(worst, 1e-9, f"#{eid}: CLI and extension outlines differ by {worst}")

    def test_connect_holes_match_the_extension(self):
        src = os.path.join(DATA, "connect_mm.svg")
        args = ["--kind", "stitch", "--count", "12", "--slide", "0.25"]
        proc = dformer("connect", src, "-o", self.out("c.svg"), *args)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        cli = inkex.load_svg(self.out("c.svg")).getroot()
        ext_out = io.BytesIO()
        with redirect_stderr(io.StringIO()):
            Connect().run([src, "--id=A", "--id=B", "--kind=stitch", "--count=12", "--slide=0.25"], output=ext_out)
        ext = inkex.load_svg(io.BytesIO(ext_out.getvalue())).getroot()
        for eid in "AB":
            mine = [h.bounding_box().center for h in cli.getElementById(f"dformer-cut-{eid}")]
            theirs = [h.bounding_box().center for h in ext.getElementById(f"dformer-cut-{eid}")]
            self.assertEqual(len(mine), 12)
            worst = max(math.dist(p, q) for p, q in zip(mine, theirs))
            self.assertLess(worst, 1e-9, f"#{eid}: CLI and extension holes differ by {worst}")
        self.assertEqual(cli.getElementById("dformer-engrave").label, "D-former engrave")

    def test_connect_twice_replaces_the_earlier_groups(self):
        src = os.path.join(DATA, "connect_mm.svg")
        dformer("connect", src, "-o", self.out("1.svg"), "--count", "12", "--slide", "0.25")
        proc = dformer("connect", self.out("1.svg"), "-o", self.out("2.svg"), "--count", "6", "--slide", "0.25")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        svg = inkex.load_svg(self.out("2.svg")).getroot()
        self.assertEqual(len(svg.getElementById("dformer-cut-A")), 6)
        self.assertEqual(len(svg.xpath("//svg:g[@id='dformer-cut']")), 1)

    def test_id_reads_only_the_chosen_shapes(self):
        # r1's width="50%" made `dformer measure rects.svg --id r2` fail.
        path = self.out("rects.svg")
        with open(path, "w", encoding="utf-8") as fh:
            fh.write('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">'
                     '<rect id="r1" width="50%" height="10"/><rect id="r2" x="10" y="20" width="30" height="20"/>'
                     '<rect id="r3" x="10" y="50" width="10" height="10"/></svg>')
        proc = dformer("measure", "--json", path, "--id", "r2")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertAlmostEqual(json.loads(proc.stdout)[0]["perimeter"], 2 * (30 + 20), 9)
        proc = dformer("normalize", path, "-o", self.out("n.svg"), "--id", "r2", "--id", "r3")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(self.out("n.svg"), encoding="utf-8") as fh:
            self.assertIn('<rect id="r1" width="50%" height="10"/>', fh.read())
        # Every shape: r1 cannot be read, so it is skipped and named with why; r2 and r3 are
        # measured (r1 used to fail the whole file).
        proc = dformer("measure", path)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([l.split("\t")[0] for l in proc.stdout.splitlines()], ["#r2", "#r3"])
        self.assertIn('skipped: #r1: attribute width="50%"', proc.stderr)

    def test_errors_are_messages_with_exit_status_1_and_no_output_file(self):
        cases = [
            (["connect", os.path.join(DATA, "pieces_mm.svg")], "exactly 2 closed shapes are needed, the file has 3"),
            (["connect", os.path.join(DATA, "pieces_mm.svg"), "--id", "A", "--id", "C"], "Normalize them first"),
            (["normalize", os.path.join(DATA, "pieces_mm.svg"), "--id", "nope"], 'no shape with id "nope"'),
            (["normalize", os.path.join(DATA, "pieces_mm.svg"), "--target", "12furlongs"], "--target"),
            # The same shape twice: normalize stopped with "internal error: overlapping edits".
            (["normalize", os.path.join(DATA, "pieces_mm.svg"), "--id", "A", "--id", "B", "--id", "A"], '--id "A" is given twice'),
            (["connect", os.path.join(DATA, "connect_mm.svg"), "--id", "A", "--id", "A", "--count", "6"], '--id "A" is given twice'),
        ]
        for args, wanted in cases:
            with self.subTest(args=args):
                proc = dformer(*args, "-o", self.out("x.svg"))
                self.assertEqual(proc.returncode, 1, proc.stderr)
                self.assertIn(wanted, proc.stderr)
                self.assertFalse(os.path.exists(self.out("x.svg")), "no output on error")


if __name__ == "__main__":
    unittest.main()
