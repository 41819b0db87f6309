// Which post-MVP WebAssembly features does a .wasm binary use, and so which Chromium (and CEP,
// and Illustrator) can instantiate it?
//
// Walks the binary format of the WebAssembly 1.0 spec (https://webassembly.github.io/spec/core/binary/):
// type, import, table, element, data, data-count and code sections, decoding every instruction's
// immediates so that each opcode is seen exactly once. Post-MVP features and the Chromium release
// that shipped them (chromestatus / V8 release notes):
//   mutable-globals 74, sign-ext 74, nontrapping-fptoint 75, bulk-memory 75, multi-value 85,
//   BigInt<->i64 at the JS boundary 85, SIMD 91, exceptions 95, reference-types 96, tail-call 112,
//   relaxed SIMD 114.
// CEP's Chromium (Adobe CEP cookbooks): CEP 8 = 57, CEP 9 = 61, CEP 10 = 74, CEP 11 = 88, CEP 12 = 99.

import { Reader, readSections } from './wasm-binary.mjs';

export const FEATURE_CHROMIUM = {
  'mutable-globals': 74,
  'sign-ext': 74,
  'nontrapping-fptoint': 75,
  'bulk-memory': 75,
  'multi-value': 85,
  simd: 91,
  'relaxed-simd': 114,
  exceptions: 95,
  'reference-types': 96,
  'tail-call': 112,
};

/** CEP release → Chromium major, and the first Illustrator release that ships it (CEP cookbooks). */
export const CEP_RELEASES = [
  { cep: 8, chromium: 57, illustrator: '22.0' },
  { cep: 9, chromium: 61, illustrator: '23.0' },
  { cep: 10, chromium: 74, illustrator: '25.0' },
  { cep: 11, chromium: 88, illustrator: '25.3' },
  // CEP 12 HTML Extension Cookbook, application table (FY2024 column): Illustrator 29.5.1 (CEP 12).
  { cep: 12, chromium: 99, illustrator: '29.5.1' },
];

/**
 * Scans `bytes` (a .wasm module) and returns `{ features: {name: count}, minChromium }`.
 * Throws on a malformed module rather than guessing.
 */
export function scanWasmFeatures(bytes) {
  const u8 = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  if (u8[0] !== 0 || u8[1] !== 0x61 || u8[2] !== 0x73 || u8[3] !== 0x6d) throw new Error('not a WebAssembly module');
  const features = {};
  const where = {};
  let importedFuncs = 0;
  let current = null;
  const use = (name) => {
    features[name] = (features[name] || 0) + 1;
    if (current !== null) (where[name] = where[name] || new Set()).add(current);
  };
  let names = null;
  for (const { id, offset, body } of readSections(u8)) {
    const s = new Reader(u8, offset, offset + body.length);
    if (id === 1) typeSection(s, use);
    else if (id === 2) importedFuncs = importSection(s, use);
    else if (id === 4) s.vec(() => tableType(s, use));
    else if (id === 6) s.vec(() => globalEntry(s, use));
    else if (id === 9) elementSection(s, use);
    else if (id === 10) {
      s.vec((i) => {
        current = importedFuncs + i;
        functionBody(s, use);
      });
      current = null;
    } else if (id === 0) names = nameSection(s) || names;
    else if (id === 11) dataSection(s, use);
    else if (id === 12) use('bulk-memory'); // data count section
  }
  let minChromium = 57;
  for (const name of Object.keys(features)) minChromium = Math.max(minChromium, FEATURE_CHROMIUM[name] || 0);
  const functions = {};
  for (const [name, set] of Object.entries(where)) {
    functions[name] = [...set].map((i) => (names && names.get(i)) || `func[${i}]`);
  }
  return { features, minChromium, functions };
}

/** Function names from the `name` custom section (subsection 1), if present. */
function nameSection(s) {
  if (s.name() !== 'name') return null;
  const names = new Map();
  while (s.p < s.end) {
    const sub = s.byte();
    const size = s.u32();
    const end = s.p + size;
    if (sub === 1) {
      s.vec(() => {
        const idx = s.u32();
        names.set(idx, s.name());
      });
    }
    s.p = end;
  }
  return names;
}

/** The oldest CEP release (and Illustrator) whose Chromium has every feature, or null. */
export function minimumCep(minChromium) {
  return CEP_RELEASES.find((c) => c.chromium >= minChromium) || null;
}

function valType(t, use) {
  if (t === 0x7b) use('simd');
  else if (t === 0x70 || t === 0x6f) use('reference-types');
}

function typeSection(s, use) {
  s.vec(() => {
    if (s.byte() !== 0x60) throw new Error('unsupported type form (GC proposal?)');
    s.vec(() => valType(s.byte(), use));
    const results = s.vec(() => valType(s.byte(), use));
    if (results > 1) use('multi-value');
  });
}

function limits(s) {
  const flags = s.byte();
  s.u32();
  if (flags & 1) s.u32();
}

function tableType(s, use) {
  const elem = s.byte();
  if (elem !== 0x70) use('reference-types');
  limits(s);
}

/** Walks the import section, recording features; returns the number of imported functions. */
export function importSection(s, use) {
  let funcs = 0;
  s.vec(() => {
    s.skip(s.u32());
    s.skip(s.u32());
    const kind = s.byte();
    if (kind === 0) {
      s.u32();
      funcs++;
    }
    else if (kind === 1) tableType(s, use);
    else if (kind === 2) limits(s);
    else if (kind === 3) {
      valType(s.byte(), use);
      if (s.byte() === 1) use('mutable-globals');
    } else if (kind === 4) {
      use('exceptions');
      s.byte();
      s.u32();
    } else throw new Error(`unknown import kind ${kind}`);
  });
  return funcs;
}

function constExpr(s, use) {
  for (;;) {
    const op = s.byte();
    if (op === 0x0b) return;
    instruction(op, s, use);
  }
}

function globalEntry(s, use) {
  valType(s.byte(), use);
  s.byte();
  constExpr(s, use);
}

function elementSection(s, use) {
  s.vec(() => {
    const flags = s.u32();
    if (flags !== 0) use(flags === 2 ? 'reference-types' : 'bulk-memory');
    if (flags & 2 && !(flags & 1)) s.u32(); // explicit table index
    if (!(flags & 1)) constExpr(s, use); // active: offset
    if (flags & 3) s.byte(); // elemkind / reftype
    if (flags & 4) s.vec(() => constExpr(s, use));
    else s.vec(() => s.u32());
  });
}

function dataSection(s, use) {
  s.vec(() => {
    const flags = s.u32();
    if (flags === 1) use('bulk-memory');
    if (flags === 2) {
      s.u32();
      use('multi-memory');
    }
    if (flags !== 1) constExpr(s, use);
    s.skip(s.u32());
  });
}

function functionBody(s, use) {
  const size = s.u32();
  const end = s.p + size;
  const body = new Reader(s.b, s.p, end);
  body.vec(() => {
    body.u32();
    valType(body.byte(), use);
  });
  while (body.p < end) {
    instruction(body.byte(), body, use);
  }
  s.p = end;
}

/** Decodes one instruction's immediates and records the feature it needs. */
export function instruction(op, s, use) {
  if (op === 0x02 || op === 0x03 || op === 0x04) {
    const bt = s.sleb();
    if (bt >= 0) use('multi-value'); // block type given by a type index
    else if (bt === -5) use('simd');
    else if (bt === -16 || bt === -17) use('reference-types');
  } else if (op === 0x0c || op === 0x0d) s.u32();
  else if (op === 0x0e) {
    s.vec(() => s.u32());
    s.u32();
  } else if (op === 0x10) s.u32();
  else if (op === 0x11) {
    s.u32();
    if (s.u32() !== 0) use('reference-types');
  } else if (op === 0x12 || op === 0x13) {
    use('tail-call');
    s.u32();
    if (op === 0x13) s.u32();
  } else if (op >= 0x06 && op <= 0x09) {
    use('exceptions');
    if (op === 0x06) s.sleb();
    else s.u32();
  } else if (op === 0x18 || op === 0x19) {
    use('exceptions');
    if (op === 0x18) s.u32();
  } else if (op === 0x1c) {
    use('reference-types');
    s.vec(() => s.byte());
  } else if (op >= 0x20 && op <= 0x24) s.u32();
  else if (op === 0x25 || op === 0x26) {
    use('reference-types');
    s.u32();
  } else if (op >= 0x28 && op <= 0x3e) {
    s.u32();
    s.u32();
  } else if (op === 0x3f || op === 0x40) s.byte();
  else if (op === 0x41 || op === 0x42) s.sleb();
  else if (op === 0x43) s.skip(4);
  else if (op === 0x44) s.skip(8);
  else if (op >= 0xc0 && op <= 0xc4) use('sign-ext');
  else if (op === 0xd0) {
    use('reference-types');
    s.byte();
  } else if (op === 0xd1) use('reference-types');
  else if (op === 0xd2) {
    use('reference-types');
    s.u32();
  } else if (op === 0xfc) {
    const sub = s.u32();
    if (sub <= 7) use('nontrapping-fptoint');
    else if (sub <= 11) {
      use('bulk-memory');
      if (sub === 8) {
        s.u32();
        s.byte();
      } else if (sub === 9) s.u32();
      else if (sub === 10) {
        s.byte();
        s.byte();
      } else s.byte();
    } else if (sub <= 17) {
      use(sub <= 14 ? 'bulk-memory' : 'reference-types');
      s.u32();
      if (sub === 12 || sub === 14) s.u32();
    } else throw new Error(`unknown 0xFC sub-opcode ${sub}`);
  } else if (op === 0xfd) {
    const sub = s.u32();
    use(sub >= 0x100 ? 'relaxed-simd' : 'simd');
    if (sub <= 11 || sub === 92 || sub === 93) {
      s.u32(); // memarg
      s.u32();
    } else if (sub === 12 || sub === 13) s.skip(16); // v128.const, i8x16.shuffle
    else if (sub >= 21 && sub <= 34) s.byte(); // extract/replace lane
    else if (sub >= 84 && sub <= 91) {
      s.u32();
      s.u32();
      s.byte(); // load/store lane: memarg + lane
    }
  } else if (op > 0xc4 && op !== 0xfc) throw new Error(`unknown opcode 0x${op.toString(16)}`);
  return undefined;
}

// CLI: node uxp-panel/tools/wasm-features.mjs file.wasm
if (import.meta.url === `file://${process.argv[1]}`) {
  const { readFileSync } = await import('node:fs');
  const { features, minChromium, functions } = scanWasmFeatures(readFileSync(process.argv[2]));
  const cep = minimumCep(minChromium);
  console.log(JSON.stringify({ features, minChromium, cep }, null, 2));
  if (process.argv.includes('--where')) {
    for (const [name, list] of Object.entries(functions)) console.log(`${name}:\n  ${list.slice(0, 12).join('\n  ')}${list.length > 12 ? `\n  … ${list.length - 12} more` : ''}`);
  }
}
