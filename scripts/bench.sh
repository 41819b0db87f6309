#!/usr/bin/env bash
# Benchmarks (not tests): prints figures and ratios against baselines run in the same process.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# The Evolver peer (bench/evolver.bench.mjs) needs Debian's Surface Evolver.
if ! command -v evolver >/dev/null; then
  printf '\033[1mbench:\033[0m installing evolver-nox (Surface Evolver) from Debian\n'
  sudo_cmd=""; [ "$(id -u)" = 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends evolver-nox >/dev/null
fi
bash scripts/build-wasm.sh
for b in bench/*.bench.mjs; do
  printf '\n\033[1m== %s ==\033[0m\n' "$b"
  node "$b"
done
if [ -f core/examples/simulate_bench.rs ]; then
  printf '\n\033[1m== native simulate (cargo run --release --example simulate_bench) ==\033[0m\n'
  cargo run --quiet --release -p dformer --example simulate_bench
fi
printf '\n\033[1m== how often simulate finds the D-form (cargo run --release --example simulate_survey) ==\033[0m\n'
cargo run --quiet --release -p dformer --example simulate_survey
