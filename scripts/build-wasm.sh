#!/usr/bin/env bash
# Builds the core as WebAssembly: core/pkg (Node, CommonJS) and core/pkg-web (browser ES module).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
for target in nodejs web; do
  out=pkg; [ "$target" = web ] && out=pkg-web
  rm -rf "core/$out"
  wasm-pack --log-level warn build core --release --target "$target" --out-dir "$out"
done
