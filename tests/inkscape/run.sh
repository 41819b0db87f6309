#!/usr/bin/env bash
# The Inkscape side of the test suite: builds the `dformer` CLI, then runs with Debian's
# /usr/bin/python3 (the interpreter Inkscape runs extensions with, and Inkscape 1.2's bundled
# inkex from /usr/share/inkscape/extensions):
#   - the CLI's own Rust unit tests (cargo test -p dformer-cli);
#   - test_golden.py      inkex ComparisonMixin golden files (EXPORT_COMPARE=2/3 to regenerate);
#   - test_properties.py  equal perimeters, paired holes at pitch and inset, errors, .inx checks;
#   - test_export3d.py    the OBJ/STL written by 3D export against the reported volume and area;
#   - test_cli.py         the JSON bridge and batch SVG commands, cross-checked with the extension;
#   - test_inkscape_e2e.py the real Inkscape 1.2 running the installed extension (under xvfb-run);
#   - test_inkscape_refusals.py each bad input of issue 15 refused in the real Inkscape: its message
#     as Inkscape received it, the exported document unchanged (own Xvfb; xdotool closes the dialog).
# Needs: inkscape, python3-lxml, python3-numpy (Inkscape's own dependencies), xvfb + xauth, xdotool.
set -euo pipefail
cd "$(dirname "$0")/../.."
DFORMER_BIN="$(cargo build -p dformer-cli --message-format=json-render-diagnostics \
  | /usr/bin/python3 -c 'import json, sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and m.get("executable"):
        print(m["executable"])' | tail -n 1)"
export DFORMER_BIN
cargo test -p dformer-cli --quiet
export DFORMER_REQUIRE_INKSCAPE=1
/usr/bin/python3 -m unittest discover -s tests/inkscape -t tests/inkscape "$@"
