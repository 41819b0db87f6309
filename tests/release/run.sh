#!/usr/bin/env bash
# The proofs of the release packages in dist/release/ (build them first: bash scripts/package.sh):
#   test_binaries.py       the macOS, Linux and Windows dformer headers, read by our own code;
#   test_windows_wine.py   dformer.exe under wine64 answers as the Linux binary does;
#   test_inkscape_zip.py   the Linux zip unzipped into a fresh HOME, real Inkscape 1.2, no dformer on PATH;
#   test_illustrator_zip.py the CEP manifest against Adobe's XSD, the installers (shellcheck, fake HOME, text);
#   test_version.py        one version everywhere, SHA256SUMS;
#   offline-html.mjs       the one-file browser app opened from disk in headless Chromium.
# Debian's /usr/bin/python3 (lxml, Inkscape's inkex) runs the Python ones.
set -euo pipefail
cd "$(dirname "$0")/../.."
/usr/bin/python3 -m unittest discover -s tests/release -t tests/release -p 'test_*.py' "$@"
node --test tests/release/offline-html.mjs
