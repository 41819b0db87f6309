#!/usr/bin/env bash
# The main job: sets up what is missing, builds the core, runs it on the bundled sample shapes.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build-wasm.sh
node scripts/demo.mjs "$@"
