"""The Linux Inkscape zip, installed as a user would: unzipped into a fresh HOME's Inkscape
user extensions folder (~/.config/inkscape/extensions), with no `dformer` on PATH, no
DFORMER_BIN and no cargo build. The real Inkscape 1.2 (Debian, under xvfb-run) then runs
Extensions > D-former > Measure, Normalize and Connectors on the bundled sample
(samples/pebble-and-ellipse.svg) through their action ids, and the results are checked
independently: perimeters by Gauss-Legendre quadrature of the exported cubics, the ellipse's
by the closed form (the periodic trapezoid rule on its parametric speed, exact to round-off).

Inkscape shows whatever an extension writes to stderr in a dialog and waits, even in
--batch-process mode, and Measure always reports. So the profile's preferences name a Python
interpreter of this test's (Inkscape's own setting, /extensions/python-interpreter; Debian's
Inkscape does not look for python3 on PATH), a wrapper that runs Debian's /usr/bin/python3 on the
same arguments and sends the extension's stderr to a log instead: the log holds Measure's
report, and the folder and script Inkscape started (which must be the unzipped ones)."""

import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import unittest

from support import REPO, SAMPLE, artifact, unzip, version

INKEX = os.environ.get("INKEX_PATH", "/usr/share/inkscape/extensions")
if INKEX not in sys.path:
    sys.path.insert(0, INKEX)
import inkex  # noqa: E402

INKSCAPE = shutil.which("inkscape", path="/usr/bin:/bin")
XVFB = shutil.which("xvfb-run", path="/usr/bin:/bin")

# 16-point Gauss-Legendre on [-1, 1] (Abramowitz & Stegun, table 25.4), halves of the symmetric pairs.
GL = [(0.0950125098376374, 0.1894506104550685), (0.2816035507792589, 0.1826034150449236),
      (0.4580167776572274, 0.1691565193950025), (0.6178762444026438, 0.1495959888165767),
      (0.7554044083550030, 0.1246289712555339), (0.8656312023878318, 0.0951585116824928),
      (0.9445750230732326, 0.0622535239386479), (0.9894009349916499, 0.0271524594117541)]


def cubic_length(p, a=0.0, b=1.0, depth=0):
    def speed(t):
        u = 1 - t
        d = [3 * (u * u * (p[1][i] - p[0][i]) + 2 * u * t * (p[2][i] - p[1][i]) + t * t * (p[3][i] - p[2][i])) for i in (0, 1)]
        return math.hypot(*d)

    def gl(a, b):
        m, h = (a + b) / 2, (b - a) / 2
        return h * sum(w * (speed(m - h * x) + speed(m + h * x)) for x, w in GL)

    whole, m = gl(a, b), (a + b) / 2
    halves = gl(a, m) + gl(m, b)
    if depth > 20 or abs(whole - halves) <= 1e-13 * max(1.0, abs(halves)):
        return halves
    return cubic_length(p, a, m, depth + 1) + cubic_length(p, m, b, depth + 1)


def path_perimeter(elem):
    """Perimeter of a <path> (document user units, no transforms here): its first closed subpath."""
    sub = inkex.Path(elem.get("d")).to_absolute().to_superpath()[0]
    total = sum(cubic_length((a, ar, bl, b)) for (_, a, ar), (bl, b, _) in zip(sub, sub[1:]))
    return total + math.dist(sub[-1][1], sub[0][1])


def ellipse_perimeter(a, b, n=4096):
    """Closed form: the integral of |(−a sin t, b cos t)| over a period; the trapezoid rule
    on a smooth periodic integrand converges geometrically (exact to round-off at n = 4096)."""
    return 2 * math.pi / n * sum(math.hypot(a * math.sin(2 * math.pi * k / n), b * math.cos(2 * math.pi * k / n)) for k in range(n))


class LinuxZipInRealInkscape(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        assert INKSCAPE and XVFB, "Inkscape and xvfb-run must be installed: run `bash scripts/setup.sh --all`"
        cls.home = tempfile.mkdtemp(prefix="dformer-release-inkscape-")
        cls.extensions = os.path.join(cls.home, ".config", "inkscape", "extensions")
        unzip(artifact("inkscape-linux-x86_64.zip"), cls.extensions)
        cls.wrap = os.path.join(cls.home, "wrap")
        os.makedirs(cls.wrap)
        cls.log = os.path.join(cls.home, "extension-stderr.log")
        with open(os.path.join(cls.wrap, "python3"), "w") as fh:
            fh.write(f'#!/bin/sh\nprintf "RUN %s %s\\n" "$(pwd)" "$*" >> "{cls.log}"\nexec /usr/bin/python3 "$@" 2>> "{cls.log}"\n')
        os.chmod(os.path.join(cls.wrap, "python3"), 0o755)
        with open(os.path.join(cls.home, ".config", "inkscape", "preferences.xml"), "w", encoding="utf-8") as fh:
            fh.write('<?xml version="1.0" encoding="UTF-8"?>\n<inkscape version="1">\n'
                     f'  <group id="extensions" python-interpreter="{cls.wrap}/python3" org.dformer.measure.unit="mm" org.dformer.normalize.target="largest"'
                     ' org.dformer.connect.kind="stitch" org.dformer.connect.count="16" />\n</inkscape>\n')

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.home, ignore_errors=True)

    def env(self):
        """A user's session: the fresh HOME, nothing of D-former on PATH, no DFORMER_BIN."""
        env = {k: v for k, v in os.environ.items() if not k.startswith(("DFORMER", "XDG_", "CARGO"))}
        env.update(HOME=self.home, PATH="/usr/bin:/bin")
        env.pop("DISPLAY", None)
        self.assertIsNone(shutil.which("dformer", path=env["PATH"]), "a dformer is on PATH: the test would not prove the bundled one runs")
        return env

    def inkscape(self, source, actions):
        out = os.path.join(self.home, f"out-{len(os.listdir(self.home))}.svg")
        open(self.log, "w").close()
        cmd = [XVFB, "-a", INKSCAPE, source, "--batch-process", f"--actions={actions};export-filename:{out};export-do"]
        # A session of its own, so a timeout ends Xvfb and Inkscape too, not only xvfb-run.
        child = subprocess.Popen(cmd, env=self.env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                 cwd=self.home, start_new_session=True)
        try:
            _, stderr = child.communicate(timeout=180)
        except subprocess.TimeoutExpired:
            os.killpg(child.pid, signal.SIGKILL)
            child.communicate()
            self.fail("Inkscape did not finish in 180 s (it waits on a dialog when an extension prints a message)")
        proc = subprocess.CompletedProcess(cmd, child.returncode, "", stderr)
        with open(self.log, encoding="utf-8") as fh:
            log = fh.read()
        self.assertTrue(os.path.isfile(out), f"Inkscape wrote no {out}: exit {proc.returncode}\n{proc.stderr[-3000:]}\n{log}")
        self.assertNotIn("could not find action", proc.stderr, "Inkscape did not register the D-former actions from the zip")
        ran = [line for line in log.splitlines() if line.startswith("RUN ")]
        self.assertTrue(ran, f"Inkscape ran no extension script:\n{proc.stderr[-2000:]}")
        for line in ran:
            self.assertTrue(line.startswith(f"RUN {os.path.join(self.extensions, 'dformer')} dformer_"),
                            f"Inkscape ran a script from elsewhere: {line}")
        self.assertNotIn("Traceback", log, log)
        self.assertNotIn("not found", log, log)
        return inkex.load_svg(out).getroot(), log

    def test_the_zip_holds_one_extension_folder_with_its_binary_and_versioned_inx_files(self):
        folder = os.path.join(self.extensions, "dformer")
        self.assertEqual(os.listdir(self.extensions), ["dformer"])
        self.assertTrue(os.access(os.path.join(folder, "dformer"), os.X_OK), "the bundled dformer is not executable after unzip")
        inx = sorted(f for f in os.listdir(folder) if f.endswith(".inx"))
        self.assertEqual(inx, sorted(f for f in os.listdir(os.path.join(REPO, "inkscape-extension")) if f.endswith(".inx")))
        for name in inx:
            with open(os.path.join(folder, name), encoding="utf-8") as fh:
                self.assertIn(f"(D-former {version()})", fh.read(), name)

    def test_measure_reports_both_perimeters(self):
        _, log = self.inkscape(SAMPLE, "select-by-id:pebble,ellipse;org.dformer.measure.noprefs")
        src = inkex.load_svg(SAMPLE).getroot()
        wanted = {"pebble": path_perimeter(src.getElementById("pebble")), "ellipse": ellipse_perimeter(75, 45)}
        for eid, p in wanted.items():
            line = next((ln for ln in log.splitlines() if f"#{eid}" in ln and "perimeter" in ln), None)
            self.assertIsNotNone(line, f"Measure reported nothing for #{eid}:\n{log}")
            got = float(line.split("perimeter ", 1)[1].split(" mm", 1)[0])
            # SVG draws an <ellipse> as four cubics (kappa 0.5523): 2e-7 longer than the true ellipse.
            tol = 1e-6 * p if eid == "ellipse" else 1e-4
            print(f"Measure in Inkscape, #{eid}: wanted {p:.6f} mm, got {got:.4f} mm")
            self.assertLessEqual(abs(got - p), tol, f"#{eid}: wanted {p:.6f} mm, got {got} mm")
        self.assertIn("run D-former > Normalize", log)

    def test_normalize_then_connect(self):
        svg, _ = self.inkscape(SAMPLE, "select-by-id:pebble,ellipse;org.dformer.normalize.noprefs")
        a, b = (path_perimeter(svg.getElementById(i)) for i in ("pebble", "ellipse"))
        print(f"Normalize in Inkscape: pebble {a:.9f} mm, ellipse {b:.9f} mm (largest before: ellipse {ellipse_perimeter(75, 45):.6f})")
        self.assertLess(abs(a - b), 1e-9 * b, f"wanted equal perimeters, got {a} and {b}")
        self.assertLess(abs(b - ellipse_perimeter(75, 45)), 1e-6 * b, "the largest (the ellipse) sets the perimeter")
        normalized = os.path.join(self.home, "normalized.svg")
        svg.getroottree().write(normalized)
        svg, _ = self.inkscape(normalized, "select-by-id:pebble,ellipse;org.dformer.connect.noprefs")
        for eid in ("pebble", "ellipse"):
            holes = svg.getElementById(f"dformer-cut-{eid}")
            self.assertIsNotNone(holes, f"no holes for #{eid}: Inkscape did not run Connectors")
            self.assertEqual(len(holes), 16, f"#{eid}: wanted the 16 holes of the saved settings, got {len(holes)}")
        self.assertEqual(svg.getElementById("dformer-cut").get("inkscape:groupmode"), "layer")


if __name__ == "__main__":
    unittest.main()
