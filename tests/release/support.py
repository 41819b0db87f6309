"""Shared by the release tests: where the packages are (dist/release/, built by
`bash scripts/package.sh`), the project version, and unzipping as a user's tool does."""

import os
import re
import shutil
import subprocess
import unittest
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
RELEASE = os.path.join(REPO, "dist", "release")
SAMPLE = os.path.join(REPO, "samples", "pebble-and-ellipse.svg")


def version():
    """[workspace.package] version from the workspace Cargo.toml: the one project version."""
    with open(os.path.join(REPO, "Cargo.toml"), encoding="utf-8") as fh:
        text = fh.read()
    m = re.search(r'^\[workspace\.package\][^\[]*?^version = "([^"]+)"', text, re.M | re.S)
    assert m, "no [workspace.package] version in Cargo.toml"
    return m.group(1)


def artifact(kind):
    """The path of one release file, e.g. artifact("inkscape-linux-x86_64.zip"); fails clearly if
    the packages were not built."""
    path = os.path.join(RELEASE, f"d-former-{version()}-{kind}" if kind != "html" else f"d-former-{version()}.html")
    if not os.path.isfile(path):
        raise AssertionError(
            f"{path} is missing: run `bash scripts/package.sh` first (scripts/test.sh does)")
    return path


def unzip(path, dest):
    """Unzips with Info-ZIP's unzip, which (like macOS's Archive Utility) restores the Unix
    permissions stored in the zip; Python's zipfile would not."""
    os.makedirs(dest, exist_ok=True)
    subprocess.run(["unzip", "-q", "-o", path, "-d", dest], check=True)


def read_member(path, name):
    with zipfile.ZipFile(path) as z:
        return z.read(name)


def wine():
    """Debian's wine64 loader (package wine64 puts it in /usr/lib/wine) and the environment for
    a throw-away prefix in `prefix`: no debug chatter, no Mono/Gecko install prompts, no display."""
    for candidate in (shutil.which("wine64"), "/usr/lib/wine/wine64", shutil.which("wine")):
        if candidate and os.path.isfile(candidate):
            return candidate
    raise AssertionError("wine64 is not installed: run `bash scripts/setup-release.sh`")


def wine_env(prefix, **extra):
    env = dict(os.environ, WINEPREFIX=prefix, WINEDEBUG="-all", WINEDLLOVERRIDES="mscoree,mshtml=", **extra)
    env.pop("DISPLAY", None)
    return env
