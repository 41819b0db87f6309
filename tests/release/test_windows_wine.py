"""The Windows package's dformer.exe, run under Debian's wine64 on the sample SVG, gives the
same answers as the Linux package's dformer: `measure`, `connect` (the laser SVG it writes) and
the JSON bridge the Inkscape extension speaks on Windows. Byte for byte where the two agree
exactly; otherwise every number to round-off (relative 1e-12) and all other text identical.

Rust's standard library (1.78+) imports ProcessPrng from bcryptprimitives.dll, which Windows 10
and 11 ship and Debian's wine 8.0 lacks: the test builds a stand-in (wine/bcryptprimitives.c,
MinGW) beside the unzipped .exe. The package itself ships only dformer.exe (test_binaries.py
checks it imports nothing a Windows PC does not have)."""

import json
import os
import re
import shutil
import subprocess
import tempfile
import unittest

from support import HERE, SAMPLE, artifact, unzip, wine, wine_env

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def same_to_round_off(test, what, linux, windows):
    if linux == windows:
        return
    a, b = linux.decode("utf-8"), windows.decode("utf-8").replace("\r\n", "\n")
    test.assertEqual(NUMBER.sub("#", a), NUMBER.sub("#", b), f"{what}: the text differs beyond numbers")
    for x, y in zip(NUMBER.findall(a), NUMBER.findall(b)):
        fx, fy = float(x), float(y)
        test.assertLessEqual(abs(fx - fy), 1e-12 * max(1.0, abs(fx)), f"{what}: Linux {x}, Windows {y}")


class WindowsExeUnderWine(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="dformer-wine-")
        for plat in ("linux-x86_64", "windows-x86_64"):
            unzip(artifact(f"inkscape-{plat}.zip"), os.path.join(cls.tmp, plat))
        cls.linux = os.path.join(cls.tmp, "linux-x86_64", "dformer", "dformer")
        cls.exe = os.path.join(cls.tmp, "windows-x86_64", "dformer", "dformer.exe")
        subprocess.run(["x86_64-w64-mingw32-gcc", "-O2", "-shared", "-o",
                        os.path.join(os.path.dirname(cls.exe), "bcryptprimitives.dll"),
                        os.path.join(HERE, "wine", "bcryptprimitives.c"), "-lbcrypt"], check=True)
        shutil.copy(SAMPLE, os.path.join(cls.tmp, "sample.svg"))
        cls.env = wine_env(os.path.join(cls.tmp, "wineprefix"))
        cls.wine = wine()

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def run_both(self, args, stdin=None, status=0):
        """Runs the Linux binary and the Windows one (under wine) with the same arguments in the
        same folder, both wanted to exit with `status`; returns (linux stdout, windows stdout)."""
        linux = subprocess.run([self.linux] + args, cwd=self.tmp, input=stdin, capture_output=True, timeout=120)
        self.assertEqual(linux.returncode, status, linux.stderr.decode(errors="replace"))
        win = subprocess.run([self.wine, self.exe] + args, cwd=self.tmp, input=stdin, capture_output=True,
                             env=self.env, timeout=600)
        self.assertEqual(win.returncode, status, f"dformer.exe under wine: exit {win.returncode}\n{win.stderr.decode(errors='replace')[-2000:]}")
        return linux.stdout, win.stdout

    def test_measure_prints_the_same_perimeters(self):
        linux, windows = self.run_both(["measure", "sample.svg"])
        self.assertIn(b"pebble", linux)
        print(f"measure, Linux:\n{linux.decode()}measure, Windows (wine): {'identical bytes' if linux == windows else windows.decode()}")
        same_to_round_off(self, "measure", linux, windows)

    def test_connect_writes_the_same_laser_svg(self):
        args = ["--kind", "stitch", "--pitch", "12mm", "--diameter", "2.5mm", "--inset", "4mm"]
        self.run_both(["normalize", "sample.svg", "--target", "mean", "-o", "normalized-linux.svg"])
        self.run_both(["connect", "normalized-linux.svg"] + args + ["-o", "out.svg"])
        # Each binary wrote out.svg in turn; write them apart to compare.
        subprocess.run([self.linux, "connect", "normalized-linux.svg"] + args + ["-o", "linux.svg"],
                       cwd=self.tmp, check=True, timeout=120)
        subprocess.run([self.wine, self.exe, "connect", "normalized-linux.svg"] + args + ["-o", "windows.svg"],
                       cwd=self.tmp, env=self.env, check=True, timeout=600, capture_output=True)
        with open(os.path.join(self.tmp, "linux.svg"), "rb") as fh:
            linux = fh.read()
        with open(os.path.join(self.tmp, "windows.svg"), "rb") as fh:
            windows = fh.read()
        self.assertGreater(linux.count(b"hole"), 10, "the Linux laser SVG has no holes")
        print(f"connect: Linux {len(linux)} bytes, Windows {len(windows)} bytes, identical: {linux == windows}")
        same_to_round_off(self, "connect", linux, windows)

    def test_json_bridge_answers_alike(self):
        """What the Inkscape extension sends on Windows: a batch on stdin, answers on stdout."""
        pebble = "M 20 62 C 18 30 52 12 88 16 C 122 20 152 30 150 62 C 148 92 126 106 96 100 Z"
        linux, windows = self.run_both(["json"], stdin=json.dumps([{"op": "pathFromSvg", "d": pebble}]).encode())
        same_to_round_off(self, "json pathFromSvg", linux, windows)
        path = json.loads(linux.decode())[0][0]  # pathFromSvg answers one path per subpath
        batch = [{"op": "measure", "path": path},
                 {"op": "normalize", "paths": [path, path], "options": {"target": "exact", "length": 500}},
                 {"op": "no-such-op"}]
        # Any request refused makes the exit status 1, the other answers still given.
        linux, windows = self.run_both(["json"], stdin=json.dumps(batch).encode(), status=1)
        answers = json.loads(linux.decode())
        self.assertIn("perimeter", answers[0])
        self.assertIn("error", answers[2])
        same_to_round_off(self, "json measure/normalize/error", linux, windows)

    def test_json_bridge_gives_the_same_form_to_the_bit(self):
        """The 3D form of a cushion with a bay in one side glued to its copy at an eighth of its
        perimeter (a non-convex pair: the sheet path), and its measure: the same bytes from
        dformer.exe as from the Linux dformer. The core computes its transcendental functions
        with the `libm` crate on every system (core/src/libm_ext.rs); with each system's own
        maths library they differed in the last bits (on Linux this form's bytes did, between
        glibc and libm), and a non-convex form can turn on those."""
        bay = "M 0 0 C 40 -20 80 -20 120 0 C 140 30 140 70 120 100 C 80 75 40 75 0 100 C -20 70 -20 30 0 0 Z"
        first, _ = self.run_both(["json"], stdin=json.dumps([{"op": "pathFromSvg", "d": bay}]).encode())
        path = json.loads(first.decode())[0][0]
        measured, _ = self.run_both(["json"], stdin=json.dumps({"op": "measure", "path": path}).encode())
        offset = json.loads(measured.decode())["perimeter"] / 8
        batch = [{"op": "measure", "path": path},
                 {"op": "simulate", "pieces": [path, path], "options": {"offset": offset, "resolution": 32}}]
        linux, windows = self.run_both(["json"], stdin=json.dumps(batch).encode())
        answers = json.loads(linux.decode())
        self.assertGreater(len(answers[1]["vertices"]), 32, "the sheet path's mesh has interior vertices")
        windows = windows.replace(b"\r\n", b"\n")
        # Each answer's own clock time is the one field that may differ.
        strip = lambda text: re.sub(rb'"ms":[0-9.eE+-]+', b'"ms":0', text)
        print(f"simulate under wine: {len(linux)} bytes, identical: {strip(linux) == strip(windows)}")
        self.assertEqual(strip(linux), strip(windows), "the Windows dformer's form differs from the Linux one's")

if __name__ == "__main__":
    unittest.main()
