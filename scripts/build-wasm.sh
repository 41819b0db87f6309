#!/usr/bin/env bash
# Builds the core as WebAssembly: core/pkg (Node, CommonJS) and core/pkg-web (browser ES module),
# each shrunk by binaryen's wasm-opt -Oz from npm (scripts/wasm-opt.mjs says why not wasm-pack's).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
for target in nodejs web; do
  out=pkg; [ "$target" = web ] && out=pkg-web
  rm -rf "core/$out"
  wasm-pack --log-level warn build core --release --target "$target" --out-dir "$out"
  node scripts/wasm-opt.mjs "core/$out/dformer_bg.wasm"
done
