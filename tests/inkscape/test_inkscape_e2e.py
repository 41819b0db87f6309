"""End to end in the real Inkscape 1.2 (/usr/bin/inkscape, Debian): the extension is
installed into a fresh, temporary Inkscape profile (XDG_CONFIG_HOME) by the same
inkscape-extension/install.sh users run (the .inx and .py files plus the `dformer` binary in
<Inkscape user data directory>/extensions/dformer/, the directory asked from Inkscape), then Inkscape opens a fixture, selects pieces by id, runs
Extensions > D-former through its action id (`org.dformer.normalize.noprefs`, …) and exports
the document. The test then reads the exported SVG and checks that Inkscape really ran the
extension: the pieces' perimeters (measured independently) became equal, the laser layers
appeared; and that Inkscape loaded the .inx files without complaint.

Needs a display for Inkscape's extension actions: run under `xvfb-run -a` (Debian package
xvfb) when $DISPLAY is unset. Inkscape starts extensions with the `python3` found on PATH; on
Debian that is /usr/bin/python3 with python3-lxml, which this test puts first on PATH.
Inkscape shows any message an extension prints (warnings, reports) in a dialog, even in
--batch-process mode, and waits: the settings used here produce no message, and 3D export
(which always reports) is tested through inkex in test_export3d.py.
Skipped (with the reason) only when Inkscape or xvfb-run is not installed at all; set
DFORMER_REQUIRE_INKSCAPE=1 (the test script does) to make that a failure instead.
"""

import os
import shutil
import subprocess
import tempfile
import unittest

import support
from support import perimeter, rel

import inkex

INKSCAPE = shutil.which("inkscape")
XVFB = shutil.which("xvfb-run")
MISSING = None if INKSCAPE and (XVFB or os.environ.get("DISPLAY")) else "inkscape or xvfb-run is not installed"


class InkscapeProfile(unittest.TestCase):
    """A fresh Inkscape profile with the extension installed by install.sh (no tests here)."""

    @classmethod
    def setUpClass(cls):
        cls.home = tempfile.mkdtemp(prefix="dformer-inkscape-")
        cls.profile = os.path.join(cls.home, "config", "inkscape")
        os.makedirs(cls.profile)
        install = subprocess.run(
            ["bash", os.path.join(support.EXTENSION, "install.sh"), "--bin", os.environ["DFORMER_BIN"]],
            env=cls.env(), capture_output=True, text=True, timeout=120, check=False,
        )
        assert install.returncode == 0, f"install.sh failed: {install.stderr}"
        assert os.path.isfile(os.path.join(cls.profile, "extensions", "dformer", "dformer_connect.inx")), install.stdout
        # Saved settings for the `.noprefs` actions (what a user's last dialog run leaves).
        with open(os.path.join(cls.profile, "preferences.xml"), "w", encoding="utf-8") as fh:
            fh.write(
                '<?xml version="1.0" encoding="UTF-8"?>\n<inkscape version="1">\n'
                '  <group id="extensions" org.dformer.connect.count="12" org.dformer.connect.slide="0.25"'
                ' org.dformer.connect.kind="stitch" org.dformer.normalize.target="largest" />\n</inkscape>\n'
            )

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.home, ignore_errors=True)

    @classmethod
    def env(cls):
        """Inkscape's environment: the temporary profile, Debian's python3 first on PATH, and
        no DFORMER_BIN, so the copy installed next to the extension must be the one found."""
        env = dict(os.environ)
        env.pop("DFORMER_BIN", None)
        env["XDG_CONFIG_HOME"] = os.path.join(cls.home, "config")
        env["PATH"] = "/usr/bin:/bin:" + env.get("PATH", "")
        return env


@unittest.skipIf(MISSING and not os.environ.get("DFORMER_REQUIRE_INKSCAPE"), MISSING or "")
class InkscapeRunsTheExtension(InkscapeProfile):
    def inkscape(self, fixture, actions):
        """Runs Inkscape on a fixture with the actions, exporting to a new SVG; returns its root."""
        out = os.path.join(self.home, f"out-{len(os.listdir(self.home))}.svg")
        env = self.env()
        cmd = [INKSCAPE, os.path.join(support.HERE, "data", "svg", fixture), "--batch-process",
               f"--actions={actions};export-filename:{out};export-do"]
        if not env.get("DISPLAY"):
            cmd = [XVFB, "-a"] + cmd
        try:
            proc = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=120, check=False)
        except subprocess.TimeoutExpired:
            self.fail(
                "Inkscape did not finish in 120 s. In --batch-process mode it waits on a dialog whenever an "
                "extension prints a message (warnings, reports): the settings of this run must produce none."
            )
        self.assertTrue(os.path.isfile(out), f"Inkscape wrote no {out}: exit {proc.returncode}\n{proc.stderr[-3000:]}")
        self.assertNotIn("could not find action", proc.stderr, "Inkscape did not register the D-former actions")
        return inkex.load_svg(out).getroot(), proc

    def test_the_inx_files_load_without_errors(self):
        self.inkscape("connect_mm.svg", "select-by-id:A,B;org.dformer.normalize.noprefs")
        log = os.path.join(self.profile, "extension-errors.log")
        text = ""
        if os.path.isfile(log):
            with open(log, encoding="utf-8") as fh:
                text = fh.read()
        self.assertNotIn("D-former", text, f"Inkscape refused a D-former .inx:\n{text}")
        self.assertNotIn("dformer", text, f"Inkscape refused a D-former .inx:\n{text}")

    def test_normalize_makes_the_selected_perimeters_equal(self):
        before = inkex.load_svg(os.path.join(support.HERE, "data", "svg", "pieces_mm.svg")).getroot()
        self.assertGreater(rel(perimeter(before.getElementById("A")), perimeter(before.getElementById("B"))), 0.1)
        svg, _ = self.inkscape("pieces_mm.svg", "select-by-id:A,B;org.dformer.normalize.noprefs")
        a, b = perimeter(svg.getElementById("A")), perimeter(svg.getElementById("B"))
        self.assertLess(rel(a, 180.0), 1e-9, f"wanted A at the largest perimeter 180 mm, got {a}")
        self.assertLess(rel(a, b), 1e-9, f"wanted equal perimeters after Inkscape ran Normalize, got {a} and {b}")
        c = perimeter(svg.getElementById("C"))
        self.assertLess(rel(c, 120.0), 1e-9, f"the unselected C must stay at 120 mm, got {c}")

    def test_connectors_land_on_laser_layers(self):
        svg, _ = self.inkscape("connect_mm.svg", "select-by-id:A,B;org.dformer.connect.noprefs")
        for eid in "AB":
            holes = svg.getElementById(f"dformer-cut-{eid}")
            self.assertIsNotNone(holes, f"no holes for #{eid}: Inkscape did not run Connectors")
            self.assertEqual(len(holes), 12, f"#{eid}: wanted the 12 holes of the saved settings, got {len(holes)}")
        layer = svg.getElementById("dformer-cut")
        self.assertEqual(layer.get("inkscape:groupmode"), "layer")


if __name__ == "__main__":
    unittest.main()
