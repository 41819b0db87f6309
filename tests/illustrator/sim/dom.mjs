// A small simulated Illustrator DOM, written from the Illustrator JavaScript Scripting Reference
// (docsforadobe/illustrator-scripting-guide: Document, Layer(s), GroupItem(s), PathItem(s), PathPoint(s),
// TextFrameItems, RGBColor, PageItem.resize). Only what the D-former scripts touch, but with the
// documented semantics, so a script that works here uses the DOM the way Illustrator does:
// - scripting coordinates are points, y up; geometricBounds = [left, top, right, bottom] (top > bottom);
// - collections are live, index 0 is the top of the stacking order, `add()` puts the new item on top
//   of that container (document-level collections add to the active layer);
// - PathPoint.anchor / leftDirection / rightDirection return copies; assigning sets the point;
// - setEntirePath([[x,y],…]) replaces all points by corner points (handles at the anchors);
// - PathItem.length is the true Bézier arc length (dense Gauss–Legendre quadrature, see bezier.mjs);
// - resize(sx%, sy%, …, changeLineWidths%, scaleAbout) scales about a point of the geometric bounds;
// - locked or hidden items and locked or hidden layers cannot be modified ("Target layer cannot be modified");
// - getByName and out-of-range indices throw "No such element"; so does getPageItemFromUuid on a miss;
// - app.coordinateSystem (Application.coordinateSystem: "the coordinate system currently in use, document
//   or artboard"; scripting-constants CoordinateSystem) is one global setting of the application, not of a
//   document. With DOCUMENTCOORDINATESYSTEM (the default) coordinates are document coordinates (how the
//   simulator stores them). With ARTBOARDCOORDINATESYSTEM every coordinate a script reads or writes
//   (PathPoint anchor/leftDirection/rightDirection, setEntirePath, ellipse/rectangle top-left,
//   geometricBounds, position, left, top, TextFrame.anchor, Artboard.artboardRect, the DOCUMENTORIGIN
//   pivot of resize) is relative to the top-left corner of the ACTIVE artboard (the guide's "Page-item
//   positioning": the artboard's coordinate origin is its top-left corner; Artboard.rulerOrigin is taken
//   as its default [0,0]). Simulator choice: the y axis stays up in both systems (geometricBounds top >
//   bottom), as scripts observe; only the origin moves. Lengths and other relative values do not change;
//   - Document.documentColorSpace is read-only (RGB unless the host says CMYK); colours are stored as
//   assigned (Illustrator's translation of RGB colours in a CMYK document is not simulated).
import { cubicBounds, cubicLength, segmentsOf } from './bezier.mjs';
import { CoordinateSystem, DocumentColorSpace, PathPointSelection, PointType, RulerUnits, Transformation, Justification, UNIT_MEMBERS } from './enums.mjs';

const NO_SUCH = () => new Error('No such element');
const LOCKED = () => new Error('Target layer cannot be modified');

/** A live collection: a Proxy that reads `list()` on every access. */
function collection(typename, list, methods = {}) {
  const base = { typename, ...methods };
  base.getByName = (name) => {
    const hit = list().find((x) => x.name === name);
    if (!hit) throw NO_SUCH();
    return hit;
  };
  base.index = (key) => (typeof key === 'number' ? at(key) : base.getByName(key));
  function at(i) {
    const l = list();
    if (i < 0 || i >= l.length) throw NO_SUCH();
    return l[i];
  }
  return new Proxy(base, {
    get(t, p) {
      if (p === 'length') return list().length;
      if (typeof p === 'string' && /^\d+$/.test(p)) return at(Number(p));
      return t[p];
    },
    set() { throw new Error(`${typename} is read-only`); },
  });
}

export class RGBColor {
  constructor() { this.red = 0; this.green = 0; this.blue = 0; }
  get typename() { return 'RGBColor'; }
}
export class NoColor { get typename() { return 'NoColor'; } }

function isPair(v) {
  return v != null && typeof v.length === 'number' && v.length === 2 &&
    typeof v[0] === 'number' && typeof v[1] === 'number';
}

export class Sim {
  constructor({ uuid = true, units = 'mm', float32 = false, name = 'Untitled-1.ai', colorSpace = 'RGB' } = {}) {
    this.hasUuid = uuid;
    this.float32 = float32;
    this.nextUuid = 1;
    this.faults = {};              // name → remaining count before a thrown fault (tests)
    this.calls = {};
    this.documents = [];
    this.coordinateSystem = CoordinateSystem.DOCUMENTCOORDINATESYSTEM;
    this.coordinateUses = {};      // "CoordinateSystem.X" → how many coordinates were read or written in it (tests)
    if (units !== null) this.documents.push(new Document(this, name, units, colorSpace));
  }
  /** Where the current coordinate system's [0,0] is, in document coordinates. */
  origin(doc) {
    const k = String(this.coordinateSystem);
    this.coordinateUses[k] = (this.coordinateUses[k] || 0) + 1;
    if (this.coordinateSystem !== CoordinateSystem.ARTBOARDCOORDINATESYSTEM || !doc) return [0, 0];
    const r = doc._artboards[doc._activeArtboard].rect;
    return [r[0], r[1]];
  }
  /** A stored (document) point as the script sees it in the current coordinate system. */
  out(doc, p) {
    const o = this.origin(doc);
    return o[0] === 0 && o[1] === 0 ? p.slice() : [this.num(p[0] - o[0]), this.num(p[1] - o[1])];
  }
  /** A point the script wrote, in the current coordinate system, as stored document coordinates. */
  in(doc, v, what) {
    const q = this.pair(v, what), o = this.origin(doc);
    return o[0] === 0 && o[1] === 0 ? q : [this.num(q[0] + o[0]), this.num(q[1] + o[1])];
  }
  /** Count a DOM call and throw if a fault was injected for it. */
  hit(what) {
    this.calls[what] = (this.calls[what] || 0) + 1;
    if (this.faults[what] !== undefined) {
      this.faults[what] -= 1;
      if (this.faults[what] <= 0) { delete this.faults[what]; throw new Error(`simulated failure in ${what}`); }
    }
  }
  num(v) { return this.float32 ? Math.fround(v) : v; }
  pair(v, what) {
    if (!isPair(v)) throw new Error(`${what}: expected an array of 2 numbers`);
    return [this.num(v[0]), this.num(v[1])];
  }
}

class Node {
  constructor(sim, typename) { this.sim = sim; this._typename = typename; this._parent = null; }
  get typename() { return this._typename; }
  get parent() { return this._parent; }
  get document() { let n = this; while (n && !(n instanceof Document)) n = n._parent; return n; }
}

/** Container behaviour shared by Layer, GroupItem, Document (via its active layer). */
function containerCollections(owner, itemsHost) {
  const of = (T) => () => itemsHost()._items.filter((x) => x instanceof T);
  const addTo = (make, what) => () => {
    const host = itemsHost();
    owner.sim.hit(what);
    host.assertWritable();
    const item = make();
    item._parent = host;
    host._items.unshift(item);
    return item;
  };
  return {
    pageItems: () => collection('PageItems', () => itemsHost()._items.slice()),
    pathItems: () => collection('PathItems', of(PathItem), {
      add: addTo(() => new PathItem(owner.sim), 'pathItems.add'),
      ellipse: (top = 100, left = 100, width = 50, height = 100, reversed = false) => {
        const p = addTo(() => new PathItem(owner.sim), 'pathItems.ellipse')();
        [left, top] = owner.sim.in(owner.document, [left, top], 'ellipse');
        p._setPoints(ellipsePoints(top, left, width, height, reversed));
        p.closed = true;
        return p;
      },
      rectangle: (top, left, width, height, reversed = false) => {
        const p = addTo(() => new PathItem(owner.sim), 'pathItems.rectangle')();
        [left, top] = owner.sim.in(owner.document, [left, top], 'rectangle');
        const pts = [[left, top], [left, top - height], [left + width, top - height], [left + width, top]];
        if (reversed) pts.reverse();
        p._setPoints(pts.map((a) => ({ anchor: a, left: a, right: a })));
        p.closed = true;
        return p;
      },
    }),
    groupItems: () => collection('GroupItems', of(GroupItem), { add: addTo(() => new GroupItem(owner.sim), 'groupItems.add') }),
    textFrames: () => collection('TextFrameItems', of(TextFrame), { add: addTo(() => new TextFrame(owner.sim), 'textFrames.add') }),
    compoundPathItems: () => collection('CompoundPathItems', of(CompoundPathItem), {
      add: addTo(() => new CompoundPathItem(owner.sim), 'compoundPathItems.add'),
    }),
  };
}

/**
 * Ellipse from 4 anchors with the standard kappa = 4(√2−1)/3 handles. Point order (simulator choice,
 * not documented by Adobe): start at the leftmost point, counter-clockwise in y-up coordinates
 * (left, bottom, right, top); `reversed` walks the other way.
 */
export function ellipsePoints(top, left, width, height, reversed) {
  const k = (4 * (Math.SQRT2 - 1)) / 3;
  const rx = width / 2, ry = height / 2, cx = left + rx, cy = top - ry;
  let pts = [
    { anchor: [cx - rx, cy], left: [cx - rx, cy + k * ry], right: [cx - rx, cy - k * ry] },
    { anchor: [cx, cy - ry], left: [cx - k * rx, cy - ry], right: [cx + k * rx, cy - ry] },
    { anchor: [cx + rx, cy], left: [cx + rx, cy - k * ry], right: [cx + rx, cy + k * ry] },
    { anchor: [cx, cy + ry], left: [cx + k * rx, cy + ry], right: [cx - k * rx, cy + ry] },
  ];
  if (reversed) pts = pts.reverse().map((p) => ({ anchor: p.anchor, left: p.right, right: p.left }));
  return pts;
}

export class Artboard extends Node {
  constructor(sim, rect, name) { super(sim, 'Artboard'); this.rect = rect.slice(); this.name = name; }
  /** [left, top, right, bottom] in the current coordinate system. */
  get artboardRect() {
    const a = this.sim.out(this._parent, [this.rect[0], this.rect[1]]), b = this.sim.out(this._parent, [this.rect[2], this.rect[3]]);
    return [a[0], a[1], b[0], b[1]];
  }
  set artboardRect(v) {
    if (!v || v.length !== 4) throw new Error('artboardRect: expected [left, top, right, bottom]');
    const a = this.sim.in(this._parent, [v[0], v[1]], 'artboardRect'), b = this.sim.in(this._parent, [v[2], v[3]], 'artboardRect');
    this.rect = [a[0], a[1], b[0], b[1]];
  }
}

export class Document extends Node {
  constructor(sim, name, units, colorSpace = 'RGB') {
    super(sim, 'Document');
    this.name = name;
    if (!DocumentColorSpace[colorSpace]) throw new Error(`unknown colour space ${colorSpace}`);
    this._colorSpace = DocumentColorSpace[colorSpace];
    // One US Letter artboard whose top-left corner is the document origin (until the host sets others).
    this._artboards = [new Artboard(sim, [0, 0, 612, -792], 'Artboard 1')];
    this._artboards[0]._parent = this;
    this._activeArtboard = 0;
    const member = UNIT_MEMBERS[units] || units;
    if (!RulerUnits[member]) throw new Error(`unknown ruler units ${units}`);
    this._rulerUnits = RulerUnits[member];
    this._layers = [];
    const l = new Layer(sim, 'Layer 1');
    l._parent = this;
    this._layers.push(l);
    this._active = l;
    if (sim.hasUuid) this.getPageItemFromUuid = (u) => {
      const hit = this._all().find((x) => x._uuid === String(u));
      if (!hit) throw NO_SUCH();
      return hit;
    };
    const c = containerCollections(this, () => this._active);
    this._c = c;
  }
  get rulerUnits() { return this._rulerUnits; }
  get documentColorSpace() { return this._colorSpace; }
  get artboards() {
    return collection('Artboards', () => this._artboards.slice(), {
      getActiveArtboardIndex: () => this._activeArtboard,
      setActiveArtboardIndex: (i) => {
        if (!(i >= 0 && i < this._artboards.length)) throw NO_SUCH();
        this._activeArtboard = i;
      },
    });
  }
  get layers() {
    return collection('Layers', () => this._layers.slice(), {
      add: () => {
        this.sim.hit('layers.add');
        const l = new Layer(this.sim, `Layer ${this._layers.length + 1}`);
        l._parent = this;
        this._layers.unshift(l);
        this._active = l;
        return l;
      },
    });
  }
  get activeLayer() { return this._active; }
  set activeLayer(l) { this._active = l; }
  /** Every page item at any depth (document-level collections are recursive in Illustrator). */
  _all() {
    const out = [];
    const walk = (c) => {
      for (const it of c._items) { out.push(it); if (it._items) walk(it); }
      for (const l of c._layers || []) walk(l);
    };
    for (const l of this._layers) walk(l);
    return out;
  }
  get pageItems() { return collection('PageItems', () => this._all()); }
  get pathItems() {
    const c = this._c.pathItems();
    return collection('PathItems', () => this._all().filter((x) => x instanceof PathItem),
      { add: c.add, ellipse: c.ellipse, rectangle: c.rectangle });
  }
  get groupItems() {
    return collection('GroupItems', () => this._all().filter((x) => x instanceof GroupItem), { add: this._c.groupItems().add });
  }
  get textFrames() {
    return collection('TextFrameItems', () => this._all().filter((x) => x instanceof TextFrame), { add: this._c.textFrames().add });
  }
  get compoundPathItems() {
    return collection('CompoundPathItems', () => this._all().filter((x) => x instanceof CompoundPathItem));
  }
  /** Selected items in stacking order; a selected group is listed, not its children. */
  get selection() {
    const out = [];
    const walk = (c) => {
      for (const l of c._layers || []) walk(l);
      for (const it of c._items) {
        if (it.selected) out.push(it);
        else if (it._items && !(it instanceof CompoundPathItem)) walk(it);
      }
    };
    for (const l of this._layers) walk(l);
    return out;
  }
  set selection(v) {
    for (const it of this._all()) it.selected = false;
    if (v) for (let i = 0; i < v.length; i++) v[i].selected = true;
  }
}

export class Layer extends Node {
  constructor(sim, name) {
    super(sim, 'Layer');
    this.name = name;
    this.locked = false;
    this.visible = true;
    this.printable = true;
    this.color = Object.assign(new RGBColor(), { red: 79, green: 128, blue: 255 });
    this._items = [];
    this._layers = [];
    const c = containerCollections(this, () => this);
    Object.defineProperties(this, {
      pageItems: { get: c.pageItems }, pathItems: { get: c.pathItems }, groupItems: { get: c.groupItems },
      textFrames: { get: c.textFrames }, compoundPathItems: { get: c.compoundPathItems },
    });
  }
  get layers() {
    return collection('Layers', () => this._layers.slice(), {
      add: () => { const l = new Layer(this.sim, `Layer ${this._layers.length + 1}`); l._parent = this; this._layers.unshift(l); return l; },
    });
  }
  get hasSelectedArtwork() { return this.document.selection.some((x) => x.layer === this); }
  assertWritable() {
    for (let n = this; n instanceof Layer; n = n._parent) if (n.locked || !n.visible) throw LOCKED();
  }
  remove() {
    this.sim.hit('layer.remove');
    this.assertWritable();
    const p = this._parent, list = p._layers;
    list.splice(list.indexOf(this), 1);
    const doc = this.document || p;
    if (doc._active === this) doc._active = doc._layers[0];
    this._parent = null;
  }
}

class PageItem extends Node {
  constructor(sim, typename) {
    super(sim, typename);
    this.name = '';
    this.locked = false;
    this.hidden = false;
    this.note = '';
    this._selected = false;
    if (sim.hasUuid) this._uuid = String(sim.nextUuid++);
  }
  get uuid() { return this._uuid; }
  get layer() { let n = this._parent; while (n && !(n instanceof Layer)) n = n._parent; return n; }
  get selected() { return this._selected; }
  set selected(v) { this._selected = !!v; }
  get editable() { return !this.locked && !this.hidden; }
  assertWritable() {
    for (let n = this; n instanceof PageItem; n = n._parent) if (n.locked || n.hidden) throw LOCKED();
    const l = this.layer;
    if (l) l.assertWritable();
  }
  /** _bounds() ([minX, minY, maxX, maxY], document coordinates) as [left, top, right, bottom] in the current system. */
  get geometricBounds() {
    const b = this._bounds(), tl = this.sim.out(this.document, [b[0], b[3]]), br = this.sim.out(this.document, [b[2], b[1]]);
    return [tl[0], tl[1], br[0], br[1]];
  }
  get width() { const b = this._bounds(); return b[2] - b[0]; }
  get height() { const b = this._bounds(); return b[3] - b[1]; }
  get left() { return this.geometricBounds[0]; }
  get top() { return this.geometricBounds[1]; }
  get position() { const b = this.geometricBounds; return [b[0], b[1]]; }
  remove() {
    this.sim.hit(`${this._typename}.remove`);
    if (!this._parent) throw new Error('object has been removed');
    this.assertWritable();
    const list = this._parent._items;
    list.splice(list.indexOf(this), 1);
    this._parent = null;
  }
  /** Map every coordinate through f (used by translate/resize). */
  _transform() { throw new Error('not transformable'); }
  translate(dx = 0, dy = 0) {
    this.assertWritable();
    this._transform((p) => [p[0] + dx, p[1] + dy]);
  }
  resize(scaleX, scaleY, changePositions = true, changeFillPatterns = true, changeFillGradients = true,
    changeStrokePattern = true, changeLineWidths = 100, scaleAbout = Transformation.CENTER) {
    this.sim.hit('resize');
    this.assertWritable();
    if (!Number.isFinite(scaleX) || !Number.isFinite(scaleY)) throw new Error('resize: scale must be a number');
    const [minX, minY, maxX, maxY] = this._bounds();
    const [l, t, r, b] = [minX, maxY, maxX, minY];
    const ref = {
      [Transformation.DOCUMENTORIGIN]: this.sim.origin(this.document), [Transformation.TOPLEFT]: [l, t], [Transformation.LEFT]: [l, (t + b) / 2],
      [Transformation.BOTTOMLEFT]: [l, b], [Transformation.TOP]: [(l + r) / 2, t], [Transformation.CENTER]: [(l + r) / 2, (t + b) / 2],
      [Transformation.BOTTOM]: [(l + r) / 2, b], [Transformation.TOPRIGHT]: [r, t], [Transformation.RIGHT]: [r, (t + b) / 2],
      [Transformation.BOTTOMRIGHT]: [r, b],
    }[String(scaleAbout)];
    if (!ref) throw new Error(`resize: bad scaleAbout ${scaleAbout}`);
    const sx = scaleX / 100, sy = scaleY / 100;
    this._transform((p) => [ref[0] + (p[0] - ref[0]) * sx, ref[1] + (p[1] - ref[1]) * sy]);
    this._scaleStroke(changeLineWidths / 100);
  }
  _scaleStroke() {}
}

export class PathPoint extends Node {
  constructor(sim, path) {
    super(sim, 'PathPoint');
    this._parent = path;
    this._a = [0, 0]; this._l = [0, 0]; this._r = [0, 0];
    this._type = PointType.CORNER;
    this._sel = PathPointSelection.NOSELECTION;
  }
  _w(what, v) { this.sim.hit(`PathPoint.${what}`); this._parent.assertWritable(); return this.sim.in(this.document, v, what); }
  get anchor() { return this.sim.out(this.document, this._a); }
  set anchor(v) { this._a = this._w('anchor', v); }
  get leftDirection() { return this.sim.out(this.document, this._l); }
  set leftDirection(v) { this._l = this._w('leftDirection', v); }
  get rightDirection() { return this.sim.out(this.document, this._r); }
  set rightDirection(v) { this._r = this._w('rightDirection', v); }
  get pointType() { return this._type; }
  set pointType(v) {
    this._parent.assertWritable();
    if (v !== PointType.SMOOTH && v !== PointType.CORNER) throw new Error('pointType: expected PointType');
    this._type = v;
  }
  get selected() { return this._sel; }
  set selected(v) { this._sel = v; }
  remove() { this._parent.assertWritable(); const l = this._parent._points; l.splice(l.indexOf(this), 1); }
}

export class PathItem extends PageItem {
  constructor(sim) {
    super(sim, 'PathItem');
    this._points = [];
    this.closed = false;
    this.filled = true;
    this.stroked = true;
    this.fillColor = Object.assign(new RGBColor(), { red: 255, green: 255, blue: 255 });
    this.strokeColor = new RGBColor();
    this.strokeWidth = 1;
    this.clipping = false;
    this.guides = false;
    this.evenodd = false;
  }
  get pathPoints() {
    return collection('PathPoints', () => this._points.slice(), {
      add: () => {
        this.sim.hit('pathPoints.add');
        this.assertWritable();
        const p = new PathPoint(this.sim, this);
        this._points.push(p);
        return p;
      },
    });
  }
  get selectedPathPoints() {
    return collection('PathPoints', () => this._points.filter((p) => p._sel !== PathPointSelection.NOSELECTION));
  }
  get selected() { return this._points.some((p) => p._sel !== PathPointSelection.NOSELECTION) || this._selected; }
  set selected(v) {
    this._selected = !!v;
    for (const p of this._points) p._sel = v ? PathPointSelection.ANCHORPOINT : PathPointSelection.NOSELECTION;
  }
  setEntirePath(pts) {
    this.sim.hit('setEntirePath');
    this.assertWritable();
    const list = [];
    for (let i = 0; i < pts.length; i++) {
      const a = this.sim.in(this.document, pts[i], 'setEntirePath');
      list.push({ anchor: a, left: a, right: a });
    }
    this._setPoints(list);
  }
  _setPoints(list) {
    this._points = list.map((q) => {
      const p = new PathPoint(this.sim, this);
      p._a = this.sim.pair(q.anchor, 'anchor'); p._l = this.sim.pair(q.left, 'left'); p._r = this.sim.pair(q.right, 'right');
      p._type = q.type || PointType.CORNER;
      return p;
    });
  }
  /** Plain {anchor,left,right} list (for the geometry helpers and snapshots). */
  _plain() { return this._points.map((p) => ({ anchor: p._a.slice(), left: p._l.slice(), right: p._r.slice() })); }
  get length() {
    let s = 0;
    for (const seg of segmentsOf(this._plain(), this.closed)) s += cubicLength(...seg);
    return s;
  }
  _bounds() {
    const pts = this._plain();
    if (pts.length === 0) return [0, 0, 0, 0];
    let b = [pts[0].anchor[0], pts[0].anchor[1], pts[0].anchor[0], pts[0].anchor[1]];
    for (const seg of segmentsOf(pts, this.closed)) {
      const c = cubicBounds(...seg);
      b = [Math.min(b[0], c[0]), Math.min(b[1], c[1]), Math.max(b[2], c[2]), Math.max(b[3], c[3])];
    }
    return b;
  }
  _transform(f) {
    for (const p of this._points) {
      p._a = this.sim.pair(f(p._a), 'anchor'); p._l = this.sim.pair(f(p._l), 'left'); p._r = this.sim.pair(f(p._r), 'right');
    }
  }
  _scaleStroke(k) { this.strokeWidth *= k; }
}

export class GroupItem extends PageItem {
  constructor(sim, typename = 'GroupItem') {
    super(sim, typename);
    this._items = [];
    this.clipped = false;
    const c = containerCollections(this, () => this);
    Object.defineProperties(this, {
      pageItems: { get: c.pageItems }, pathItems: { get: c.pathItems }, groupItems: { get: c.groupItems },
      textFrames: { get: c.textFrames }, compoundPathItems: { get: c.compoundPathItems },
    });
  }
  set selected(v) { this._selected = !!v; for (const it of this._items) it.selected = v; }
  get selected() { return this._selected; }
  _bounds() {
    const bs = this._items.map((x) => x._bounds());
    if (bs.length === 0) return [0, 0, 0, 0];
    return [Math.min(...bs.map((b) => b[0])), Math.min(...bs.map((b) => b[1])), Math.max(...bs.map((b) => b[2])), Math.max(...bs.map((b) => b[3]))];
  }
  _transform(f) { for (const it of this._items) it._transform(f); }
  _scaleStroke(k) { for (const it of this._items) it._scaleStroke(k); }
}

export class CompoundPathItem extends GroupItem {
  constructor(sim) { super(sim, 'CompoundPathItem'); }
}

export class TextFrame extends PageItem {
  constructor(sim) {
    super(sim, 'TextFrame');
    this.contents = '';
    this._anchor = [0, 0];
    this.rotation = 0;               // simulator bookkeeping: total rotate() angle, degrees CCW
    const frame = this;
    this.textRange = {
      characterAttributes: { size: 12, fillColor: new RGBColor(), strokeColor: new NoColor() },
      paragraphAttributes: { justification: Justification.LEFT },
      get contents() { return frame.contents; },
    };
  }
  get anchor() { return this.sim.out(this.document, this._anchor); }
  set anchor(v) { this.sim.hit('TextFrame.anchor'); this.assertWritable(); this._anchor = this.sim.in(this.document, v, 'anchor'); }
  /** Approximate visual centre: glyph box 0.6·size wide per character, cap height 0.7·size. */
  _center() {
    const size = this.textRange.characterAttributes.size, w = 0.6 * size * String(this.contents).length;
    const j = this.textRange.paragraphAttributes.justification;
    const dx = j === Justification.CENTER ? 0 : j === Justification.RIGHT ? -w / 2 : w / 2;
    const a = (this.rotation * Math.PI) / 180, dy = 0.35 * size;
    return [this._anchor[0] + dx * Math.cos(a) - dy * Math.sin(a), this._anchor[1] + dx * Math.sin(a) + dy * Math.cos(a)];
  }
  _bounds() { const c = this._center(); return [c[0], c[1], c[0], c[1]]; }
  rotate(angle) {
    this.sim.hit('TextFrame.rotate');
    this.assertWritable();
    const c = this._center(), a = (angle * Math.PI) / 180;
    const d = [this._anchor[0] - c[0], this._anchor[1] - c[1]];
    this._anchor = [c[0] + d[0] * Math.cos(a) - d[1] * Math.sin(a), c[1] + d[0] * Math.sin(a) + d[1] * Math.cos(a)];
    this.rotation += angle;
  }
  _transform(f) { this._anchor = f(this._anchor); }
}

/** Items the D-former scripts only skip (images, symbols, …): a typename and bounds. */
export class OtherItem extends PageItem {
  constructor(sim, typename) { super(sim, typename); }
  _bounds() { return [0, 0, 0, 0]; }
  _transform() {}
}

export class Application {
  constructor(sim) { this.sim = sim; this.name = 'Adobe Illustrator'; this.version = '28.0.0'; this.userInteractionLevel = 'DONTDISPLAYALERTS'; }
  get typename() { return 'Application'; }
  get documents() { return collection('Documents', () => this.sim.documents.slice()); }
  get activeDocument() {
    if (this.sim.documents.length === 0) throw new Error('There is no document');
    return this.sim.documents[0];
  }
  get selection() { return this.activeDocument.selection; }
  get coordinateSystem() { return this.sim.coordinateSystem; }
  set coordinateSystem(v) {
    const hit = Object.values(CoordinateSystem).find((m) => Number(m) === Number(v));
    if (!hit) throw new Error('coordinateSystem: expected a CoordinateSystem');
    this.sim.hit('app.coordinateSystem');
    this.sim.coordinateSystem = hit;
  }
}
