#!/usr/bin/env bash
# The main job on the bundled sample shapes: two different outlines are measured, normalized to
# one perimeter and given paired stitching holes, written as a laser-ready SVG (out/demo.svg),
# with the perimeters printed before and after. Uses the `dformer` command (cli/), the same core
# that the Illustrator panel, the browser app and the Inkscape extension run.
set -euo pipefail
cd "$(dirname "$0")/.."
# The demo runs only the native `dformer`: it needs cargo and nothing else (no WebAssembly tools,
# no Node packages, which scripts/setup.sh would install for the panel and the tests).
export PATH="$HOME/.cargo/bin:$PATH"
command -v cargo >/dev/null || { echo "demo: cargo not found. Install Rust from rustup first." >&2; exit 1; }
cargo build --quiet --release -p dformer-cli
dformer="${CARGO_TARGET_DIR:-target}/release/dformer"
sample=samples/pebble-and-ellipse.svg
out=out/demo.svg
mkdir -p out

echo "== Bundled sample: $sample"
"$dformer" measure "$sample"
echo
echo "== Normalized to the mean perimeter, each shape scaled about its centre"
"$dformer" normalize "$sample" --target mean -o "$out.normalized.svg"
"$dformer" measure "$out.normalized.svg"
echo
echo "== Paired stitching holes, about every 12 mm, 2.5 mm across, 4 mm in from the edge"
"$dformer" connect "$out.normalized.svg" --kind stitch --pitch 12mm --diameter 2.5mm --inset 4mm -o "$out"
rm -f "$out.normalized.svg"
echo
echo "Wrote $out (cut: red hairline, score: blue, engrave: black). Open it in a browser, Inkscape or Illustrator."
echo
echo "== The 3D form of the stitched pieces (first anchor to first anchor, as the holes pair up)"
"$dformer" form "$out" --id pebble --id ellipse -o out/demo-form.stl -o out/demo-form.svg
echo "Wrote out/demo-form.stl (mm, for a slicer or CAD) and out/demo-form.svg (a picture of the form)."
