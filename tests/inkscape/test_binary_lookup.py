"""Which `dformer` the extension runs, and what it says when that one fails: the binary bundled
next to the extension first (as the release zips ship it), then one on PATH; every failure
message names the program and where it came from. A bundled binary that lost its executable bit
(Inkscape's Extension Manager writes zip members without permissions) is made executable again.
Each case loads a fresh copy of dformer_bridge.py from a temporary extension folder, with
stand-in programs (shell scripts) for dformer, and no DFORMER_BIN."""

import importlib.util
import os
import shutil
import stat
import tempfile
import unittest
from unittest import mock

HERE = os.path.dirname(os.path.abspath(__file__))
BRIDGE = os.path.join(os.path.dirname(os.path.dirname(HERE)), "inkscape-extension", "dformer_bridge.py")


def program(path, script, mode=0o755):
    with open(path, "w") as fh:
        fh.write("#!/bin/sh\n" + script + "\n")
    os.chmod(path, mode)


class BinaryLookup(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="dformer-lookup-")
        self.ext = os.path.join(self.tmp, "extensions", "dformer")
        self.bin = os.path.join(self.tmp, "bin")
        os.makedirs(self.ext)
        os.makedirs(self.bin)
        shutil.copy(BRIDGE, self.ext)
        env = {k: v for k, v in os.environ.items() if k != "DFORMER_BIN"}
        env["PATH"] = self.bin + ":/usr/bin:/bin"
        patcher = mock.patch.dict(os.environ, env, clear=True)
        patcher.start()
        self.addCleanup(patcher.stop)
        self.addCleanup(shutil.rmtree, self.tmp, True)

    def bridge(self):
        spec = importlib.util.spec_from_file_location(f"bridge_{id(self)}", os.path.join(self.ext, "dformer_bridge.py"))
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        return module

    def test_bundled_binary_comes_before_path(self):
        program(os.path.join(self.ext, "dformer"), "echo '[{\"from\": \"bundled\"}]'")
        program(os.path.join(self.bin, "dformer"), "echo '[{\"from\": \"path\"}]'")
        self.assertEqual(self.bridge().run_batch([{"op": "x"}]), [{"from": "bundled"}])

    def test_path_is_used_when_nothing_is_bundled(self):
        program(os.path.join(self.bin, "dformer"), "echo '[{\"from\": \"path\"}]'")
        self.assertEqual(self.bridge().run_batch([{"op": "x"}]), [{"from": "path"}])

    def test_failing_bundled_binary_is_named_as_bundled(self):
        bundled = os.path.join(self.ext, "dformer")
        program(bundled, "echo 'Segmentation fault' >&2; exit 139")
        program(os.path.join(self.bin, "dformer"), "echo '[{}]'")
        with self.assertRaises(Exception) as caught:
            self.bridge().run_batch([{"op": "x"}])
        msg = str(caught.exception)
        self.assertIn(f"{bundled} (bundled with the extension)", msg)
        self.assertIn("exit status 139", msg)
        self.assertIn("Segmentation fault", msg)

    def test_failing_path_binary_is_named_as_found_on_path(self):
        on_path = os.path.join(self.bin, "dformer")
        program(on_path, "echo 'not json'")
        with self.assertRaises(Exception) as caught:
            self.bridge().run_batch([{"op": "x"}])
        self.assertIn(f"{on_path} (found on PATH)", str(caught.exception))

    def test_no_binary_anywhere_says_where_it_looked_and_what_to_download(self):
        with self.assertRaises(Exception) as caught:
            self.bridge().run_batch([{"op": "x"}])
        msg = str(caught.exception)
        self.assertIn(self.ext, msg)
        self.assertIn("on PATH", msg)
        self.assertIn("Download the D-former Inkscape zip", msg)

    def test_bundled_binary_without_executable_bit_is_made_executable(self):
        bundled = os.path.join(self.ext, "dformer")
        program(bundled, "echo '[{\"ok\": 1}]'", mode=0o644)
        self.assertEqual(self.bridge().run_batch([{"op": "x"}]), [{"ok": 1}])
        self.assertEqual(stat.S_IMODE(os.stat(bundled).st_mode), 0o755)

    def test_on_macos_the_bundled_binary_loses_its_download_quarantine_flag(self):
        bundled = os.path.join(self.ext, "dformer")
        program(bundled, "echo '[{\"ok\": 1}]'")
        program(os.path.join(self.bin, "xattr"), f'printf "%s\\n" "$*" >> "{self.tmp}/xattr.log"')
        bridge = self.bridge()
        bridge.XATTR = os.path.join(self.bin, "xattr")
        with mock.patch.object(bridge.sys, "platform", "darwin"):
            self.assertEqual(bridge.run_batch([{"op": "x"}]), [{"ok": 1}])
        with open(os.path.join(self.tmp, "xattr.log")) as fh:
            self.assertEqual(fh.read().splitlines(), [f"-d com.apple.quarantine {bundled}"])

    def test_a_file_that_is_no_program_says_so(self):
        bundled = os.path.join(self.ext, "dformer")
        with open(bundled, "wb") as fh:
            fh.write(b"MZ\x90\x00 a Windows program on Linux")
        os.chmod(bundled, 0o755)
        with self.assertRaises(Exception) as caught:
            self.bridge().run_batch([{"op": "x"}])
        msg = str(caught.exception)
        self.assertIn(f"{bundled} (bundled with the extension)", msg)
        self.assertIn("not a program for this computer", msg)


if __name__ == "__main__":
    unittest.main()
