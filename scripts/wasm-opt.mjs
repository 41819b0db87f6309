// Shrinks a wasm-bindgen output with binaryen's wasm-opt -Oz, in place.
//
// wasm-pack's own wasm-opt step stays off (core/Cargo.toml): wasm-pack downloads binaryen from
// GitHub, which a build without internet cannot do, and Debian's binaryen (v108) breaks
// wasm-bindgen's externref table. The npm `binaryen` package (a dev dependency) is a current
// binaryen compiled to JavaScript, so this step runs wherever `npm ci` has run. A plain
// `wasm-pack build core` without it still gives a working, just larger, module.
//
// Usage: node scripts/wasm-opt.mjs <file.wasm> [--mvp]
//   default  the features rustc's wasm32 target enables (bulk memory, sign extension,
//            saturating float→int, mutable globals, reference types, multi-value)
//   --mvp    WebAssembly 1.0 only: validates that the CEP panel's lowered module stays MVP
import { execFileSync } from 'node:child_process';
import { existsSync, statSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const RUSTC_FEATURES = [
  '--enable-bulk-memory',
  '--enable-sign-ext',
  '--enable-nontrapping-float-to-int',
  '--enable-mutable-globals',
  '--enable-reference-types',
  '--enable-multivalue',
];

/** Optimizes `file` in place; returns its sizes before and after, in bytes. */
export function wasmOpt(file, { mvp = false } = {}) {
  const bin = fileURLToPath(new URL('../node_modules/.bin/wasm-opt', import.meta.url));
  if (!existsSync(bin)) throw new Error(`wasm-opt not found at ${bin}: run "npm ci" (or scripts/setup.sh) first`);
  const before = statSync(file).size;
  const features = mvp ? ['--mvp-features'] : RUSTC_FEATURES;
  execFileSync(bin, [...features, '-Oz', file, '-o', file], { stdio: 'inherit' });
  return { before, after: statSync(file).size };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const [file, flag] = process.argv.slice(2);
  if (!file) {
    console.error('usage: node scripts/wasm-opt.mjs <file.wasm> [--mvp]');
    process.exit(2);
  }
  const { before, after } = wasmOpt(file, { mvp: flag === '--mvp' });
  console.log(`wasm-opt -Oz ${file}: ${(before / 1024).toFixed(1)} KB → ${(after / 1024).toFixed(1)} KB`);
}
