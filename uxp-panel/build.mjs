#!/usr/bin/env node
// Builds the D-former panel:
//   1. compiles the core for WebAssembly *MVP* (`-C target-cpu=mvp`) so old CEP Chromiums can run it,
//   2. runs wasm-bindgen `--target web` (the only target that keeps the core's `inline_js`
//      snippets) and bundles glue + snippets with esbuild into ONE classic script (IIFE, global
//      `dformerWasm`) whose syntax is lowered to Chromium 57 (CEP 8 has no ES modules, no `??`),
//   3. lowers the standard library's post-MVP instructions (tools/wasm-lower-mvp.mjs), shrinks the
//      result with wasm-opt (scripts/wasm-opt.mjs, validating it as MVP) and inlines the bytes as base64 (CEP will not fetch() file:// URLs; inlining avoids Node.js in the panel),
//   4. scans the .wasm for post-MVP features left and sets the manifest's minimum CEP/Illustrator to
//      the oldest CEP whose Chromium can instantiate it (tools/wasm-features.mjs),
//   5. assembles the installable extension folder dist/com.dformer.panel/ (panel + jsx bridge, the
//      manifest's versions from the workspace Cargo.toml), the standalone browser app
//      dist/d-former-web/ and the same app as one self-contained file, dist/d-former.html.
// Usage: node uxp-panel/build.mjs [--dev] [--skip-wasm]
import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { Reader, readSections } from './tools/wasm-binary.mjs';
import { minimumCep, scanWasmFeatures } from './tools/wasm-features.mjs';
import { singleHtml } from './tools/single-html.mjs';
import { lowerToMvp } from './tools/wasm-lower-mvp.mjs';
import { wasmOpt } from '../scripts/wasm-opt.mjs';

const panel = dirname(fileURLToPath(import.meta.url));
const repo = dirname(panel);
const args = new Set(process.argv.slice(2));
const dev = args.has('--dev');
const wasmDir = join(panel, 'wasm');

/** Removes the `target_features` custom section: std is prebuilt with reference-types, which would
 * make wasm-bindgen emit an externref table our MVP objects cannot back. */
function stripTargetFeatures(bytes) {
  const kept = readSections(bytes).filter((s) => !(s.id === 0 && new Reader(s.body).name() === 'target_features'));
  return Buffer.concat([bytes.subarray(0, 8), ...kept.map((s) => s.raw)]);
}

async function buildWasm() {
  const targetDir =
    process.env.DFORMER_PANEL_TARGET_DIR ||
    (process.env.CARGO_TARGET_DIR ? `${process.env.CARGO_TARGET_DIR}-cep-mvp` : join(repo, 'target', 'cep-mvp'));
  // RUSTFLAGS replaces .cargo/config.toml's wasm32 flags, so its inline threshold is repeated here.
  const env = { ...process.env, CARGO_TARGET_DIR: targetDir, RUSTFLAGS: '-C target-cpu=mvp -C llvm-args=-inline-threshold=100' };
  const cargoArgs = ['build', '-p', 'dformer', '--lib', '--target', 'wasm32-unknown-unknown'];
  if (!dev) cargoArgs.push('--release');
  console.log(`[panel] cargo ${cargoArgs.join(' ')}  (RUSTFLAGS=${env.RUSTFLAGS}, target dir ${targetDir})`);
  execFileSync('cargo', cargoArgs, { cwd: repo, env, stdio: 'inherit' });
  const built = join(targetDir, 'wasm32-unknown-unknown', dev ? 'debug' : 'release', 'dformer.wasm');
  const stripped = join(targetDir, 'dformer-mvp.wasm');
  writeFileSync(stripped, stripTargetFeatures(readFileSync(built)));
  rmSync(wasmDir, { recursive: true, force: true });
  const web = join(targetDir, 'panel-web');
  rmSync(web, { recursive: true, force: true });
  execFileSync('wasm-bindgen', [stripped, '--target', 'web', '--no-typescript', '--out-dir', web, '--out-name', 'dformer'], {
    stdio: 'inherit',
  });
  mkdirSync(wasmDir, { recursive: true });
  const lowered = lowerToMvp(readFileSync(join(web, 'dformer_bg.wasm')));
  console.log(`[panel] lowered to MVP: ${JSON.stringify(lowered.lowered)}`);
  const out = join(wasmDir, 'dformer_bg.wasm');
  writeFileSync(out, lowered.bytes);
  if (!dev) {
    // Shrink; when nothing post-MVP is left, binaryen also validates the module as pure MVP.
    const mvp = Object.keys(scanWasmFeatures(lowered.bytes).features).length === 0;
    const { before, after } = wasmOpt(out, { mvp });
    console.log(`[panel] wasm-opt -Oz${mvp ? ' --mvp-features' : ''}: ${(before / 1024).toFixed(0)} KB → ${(after / 1024).toFixed(0)} KB`);
  }
  const esbuild = await import('esbuild');
  await esbuild.build({
    entryPoints: [join(web, 'dformer.js')],
    bundle: true,
    format: 'iife',
    globalName: 'dformerWasm',
    target: 'chrome57',
    // The glue's default .wasm URL (import.meta.url) is never used: core.js always passes the bytes.
    define: { 'import.meta.url': 'document.baseURI' },
    banner: { js: '/* D-former core: wasm-bindgen glue (+ inline_js snippets) bundled by uxp-panel/build.mjs for Chromium 57. */' },
    outfile: join(wasmDir, 'dformer.js'),
    logLevel: 'warning',
  });
}

if (!args.has("--skip-wasm") || !existsSync(join(wasmDir, "dformer_bg.wasm"))) await buildWasm();
const wasm = readFileSync(join(wasmDir, 'dformer_bg.wasm'));
writeFileSync(
  join(wasmDir, 'dformer-wasm-inline.js'),
  `/* Generated by uxp-panel/build.mjs: the core's .wasm bytes (${wasm.length} bytes), base64. */\nself.DFORMER_WASM_BASE64 = "${wasm.toString('base64')}";\n`
);
// The host command names of messages (one table for the panel, the CLI and the Inkscape extension).
const commands = JSON.parse(readFileSync(join(repo, 'messages', 'commands.json'), 'utf8'));
writeFileSync(
  join(wasmDir, 'commands-table.js'),
  `/* Generated by uxp-panel/build.mjs from messages/commands.json. */\nself.DFORMER_COMMANDS = ${JSON.stringify(commands)};\n`
);
const { features, minChromium, functions } = scanWasmFeatures(wasm);
const cep = minimumCep(minChromium);
const featureList = Object.keys(features).join(', ') || 'none (WebAssembly MVP)';
console.log(`[panel] wasm ${(wasm.length / 1024).toFixed(0)} KB; post-MVP features: ${featureList}; needs Chromium ${minChromium}`);
for (const [name, list] of Object.entries(functions)) {
  console.log(`[panel]   ${name}: ${list.length} function(s), e.g. ${list.slice(0, 2).join(', ')}`);
}
if (!cep) throw new Error(`the compiled core needs Chromium ${minChromium}, newer than any CEP release`);
const sourceManifest = readFileSync(join(panel, 'CSXS', 'manifest.xml'), 'utf8');
const sourceMin = /<Host Name="ILST" Version="\[([\d.]+),/.exec(sourceManifest)[1];
const illustratorMin = cep.illustrator || sourceMin;
if (cep.illustrator) {
  console.log(`[panel] → CEP ${cep.cep} (Chromium ${cep.chromium}): Illustrator ${cep.illustrator} or later`);
} else {
  console.warn(
    `[panel] WARNING: the core needs CEP ${cep.cep} (Chromium ${cep.chromium}); Adobe's CEP ${cep.cep} table lists Illustrator as "TBD".\n` +
      `[panel]   The manifest requires CSXS ${cep.cep}.0, so older Illustrator releases refuse to load the panel instead of failing at run time.`
  );
}

// --- the CEP extension folder
const dist = join(repo, 'dist');
const ext = join(dist, 'com.dformer.panel');
const web = join(dist, 'd-former-web');
rmSync(ext, { recursive: true, force: true });
rmSync(web, { recursive: true, force: true });
const common = ['index.html', 'css', 'src', 'samples'];
for (const target of [ext, web]) {
  mkdirSync(join(target, 'wasm'), { recursive: true });
  for (const item of common) cpSync(join(panel, item), join(target, item), { recursive: true });
  for (const f of ['dformer.js', 'dformer-wasm-inline.js', 'commands-table.js']) cpSync(join(wasmDir, f), join(target, 'wasm', f));
}
const bridge = join(repo, 'illustrator-scripts', 'dformer-bridge.jsx');
if (!existsSync(bridge)) throw new Error(`missing ${bridge}: the panel cannot reach the document without it`);
mkdirSync(join(ext, 'jsx'), { recursive: true });
cpSync(bridge, join(ext, 'jsx', 'dformer-bridge.jsx'));
// The one project version: [workspace.package] version in Cargo.toml (also `dformer --version`'s).
const version = /\[workspace\.package\][^[]*?\nversion = "([^"]+)"/.exec(readFileSync(join(repo, 'Cargo.toml'), 'utf8'))?.[1];
if (!version) throw new Error('no [workspace.package] version in Cargo.toml');
const manifest = readFileSync(join(panel, 'CSXS', 'manifest.xml'), 'utf8')
  .replace(/(ExtensionBundleVersion=")[^"]*/, `$1${version}`)
  .replace(/(<Extension Id="[^"]+" Version=")[^"]*/, `$1${version}`)
  .replace(/(<Host Name="ILST" Version=")\[[\d.]+,/, `$1[${illustratorMin},`)
  .replace(/(<RequiredRuntime Name="CSXS" Version=")[\d.]+/, `$1${cep.cep}.0`);
mkdirSync(join(ext, 'CSXS'), { recursive: true });
writeFileSync(join(ext, 'CSXS', 'manifest.xml'), manifest);
writeFileSync(
  join(ext, 'BUILD.txt'),
  `D-former CEP extension\nwasm: ${wasm.length} bytes; post-MVP WebAssembly features: ${featureList}\n` +
    `minimum: CEP ${cep.cep} (Chromium ${cep.chromium}); Illustrator ${cep.illustrator || 'release not documented by Adobe'}\n`
);
const single = join(dist, 'd-former.html');
writeFileSync(single, singleHtml(web, version));
console.log(`[panel] extension folder: ${ext} (version ${version})\n[panel] browser app: ${join(web, 'index.html')}, and as one file ${single}`);
