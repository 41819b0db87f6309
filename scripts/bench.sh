#!/usr/bin/env bash
# Benchmarks (not tests): prints figures and ratios against baselines run in the same process.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build-wasm.sh
for b in bench/*.bench.mjs; do
  printf '\n\033[1m== %s ==\033[0m\n' "$b"
  node "$b"
done
if [ -f core/examples/simulate_bench.rs ]; then
  printf '\n\033[1m== native simulate (cargo run --release --example simulate_bench) ==\033[0m\n'
  cargo run --quiet --release -p dformer --example simulate_bench
fi
