"""One version number, [workspace.package] version in the workspace Cargo.toml, is the one in
package.json, the CEP manifest inside the Illustrator zip, every .inx inside every Inkscape zip,
every file name, the browser file's core (the footer reads it from the WASM core), and
SHA256SUMS lists every artifact with its real digest (hashlib, not sha256sum) and nothing else;
CHANGELOG.md has an entry for it."""

import hashlib
import json
import os
import re
import unittest
import zipfile

from support import RELEASE, REPO, artifact, version

ARTIFACTS = ["inkscape-linux-x86_64.zip", "inkscape-windows-x86_64.zip", "inkscape-macos.zip", "illustrator.zip", "html"]


class OneVersion(unittest.TestCase):
    def test_package_json_and_changelog(self):
        with open(os.path.join(REPO, "package.json"), encoding="utf-8") as fh:
            self.assertEqual(json.load(fh)["version"], version(), "package.json's version")
        with open(os.path.join(REPO, "CHANGELOG.md"), encoding="utf-8") as fh:
            first = re.search(r"^## \[?([\w.-]+)\]?", fh.read(), re.M)
        self.assertIsNotNone(first, "CHANGELOG.md has no release heading")
        self.assertEqual(first.group(1), version(), "CHANGELOG.md's newest entry")

    def test_every_artifact_is_named_with_the_version_and_carries_it(self):
        self.assertEqual(sorted(os.listdir(RELEASE)),
                         sorted([os.path.basename(artifact(k)) for k in ARTIFACTS] + ["SHA256SUMS"]))
        for kind in ARTIFACTS[:3]:
            with zipfile.ZipFile(artifact(kind)) as z:
                inx = [n for n in z.namelist() if n.endswith(".inx")]
                self.assertGreaterEqual(len(inx), 4, kind)
                for n in inx:
                    self.assertIn(f"(D-former {version()})", z.read(n).decode(), f"{kind}: {n}")
        with zipfile.ZipFile(artifact("illustrator.zip")) as z:
            manifest = z.read(f"d-former-{version()}-illustrator/com.dformer.panel/CSXS/manifest.xml").decode()
        self.assertIn(f'ExtensionBundleVersion="{version()}"', manifest)
        with open(artifact("html"), encoding="utf-8") as fh:
            self.assertIn(f'<meta name="generator" content="D-former {version()}">', fh.read(), "the browser file's build stamp")

    def test_sha256sums_lists_every_artifact_with_its_digest(self):
        with open(os.path.join(RELEASE, "SHA256SUMS"), encoding="utf-8") as fh:
            lines = [ln.split("  ", 1) for ln in fh.read().splitlines()]
        listed = {name: digest for digest, name in lines}
        self.assertEqual(sorted(listed), sorted(os.path.basename(artifact(k)) for k in ARTIFACTS))
        for name, digest in listed.items():
            with open(os.path.join(RELEASE, name), "rb") as fh:
                self.assertEqual(hashlib.sha256(fh.read()).hexdigest(), digest, name)


if __name__ == "__main__":
    unittest.main()
