// Runs the real ExtendScript files of illustrator-scripts/ in Node's `vm`, against the simulated
// Illustrator DOM of ./sim. `createHost(...).evalScript(src)` behaves like CEP's
// CSInterface.evalScript: it returns the script's value as a string, "EvalScript error." if it throws.
// Documented for other helpers in illustrator-scripts/BRIDGE.md.
import fs from 'node:fs';
import path from 'node:path';
import vm from 'node:vm';
import { fileURLToPath } from 'node:url';
import * as E from './sim/enums.mjs';
import { Application, Artboard, CompoundPathItem, GroupItem, NoColor, OtherItem, PathItem, RGBColor, Sim, TextFrame, ellipsePoints, roundedRectPoints } from './sim/dom.mjs';
import { makeWindowClass } from './sim/scriptui.mjs';

export const SCRIPTS_DIR = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../illustrator-scripts');
export const BRIDGE = path.join(SCRIPTS_DIR, 'dformer-bridge.jsx');

function corner(a) { return { anchor: a, left: a, right: a }; }

/** Add one described shape to the simulated document; returns the created item. */
function addShape(sim, doc, s) {
  let layer = doc._layers.find((l) => l.name === (s.layer || 'Layer 1'));
  if (!layer) { layer = doc.layers.add(); layer.name = s.layer; }
  let container = layer;
  if (s.group) {
    container = layer._items.find((g) => g instanceof GroupItem && g.name === s.group);
    if (!container) {
      container = new GroupItem(sim);
      container.name = s.group;
      container._parent = layer;
      layer._items.unshift(container);
    }
  }
  let item;
  if (s.kind && s.kind !== 'path' && s.kind !== 'compound') {
    item = s.kind === 'text' ? new TextFrame(sim) : new OtherItem(sim, s.kind);
    if (s.kind === 'text') item.contents = s.text || 'text';
  } else {
    const p = new PathItem(sim);
    let pts, closed = true;
    if (s.path) {
      pts = s.path.points.map((q) => ({ anchor: q.anchor, left: q.left || q.anchor, right: q.right || q.anchor, type: q.type && E.PointType[q.type] }));
      closed = s.path.closed !== false;
    }
    else if (s.roundedRect) { const r = s.roundedRect; pts = roundedRectPoints(r.top, r.left, r.width, r.height, r.radius); p._live = { radius: r.radius }; }
    else if (s.ellipse) pts = ellipsePoints(s.ellipse.top, s.ellipse.left, s.ellipse.width, s.ellipse.height, !!s.ellipse.reversed);
    else if (s.rect) { const { top: t, left: l, width: w, height: h } = s.rect; pts = [[l, t], [l, t - h], [l + w, t - h], [l + w, t]].map(corner); }
    else if (s.polygon) { pts = s.polygon.map(corner); closed = s.closed !== false; }
    else throw new Error(`shape ${s.name}: give path, ellipse, rect or polygon`);
    p._setPoints(pts);
    p.closed = closed;
    if (s.strokeWidth !== undefined) p.strokeWidth = s.strokeWidth;
    p.clipping = !!s.clipping;
    p.guides = !!s.guides;
    if (s.kind === 'compound') {
      item = new CompoundPathItem(sim);
      p.name = s.subName || '';
      p._parent = item;
      item._items.push(p);
      for (const extra of s.more || []) {
        const q = new PathItem(sim);
        q._setPoints(extra.map(corner));
        q.closed = true;
        q._parent = item;
        item._items.push(q);
      }
    } else item = p;
  }
  item.name = s.name || '';
  if (s.kind === 'compound') item._items[0].name = s.subName || '';
  item._parent = container;
  container._items.unshift(item);
  // Selection tool semantics: selecting a grouped shape selects its group; `directSelect` selects
  // the shape itself inside its group (Direct Selection tool).
  if (s.selected !== false) (container instanceof GroupItem && !s.directSelect ? container : item).selected = true;
  if (s.selectedAnchors) {
    for (let i = 0; i < item._points.length; i++) {
      item._points[i]._sel = s.selectedAnchors.includes(i) ? E.PathPointSelection.ANCHORPOINT : E.PathPointSelection.NOSELECTION;
    }
  }
  if (s.locked) item.locked = true;
  if (s.hidden) item.hidden = true;
  return item;
}

/**
 * @param {object} o
 * @param {string} [o.units='mm'] ruler units: mm cm in pt px pc q m ft yd unknown
 * @param {boolean} [o.uuid=true] false = Illustrator 22–23 (no PageItem.uuid / getPageItemFromUuid)
 * @param {boolean} [o.noDocument] no open document
 * @param {boolean} [o.float32] store coordinates as 32-bit floats like Illustrator's AIReal
 * @param {object[]} [o.shapes] {name, path|ellipse|rect|polygon, layer, group, selected, directSelect, selectedAnchors, kind, locked, hidden}
 * @param {(win) => 1|2} [o.dialog] responder for ScriptUI dialogs of standalone scripts
 * @param {string[]} [o.scripts] extra .jsx files (names in illustrator-scripts/) to load after the bridge
 * @param {'RGB'|'CMYK'} [o.colorSpace='RGB'] Document.documentColorSpace (File > Document Color Mode)
 * @param {number[][]} [o.artboards] artboard rects [left, top, right, bottom] in document coordinates
 * @param {number} [o.activeArtboard=0] index of the active artboard
 * @param {'document'|'artboard'} [o.coordinateSystem='document'] app.coordinateSystem when the scripts start
 * @param {number|null} [o.scaleFactor=1] Document.scaleFactor (10: Large Canvas; null: no such property)
 * @param {object} [o.style] the current style new art is drawn with (strokeDashes, opacity, blendingMode: 'MULTIPLY', brush…)
 * @param {'works'|'throws'|'ignored'} [o.labelAnchor='works'] what assigning TextFrame.anchor does
 * @param {'throws'|'works'} [o.compoundUuid='throws'] getPageItemFromUuid on the sub-path of a compound path
 * @param {boolean} [o.preferencesLocked] app.preferences setters have no effect
 * @param {'utf8'|'legacy'} [o.transport='utf8'] 'legacy': non-ASCII text crossing evalScript is mangled
 *   (script bytes read as Latin-1, answer characters above U+007F sent as Latin-1 bytes and read as UTF-8)
 */
export function createHost(o = {}) {
  const style = o.style ? { ...o.style } : null;
  for (const [k, enumeration] of [['blendingMode', E.BlendModes], ['strokeCap', E.StrokeCap], ['strokeJoin', E.StrokeJoin]]) {
    if (style && typeof style[k] === 'string') style[k] = enumeration[style[k]];
  }
  const sim = new Sim({ uuid: o.uuid !== false, units: o.noDocument ? null : (o.units || 'mm'), float32: !!o.float32,
    name: o.document || 'Untitled-1.ai', colorSpace: o.colorSpace || 'RGB', scaleFactor: o.scaleFactor === undefined ? 1 : o.scaleFactor,
    style, labelAnchor: o.labelAnchor, compoundUuid: o.compoundUuid, preferencesLocked: !!o.preferencesLocked });
  const doc = sim.documents[0] || null;
  if (doc && o.artboards) {
    doc._artboards = o.artboards.map((r, i) => Object.assign(new Artboard(sim, r, `Artboard ${i + 1}`), { _parent: doc }));
  }
  if (doc && o.activeArtboard !== undefined) doc.artboards.setActiveArtboardIndex(o.activeArtboard);
  if (o.coordinateSystem === 'artboard') sim.coordinateSystem = E.CoordinateSystem.ARTBOARDCOORDINATESYSTEM;
  for (const s of o.shapes || []) addShape(sim, doc, s);
  // The first created shape ends up at the bottom; fine for tests (they address shapes by name).
  const alerts = [];
  const dialogs = [];
  const app = new Application(sim);
  const host = { sim, app, doc, alerts, dialogs, respond: o.dialog || null, evalFiles: [] };
  const globals = {
    app, RGBColor, NoColor,
    PointType: E.PointType, PathPointSelection: E.PathPointSelection, Transformation: E.Transformation,
    RulerUnits: E.RulerUnits, Justification: E.Justification,
    CoordinateSystem: E.CoordinateSystem, DocumentColorSpace: E.DocumentColorSpace,
    StrokeCap: E.StrokeCap, StrokeJoin: E.StrokeJoin, BlendModes: E.BlendModes,
    alert: (m) => { alerts.push(String(m)); },
    // $.evalFile(path): ExtendScript runs the file in the same engine (CEP 12 Cookbook, "Load Multiple JSX files").
    $: { writeln: () => {}, evalFile: (file) => { host.evalFiles.push(String(file)); host.load(String(file)); } },
    Window: makeWindowClass((w) => (host.respond ? host.respond(w) : 2), dialogs),
  };
  const context = vm.createContext(globals);
  host.context = context;
  host.load = (file) => {
    const full = path.isAbsolute(file) ? file : path.join(SCRIPTS_DIR, file);
    vm.runInContext(fs.readFileSync(full, 'utf8'), context, { filename: full });
  };
  host.load(BRIDGE);
  for (const f of o.scripts || []) host.load(f);
  const legacy = o.transport === 'legacy';
  /** CSInterface.evalScript stand-in: the value as a string, "EvalScript error." on a throw. */
  host.evalScript = (src) => {
    try {
      const script = legacy ? Buffer.from(String(src), 'utf8').toString('latin1') : String(src);
      const r = vm.runInContext(script, context);
      const text = r === undefined ? '' : String(r);
      return legacy ? new TextDecoder('utf-8').decode(Buffer.from(text.replace(/[^\u0000-\u00ff]/g, '?'), 'latin1')) : text;
    } catch {
      return 'EvalScript error.';
    }
  };
  /** The ExtendScript engine forgets the bridge (CEP-Resources issue 39: ScriptPath is loaded only at panel start-up). */
  host.loseBridge = () => {
    // Function declarations are not deletable globals: overwrite them (calling one then throws, as an unknown name does).
    for (const k of Object.keys(context)) if (/^(dformer_|DFORMER_)/.test(k)) context[k] = undefined;
  };
  /** Run a standalone File > Scripts script; `respond` answers its dialog. Returns the new alerts. */
  host.runScript = (file, respond) => {
    if (respond !== undefined) host.respond = respond;
    const before = alerts.length;
    host.load(file);
    return alerts.slice(before);
  };
  host.find = (name) => {
    const hit = doc._all().find((x) => x.name === name);
    if (!hit) throw new Error(`no item named ${name}`);
    return hit;
  };
  host.snapshot = () => snapshot(sim);
  return host;
}

function color(c) {
  if (!c) return null;
  return c.typename === 'RGBColor' ? { rgb: [c.red, c.green, c.blue] } : { type: c.typename };
}

function item(it) {
  const base = { typename: it.typename, name: it.name, uuid: it._uuid, locked: it.locked, hidden: it.hidden };
  if (it instanceof PathItem) {
    return {
      ...base, closed: it.closed, filled: it.filled, stroked: it.stroked, strokeWidth: it.strokeWidth,
      style: Object.fromEntries(Object.keys(it).filter((k) => /^(stroke(Dashes|DashOffset|Cap|Join|MiterLimit|Overprint)|fillOverprint|opacity|blendingMode|brush)$/.test(k))
        .map((k) => [k, Array.isArray(it[k]) ? [...it[k]] : it[k] === null || typeof it[k] !== 'object' ? it[k] : String(it[k])])),
      strokeColor: color(it.strokeColor), fillColor: color(it.fillColor), clipping: it.clipping, guides: it.guides,
      points: it._points.map((p) => ({ a: p._a, l: p._l, r: p._r, type: String(p._type), sel: String(p._sel) })),
    };
  }
  if (it instanceof TextFrame) {
    const ca = it.textRange.characterAttributes;
    return { ...base, contents: it.contents, anchor: it._anchor, rotation: it.rotation, size: ca.size, fill: color(ca.fillColor),
      opacity: it.opacity, blendingMode: String(it.blendingMode),
      justification: String(it.textRange.paragraphAttributes.justification) };
  }
  if (it._items) return { ...base, clipped: it.clipped, items: it._items.map(item) };
  return base;
}

function layer(l) {
  return { name: l.name, locked: l.locked, visible: l.visible, color: color(l.color), items: l._items.map(item), layers: l._layers.map(layer) };
}

/** Plain JSON of every document: for deep comparison before/after a script. */
export function snapshot(sim) {
  return sim.documents.map((d) => ({ name: d.name, rulerUnits: String(d.rulerUnits), active: d._active && d._active.name, layers: d._layers.map(layer) }));
}
