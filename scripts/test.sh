#!/usr/bin/env bash
# Every test: sets up what is missing (toolchain, Node deps, Chromium, Inkscape), then runs
#   1. the Rust core's tests (ground truth, properties, fuzz-style proptests),
#   2. the WebAssembly build, and the Node tests against it (core, connectors, 3D,
#      Illustrator bridge in a simulated DOM, panel in headless Chromium),
#   3. the Inkscape extension's tests, ending with a run of the real Inkscape,
#   4. the release packages, built and checked as users get them (Inkscape zips in the real
#      Inkscape, dformer.exe under wine, the CEP zip and installers, the one-file browser app).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --all

step() { printf '\n\033[1m== %s ==\033[0m\n' "$*"; }

step "Rust core (cargo test)"
cargo test --workspace --quiet

step "WebAssembly build (Node package core/pkg, web package core/pkg-web, CEP panel in dist/)"
bash scripts/build-wasm.sh
node uxp-panel/build.mjs

step "Node tests (node --test)"
node --test tests/

step "Inkscape extension and dformer CLI (unittest, real Inkscape)"
bash tests/inkscape/run.sh

step "Release packages (scripts/package.sh) and their proofs (tests/release/run.sh)"
bash scripts/package.sh --reuse-panel
bash tests/release/run.sh
