"""The Illustrator zip: its CEP manifest validates against Adobe's schema (lxml XMLSchema on
ExtensionManifest_v_7_0.xsd from shared/cep beside the repository), the macOS installer passes
shellcheck and, run with a fake HOME on Linux, writes exactly the panel's files where CEP looks
for per-user extensions and sets PlayerDebugMode for CSXS 8-12 and nothing else; the Windows
installer's folder and registry keys are those of Adobe's CEP Cookbook (checked as text)."""

import os
import re
import shutil
import subprocess
import tempfile
import unittest
import zipfile

from lxml import etree

from support import REPO, artifact, unzip, version, wine, wine_env

ID = "com.dformer.panel"
CSXS_VERSIONS = ["8", "9", "10", "11", "12"]


def schema_path():
    """Adobe's CEP 7.0 manifest schema: ../shared/cep/ beside the repository (in CI the clone sits
    beside a copy of shared/; a developer's worktree may be one level deeper, under wt/)."""
    for up in ("..", os.path.join("..", ".."), os.path.join("..", "..", "..")):
        path = os.path.normpath(os.path.join(REPO, up, "shared", "cep", "ExtensionManifest_v_7_0.xsd"))
        if os.path.isfile(path):
            return path
    raise AssertionError(f"Adobe's CEP schema ExtensionManifest_v_7_0.xsd is not in ../shared/cep/ beside {REPO}")


class IllustratorZip(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.zip = artifact("illustrator.zip")
        cls.tmp = tempfile.mkdtemp(prefix="dformer-cep-")
        unzip(cls.zip, cls.tmp)
        cls.top = os.path.join(cls.tmp, f"d-former-{version()}-illustrator")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_zip_holds_the_panel_and_four_installers(self):
        with zipfile.ZipFile(self.zip) as z:
            names = set(z.namelist())
            top = f"d-former-{version()}-illustrator/"
            for f in ("install-macos.command", "uninstall-macos.command", "install-windows.cmd",
                      "uninstall-windows.cmd", "README.txt", f"{ID}/CSXS/manifest.xml", f"{ID}/index.html",
                      f"{ID}/jsx/dformer-bridge.jsx", f"{ID}/wasm/dformer-wasm-inline.js"):
                self.assertIn(top + f, names)
            for f in ("install-macos.command", "uninstall-macos.command"):
                mode = (z.getinfo(top + f).external_attr >> 16) & 0o777
                self.assertEqual(mode & 0o111, 0o111, f"{f} must be stored executable to open by double-click (mode {mode:o})")

    def test_manifest_validates_against_adobes_schema(self):
        xsd = etree.XMLSchema(etree.parse(schema_path()))
        doc = etree.parse(os.path.join(self.top, ID, "CSXS", "manifest.xml"))
        ok = xsd.validate(doc)
        self.assertTrue(ok, "manifest.xml breaks ExtensionManifest_v_7_0.xsd:\n" + "\n".join(str(e) for e in xsd.error_log))
        root = doc.getroot()
        self.assertEqual(root.get("ExtensionBundleVersion"), version())
        self.assertEqual([e.get("Version") for e in root.iter("Extension") if e.get("Version")], [version()])

    def test_macos_installer_passes_shellcheck(self):
        for f in ("install-macos.command", "uninstall-macos.command"):
            proc = subprocess.run(["shellcheck", "--shell=bash", os.path.join(self.top, f)], capture_output=True, text=True)
            self.assertEqual(proc.returncode, 0, f"shellcheck {f}:\n{proc.stdout}{proc.stderr}")

    def run_macos(self, script, home, log):
        """Runs a .command with HOME=home and a stand-in for macOS's `defaults` that logs its
        arguments (the real one writes ~/Library/Preferences/<domain>.plist through cfprefsd)."""
        bin_dir = os.path.join(os.path.dirname(home), "bin")
        os.makedirs(bin_dir, exist_ok=True)
        with open(os.path.join(bin_dir, "defaults"), "w") as fh:
            fh.write(f'#!/bin/sh\nprintf "%s\\n" "$*" >> "{log}"\n')
        os.chmod(os.path.join(bin_dir, "defaults"), 0o755)
        env = {"HOME": home, "PATH": f"{bin_dir}:/usr/bin:/bin"}
        return subprocess.run(["/bin/bash", os.path.join(self.top, script)], env=env, capture_output=True, text=True,
                              timeout=60, cwd="/")

    def test_macos_installer_writes_exactly_the_cep_folder_and_player_debug_mode(self):
        with tempfile.TemporaryDirectory() as tmp:
            home, log = os.path.join(tmp, "home"), os.path.join(tmp, "defaults.log")
            os.makedirs(home)
            proc = self.run_macos("install-macos.command", home, log)
            self.assertEqual(proc.returncode, 0, proc.stdout + proc.stderr)
            written = sorted(os.path.relpath(os.path.join(d, f), home) for d, _, fs in os.walk(home) for f in fs)
            panel = os.path.join(self.top, ID)
            wanted = sorted(os.path.join("Library", "Application Support", "Adobe", "CEP", "extensions", ID,
                                         os.path.relpath(os.path.join(d, f), panel)) for d, _, fs in os.walk(panel) for f in fs)
            self.assertEqual(written, wanted, "the installer must write the panel's files there and nothing else")
            for rel in wanted:
                with open(os.path.join(home, rel), "rb") as a, open(os.path.join(panel, rel.split(ID + os.sep, 1)[1]), "rb") as b:
                    self.assertEqual(a.read(), b.read(), rel)
            with open(log) as fh:
                calls = fh.read().splitlines()
            self.assertEqual(calls, [f"write com.adobe.CSXS.{v} PlayerDebugMode -string 1" for v in CSXS_VERSIONS])
            # Again over an installed copy (an update), then uninstall: nothing of D-former is left.
            self.assertEqual(self.run_macos("install-macos.command", home, log).returncode, 0)
            proc = self.run_macos("uninstall-macos.command", home, log)
            self.assertEqual(proc.returncode, 0, proc.stdout + proc.stderr)
            left = [os.path.join(d, f) for d, _, fs in os.walk(home) for f in fs]
            self.assertEqual(left, [], "uninstall leaves files behind")

    def test_macos_installer_refuses_to_run_outside_the_unzipped_folder(self):
        with tempfile.TemporaryDirectory() as tmp:
            lone = os.path.join(tmp, "install-macos.command")
            shutil.copy(os.path.join(self.top, "install-macos.command"), lone)
            home = os.path.join(tmp, "home")
            os.makedirs(home)
            proc = subprocess.run(["/bin/bash", lone], env={"HOME": home, "PATH": "/usr/bin:/bin"},
                                  capture_output=True, text=True, timeout=60)
            self.assertNotEqual(proc.returncode, 0)
            self.assertIn("Unzip the whole", proc.stdout)
            self.assertEqual(os.listdir(home), [], "nothing may be written when the panel folder is missing")

    def test_windows_installer_uses_the_cep_cookbook_folder_and_registry_keys(self):
        with open(os.path.join(self.top, "install-windows.cmd"), "rb") as fh:
            raw = fh.read()
        self.assertNotIn(b"\n", raw.replace(b"\r\n", b""), "cmd.exe scripts need CRLF line endings throughout")
        text = raw.decode("ascii")
        # CEP Cookbook, "Extension Folders": per user, %APPDATA%\Adobe\CEP\extensions (Windows).
        self.assertIn(r'set "DEST=%APPDATA%\Adobe\CEP\extensions\%ID%"', text)
        self.assertIn(f'set "ID={ID}"', text)
        self.assertIn(r'xcopy "%SRC%" "%DEST%\" /e /i /q /y', text)
        # CEP Cookbook, "Debugging Unsigned Extensions": HKEY_CURRENT_USER/Software/Adobe/CSXS.N,
        # PlayerDebugMode, of type String, value 1.
        loop = re.search(r"for %%V in \(([\d ]+)\) do \(\r\n\s*reg add \"HKCU\\Software\\Adobe\\CSXS\.%%V\" "
                         r"/v PlayerDebugMode /t REG_SZ /d 1 /f", text)
        self.assertIsNotNone(loop, "no reg add of PlayerDebugMode (REG_SZ 1) under HKCU\\Software\\Adobe\\CSXS.N")
        self.assertEqual(loop.group(1).split(), CSXS_VERSIONS)
        commands = [ln for ln in text.split("\r\n") if not ln.lstrip().lower().startswith("rem ")]
        self.assertEqual(sum("reg " in ln for ln in commands), 1, "the installer must change nothing else in the registry")
        with open(os.path.join(self.top, "uninstall-windows.cmd"), "rb") as fh:
            un = fh.read().decode("ascii")
        self.assertIn(r'set "DEST=%APPDATA%\Adobe\CEP\extensions\com.dformer.panel"', un)
        self.assertIn('rmdir /s /q "%DEST%"', un)
        commands = [ln for ln in un.split("\r\n") if not ln.lstrip().lower().startswith("rem ")]
        self.assertFalse([ln for ln in commands if "reg " in ln], "uninstall must not touch the registry")

    def test_windows_installer_run_by_cmd_under_wine_installs_and_uninstalls(self):
        """The same script run for real by cmd.exe (wine's): the files land in the user's
        %APPDATA%, and reg.exe reads PlayerDebugMode back as REG_SZ "1" for each CSXS version."""
        with tempfile.TemporaryDirectory() as tmp:
            env = wine_env(os.path.join(tmp, "prefix"), DFORMER_NO_PAUSE="1")
            proc = subprocess.run([wine(), "cmd", "/c", "install-windows.cmd"], cwd=self.top, env=env,
                                  capture_output=True, timeout=600)
            self.assertEqual(proc.returncode, 0, proc.stdout.decode(errors="replace") + proc.stderr.decode(errors="replace")[-2000:])
            users = os.path.join(tmp, "prefix", "drive_c", "users")
            user = next(u for u in sorted(os.listdir(users)) if u != "Public")
            appdata = os.path.join(users, user, "AppData", "Roaming")
            panel = os.path.join(self.top, ID)
            installed = os.path.join(appdata, "Adobe", "CEP", "extensions", ID)
            rel = lambda root: sorted(os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs)
            self.assertEqual(rel(installed), rel(panel), "cmd.exe copied other files than the panel's")
            q = subprocess.run([wine(), "reg", "query", "HKCU\\Software\\Adobe", "/s"], env=env, capture_output=True, timeout=300)
            listing = q.stdout.decode(errors="replace").replace("\r\n", "\n")
            keys = re.findall(r"^HKEY_CURRENT_USER\\Software\\Adobe\\(\S+)\n((?:    .*\n)*)", listing, re.M)
            self.assertEqual(sorted(k for k, _ in keys), sorted(f"CSXS.{v}" for v in CSXS_VERSIONS), listing)
            for key, values in keys:
                self.assertRegex(values, r"^\s+PlayerDebugMode\s+REG_SZ\s+1\s*$", f"{key}: {values}")
            proc = subprocess.run([wine(), "cmd", "/c", "uninstall-windows.cmd"], cwd=self.top, env=env,
                                  capture_output=True, timeout=600)
            self.assertEqual(proc.returncode, 0)
            self.assertFalse(os.path.exists(installed), "uninstall-windows.cmd left the panel folder")


if __name__ == "__main__":
    unittest.main()
