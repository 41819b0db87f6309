// Laser-ready SVG from connect() results. Pure: no DOM, no host; used by the browser app's
// download and by the command-line demo (scripts/demo.mjs).
//
// Conventions most laser software reads: cut = red (#ff0000) hairline, score = blue (#0000ff),
// engrave = black (#000000); each on its own group (an Inkscape layer, an Illustrator layer on import).

export const DEFAULT_LAYERS = {
  cut: { name: 'cut', color: [255, 0, 0], width: 0.001 },
  score: { name: 'score', color: [0, 0, 255], width: 0.001 },
  engrave: { name: 'engrave', color: [0, 0, 0], width: 0.001 },
};

const hex = ([r, g, b]) => '#' + [r, g, b].map((v) => Math.max(0, Math.min(255, Math.round(v))).toString(16).padStart(2, '0')).join('');
const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
const num = (v) => Number(v.toFixed(4)).toString();

/** Control-point bounds of paths (they contain the curves). */
export function pathsBounds(paths) {
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const p of paths) {
    for (const pt of p.points) {
      for (const q of [pt.anchor, pt.left, pt.right]) {
        if (!q) continue;
        x0 = Math.min(x0, q[0]); y0 = Math.min(y0, q[1]);
        x1 = Math.max(x1, q[0]); y1 = Math.max(y1, q[1]);
      }
    }
  }
  return { min: [x0, y0], max: [x1, y1] };
}

/**
 * @param {object} o
 * @param {Array<{name:string, outline:object, holes:Array, labels:Array, marks:Array}>} o.pieces
 * @param {(path:object)=>string} o.pathToSvg  the core's path → SVG path data
 * @param {string} [o.units='mm']  document unit of the coordinates (mm, cm, in, pt, px)
 * @param {object} [o.layers]  colours/widths per layer (see DEFAULT_LAYERS)
 * @param {number} [o.fontSize]  label height in document units
 * @param {number} [o.margin]  margin around the drawing in document units
 */
export function laserSvg({ pieces, pathToSvg, units = 'mm', layers = DEFAULT_LAYERS, fontSize, margin }) {
  const L = { ...DEFAULT_LAYERS, ...layers };
  const all = pieces.flatMap((p) => [p.outline, ...(p.holes || []).map((h) => h.path), ...(p.marks || [])]);
  const b = pathsBounds(all);
  const size = Math.max(b.max[0] - b.min[0], b.max[1] - b.min[1]);
  const m = margin ?? size * 0.03;
  const fs = fontSize ?? Math.max(size / 80, 1e-6);
  const [x, y] = [b.min[0] - m, b.min[1] - m];
  const [w, h] = [b.max[0] - b.min[0] + 2 * m, b.max[1] - b.min[1] + 2 * m];
  const unitSuffix = ['mm', 'cm', 'in', 'pt', 'px', 'pc'].includes(units) ? units : '';
  const stroke = (l) => `fill="none" stroke="${hex(l.color)}" stroke-width="${num(l.width)}"`;
  const layer = (key, id, body) =>
    `  <g id="${id}" inkscape:groupmode="layer" inkscape:label="${esc(L[key].name)}">\n${body}  </g>\n`;

  let cut = '', score = '', engrave = '';
  pieces.forEach((p, i) => {
    const id = `piece-${i + 1}`;
    cut += `    <g id="${id}-cut" data-piece="${esc(p.name)}" ${stroke(L.cut)}>\n`;
    cut += `      <path class="outline" d="${pathToSvg(p.outline)}"/>\n`;
    for (const [k, hole] of (p.holes || []).entries()) cut += `      <path class="hole" data-index="${k}" d="${pathToSvg(hole.path)}"/>\n`;
    cut += '    </g>\n';
    score += `    <g id="${id}-score" ${stroke(L.score)}>\n`;
    for (const mark of p.marks || []) score += `      <path class="mark" d="${pathToSvg(mark)}"/>\n`;
    score += '    </g>\n';
    engrave += `    <g id="${id}-engrave" fill="${hex(L.engrave.color)}" font-family="sans-serif" font-size="${num(fs)}" text-anchor="middle" dominant-baseline="central">\n`;
    const ob = pathsBounds([p.outline]);
    engrave += `      <text class="name" x="${num((ob.min[0] + ob.max[0]) / 2)}" y="${num(ob.min[1] - fs)}">${esc(p.name)}</text>\n`;
    for (const lab of p.labels || []) {
      engrave += `      <text class="label" x="${num(lab.at[0])}" y="${num(lab.at[1])}" transform="rotate(${num(lab.angle)} ${num(lab.at[0])} ${num(lab.at[1])})">${esc(lab.text)}</text>\n`;
    }
    engrave += '    </g>\n';
  });
  return (
    `<?xml version="1.0" encoding="UTF-8"?>\n` +
    `<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" ` +
    `width="${num(w)}${unitSuffix}" height="${num(h)}${unitSuffix}" viewBox="${num(x)} ${num(y)} ${num(w)} ${num(h)}">\n` +
    `  <title>D-former pieces</title>\n` +
    layer('cut', 'layer-cut', cut) +
    layer('score', 'layer-score', score) +
    layer('engrave', 'layer-engrave', engrave) +
    `</svg>\n`
  );
}
