// Reading the WebAssembly binary format (https://webassembly.github.io/spec/core/binary/), shared by
// the build (build.mjs), the feature scan (wasm-features.mjs) and the MVP lowering (wasm-lower-mvp.mjs).

/** A cursor over bytes[pos, end): LEB128 integers (spec §5.2.2), names (§5.2.4), vectors (§5.1.3). */
export class Reader {
  constructor(bytes, pos = 0, end = bytes.length) {
    this.b = bytes;
    this.p = pos;
    this.end = end;
  }
  byte() {
    if (this.p >= this.end) throw new Error(`unexpected end of section at byte ${this.p}`);
    return this.b[this.p++];
  }
  u32() {
    let result = 0;
    let shift = 0;
    for (;;) {
      const byte = this.byte();
      result += (byte & 0x7f) * 2 ** shift;
      shift += 7;
      if (!(byte & 0x80)) return result;
    }
  }
  /** Signed LEB128 of any width; only its extent matters except for block types. */
  sleb() {
    let result = 0;
    let shift = 0;
    let byte;
    do {
      byte = this.byte();
      result += (byte & 0x7f) * 2 ** shift;
      shift += 7;
    } while (byte & 0x80);
    if (shift < 53 && byte & 0x40) result -= 2 ** shift;
    return result;
  }
  /** A name: u32 byte length, then UTF-8. */
  name() {
    const n = this.u32();
    const text = Buffer.from(this.b.subarray(this.p, this.p + n)).toString();
    this.p += n;
    return text;
  }
  skip(n) {
    this.p += n;
  }
  vec(f) {
    const n = this.u32();
    for (let i = 0; i < n; i++) f(i);
    return n;
  }
}

/** The module's sections after the 8-byte preamble (§5.5.2), in order: `{ id, offset, body, raw }`,
 * where `body` is the contents (starting at byte `offset` of the module) and `raw` the whole section
 * (id and size included), both views of `bytes`. */
export function readSections(bytes) {
  const r = new Reader(bytes, 8);
  const sections = [];
  while (r.p < bytes.length) {
    const start = r.p;
    const id = r.byte();
    const size = r.u32();
    const offset = r.p;
    const body = bytes.subarray(offset, offset + size);
    r.p += size;
    sections.push({ id, offset, body, raw: bytes.subarray(start, r.p) });
  }
  return sections;
}
