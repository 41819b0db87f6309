// Byte-level helpers to hand-assemble WebAssembly modules in the panel tests, written from the
// binary format spec (https://webassembly.github.io/spec/core/binary/) and independent of the
// reader in uxp-panel/tools/ that the tests check.

/** Unsigned LEB128 encoding of a u32 (spec §5.2.2). */
export const u32 = (n) => {
  const out = [];
  do {
    let b = n & 0x7f;
    n >>>= 7;
    if (n) b |= 0x80;
    out.push(b);
  } while (n);
  return out;
};
/** A name: length then bytes (spec §5.2.4); ASCII names only, where length in bytes = s.length. */
export const str = (s) => [...u32(s.length), ...Buffer.from(s)];
/** A section: id, byte size, contents (spec §5.5.2). */
export const section = (id, bytes) => [id, ...u32(bytes.length), ...bytes];
/** A vector: element count, then the elements' bytes (spec §5.1.3). */
export const vec = (items) => [...u32(items.length), ...items.flat()];
