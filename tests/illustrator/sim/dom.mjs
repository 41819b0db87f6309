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
//   assigned (Illustrator's translation of RGB colours in a CMYK document is not simulated);
// - behaviour real Illustrator has and the Scripting Reference does not spell out (issue 11; sources in
//   illustrator-scripts/BRIDGE.md, "What the simulated DOM models"):
//   - every PathPoint / geometricBounds read is counted in sim.reads (ExtendScript runs on Illustrator's
//     main thread: what the panel's poll reads, the student waits for);
//   - new paths and text frames take the document's current style (sim.style: dashes, caps, joins,
//     opacity, blend mode, brush), as art drawn with the tools does; graphicStyles[0] ("[Default]")
//     .applyTo() resets it;
//   - Document.scaleFactor (1, or 10 in a Large Canvas document): the DOM reports and takes lengths
//     divided by it; `real*` helpers give the printed size;
//   - TextFrame: textFrames.pointText([x, y]) creates point text at its baseline anchor; the bounds are
//     the rotated glyph box; the `anchor` setter can be made to throw or be ignored (labelAnchor);
//   - app.preferences get/set(Integer|Boolean)Preference; Live Shape rounded rectangles keep their
//     corner radius under resize() unless policyForPreservingCorners is 1 ("Scale Corners");
//   - getPageItemFromUuid does not find the sub-path of a compound path (undocumented: modelled as the
//     failing case, compoundUuid: 'throws').
import { cubicBounds, cubicLength, segmentsOf } from './bezier.mjs';
import { BlendModes, CoordinateSystem, DocumentColorSpace, PathPointSelection, PointType, RulerUnits, StrokeCap, StrokeJoin, Transformation, Justification, UNIT_MEMBERS } from './enums.mjs';

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

/** The style a new path gets from Illustrator's [Default] graphic style. */
export function defaultStyle() {
  return {
    strokeDashes: [], strokeDashOffset: 0, strokeCap: StrokeCap.BUTTENDCAP, strokeJoin: StrokeJoin.MITERENDJOIN,
    strokeMiterLimit: 10, opacity: 100, blendingMode: BlendModes.NORMAL, strokeOverprint: false, fillOverprint: false, brush: null,
  };
}
const STYLE_KEYS = Object.keys(defaultStyle());

export class Sim {
  constructor({ uuid = true, units = 'mm', float32 = false, name = 'Untitled-1.ai', colorSpace = 'RGB', scaleFactor = 1,
    style = null, labelAnchor = 'works', compoundUuid = 'throws', preferencesLocked = false } = {}) {
    this.hasUuid = uuid;
    this.float32 = float32;
    this.scaleFactor = scaleFactor;   // Document.scaleFactor; null = property absent (Illustrator before Large Canvas)
    this.style = { ...defaultStyle(), ...(style || {}) };   // the "current style" new art is drawn with
    this.labelAnchor = labelAnchor;   // 'works' | 'throws' | 'ignored': what TextFrame.anchor = … does
    this.compoundUuid = compoundUuid; // 'throws' | 'works': getPageItemFromUuid on a compound's sub-path
    this.preferencesLocked = preferencesLocked; // true: app.preferences setters have no effect
    this.preferences = { integer: { policyForPreservingCorners: 2 }, boolean: { scaleLineWeight: false } };
    this.reads = 0;                   // PathPoint and bounds reads (the poll's cost on Illustrator's main thread)
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
  // New art takes the current style, like a shape drawn with a tool after the student used a dashed,
  // half-transparent brush stroke.
  const styled = (item) => { Object.assign(item, owner.sim.style, { strokeDashes: owner.sim.style.strokeDashes.slice() }); return item; };
  const newText = () => { const t = new TextFrame(owner.sim); t.opacity = owner.sim.style.opacity; t.blendingMode = owner.sim.style.blendingMode; return t; };
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
      add: addTo(() => styled(new PathItem(owner.sim)), 'pathItems.add'),
      ellipse: (top = 100, left = 100, width = 50, height = 100, reversed = false) => {
        const p = addTo(() => styled(new PathItem(owner.sim)), 'pathItems.ellipse')();
        [left, top] = owner.sim.in(owner.document, [left, top], 'ellipse');
        p._setPoints(ellipsePoints(top, left, width, height, reversed));
        p.closed = true;
        return p;
      },
      rectangle: (top, left, width, height, reversed = false) => {
        const p = addTo(() => styled(new PathItem(owner.sim)), 'pathItems.rectangle')();
        [left, top] = owner.sim.in(owner.document, [left, top], 'rectangle');
        const pts = [[left, top], [left, top - height], [left + width, top - height], [left + width, top]];
        if (reversed) pts.reverse();
        p._setPoints(pts.map((a) => ({ anchor: a, left: a, right: a })));
        p.closed = true;
        return p;
      },
    }),
    groupItems: () => collection('GroupItems', of(GroupItem), { add: addTo(() => new GroupItem(owner.sim), 'groupItems.add') }),
    textFrames: () => collection('TextFrameItems', of(TextFrame), {
      add: addTo(newText, 'textFrames.add'),
      /** TextFrameItems.pointText(anchor): point text whose baseline starts at `anchor` (current coordinate system). */
      pointText: (anchor) => {
        const t = addTo(newText, 'textFrames.pointText')();
        t._anchor = owner.sim.in(owner.document, anchor, 'pointText');
        return t;
      },
    }),
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
  return pts.map((p) => ({ ...p, type: PointType.SMOOTH }));
}

/**
 * A Live Shape rounded rectangle (Rectangle tool + corner widget) as Illustrator expands it: 8 anchors,
 * straight sides and kappa-handle quarter arcs of radius r (clamped to half the shorter side),
 * counter-clockwise from the top of the left side.
 */
export function roundedRectPoints(top, left, width, height, radius) {
  const r = Math.max(0, Math.min(radius, width / 2, height / 2)), k = ((4 * (Math.SQRT2 - 1)) / 3) * r;
  const [l, t, ri, b] = [left, top, left + width, top - height];
  const P = (anchor, lh, rh, type) => ({ anchor, left: lh, right: rh, type });
  const S = PointType.SMOOTH;
  return [
    P([l, t - r], [l, t - r + k], [l, t - r], S), P([l, b + r], [l, b + r], [l, b + r - k], S),
    P([l + r, b], [l + r - k, b], [l + r, b], S), P([ri - r, b], [ri - r, b], [ri - r + k, b], S),
    P([ri, b + r], [ri, b + r - k], [ri, b + r], S), P([ri, t - r], [ri, t - r], [ri, t - r + k], S),
    P([ri - r, t], [ri - r + k, t], [ri - r, t], S), P([l + r, t], [l + r, t], [l + r - k, t], S),
  ];
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
      sim.hit('getPageItemFromUuid');
      const hit = this._all().find((x) => x._uuid === String(u));
      if (!hit || (sim.compoundUuid === 'throws' && hit._parent instanceof CompoundPathItem)) throw NO_SUCH();
      return hit;
    };
    const c = containerCollections(this, () => this._active);
    this._c = c;
  }
  get rulerUnits() { return this._rulerUnits; }
  get documentColorSpace() { return this._colorSpace; }
  /** 1, or 10 in a Large Canvas document (undefined before Illustrator had Large Canvas). Read-only. */
  get scaleFactor() { return this.sim.scaleFactor === null ? undefined : this.sim.scaleFactor; }
  /** The document's graphic styles; [0] is "[Default]", whose applyTo() resets an item's appearance. */
  get graphicStyles() {
    const def = {
      typename: 'ArtStyle', name: '[Default]',
      applyTo: (item) => {
        this.sim.hit('ArtStyle.applyTo');
        item.assertWritable();
        Object.assign(item, defaultStyle());
        if (item instanceof PathItem) {
          Object.assign(item, { filled: true, stroked: true, strokeWidth: 1 });
          item.fillColor = Object.assign(new RGBColor(), { red: 255, green: 255, blue: 255 });
          item.strokeColor = new RGBColor();
        }
      },
    };
    return collection('ArtStyles', () => [def]);
  }
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
    const c = this._c.textFrames();
    return collection('TextFrameItems', () => this._all().filter((x) => x instanceof TextFrame), { add: c.add, pointText: c.pointText });
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
    this.sim.reads++;
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
    this.sim.hit('translate');
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
    // A Live Shape keeps its corner radius unless Scale Corners is on (policyForPreservingCorners 1).
    if (this._live) {
      const [nl, nb, nr, nt] = [ref[0] + (minX - ref[0]) * sx, ref[1] + (minY - ref[1]) * sy, ref[0] + (maxX - ref[0]) * sx, ref[1] + (maxY - ref[1]) * sy];
      if (this.sim.preferences.integer.policyForPreservingCorners === 1) this._live.radius *= Math.sqrt(Math.abs(sx * sy));
      this._setPoints(roundedRectPoints(Math.max(nt, nb), Math.min(nl, nr), Math.abs(nr - nl), Math.abs(nt - nb), this._live.radius));
    }
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
  get anchor() { this.sim.reads++; return this.sim.out(this.document, this._a); }
  set anchor(v) { this._a = this._w('anchor', v); }
  get leftDirection() { this.sim.reads++; return this.sim.out(this.document, this._l); }
  set leftDirection(v) { this._l = this._w('leftDirection', v); }
  get rightDirection() { this.sim.reads++; return this.sim.out(this.document, this._r); }
  set rightDirection(v) { this._r = this._w('rightDirection', v); }
  get pointType() { this.sim.reads++; return this._type; }
  set pointType(v) {
    this._parent.assertWritable();
    if (v !== PointType.SMOOTH && v !== PointType.CORNER) throw new Error('pointType: expected PointType');
    this._type = v;
  }
  get selected() { this.sim.reads++; return this._sel; }
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
    Object.assign(this, defaultStyle());
    this._live = null;               // {radius} for a Live Shape rounded rectangle
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
    this.opacity = 100;
    this.blendingMode = BlendModes.NORMAL;
    const frame = this;
    this.textRange = {
      characterAttributes: { size: 12, fillColor: new RGBColor(), strokeColor: new NoColor() },
      paragraphAttributes: { justification: Justification.LEFT },
      get contents() { return frame.contents; },
    };
  }
  get anchor() { return this.sim.out(this.document, this._anchor); }
  set anchor(v) {
    this.sim.hit('TextFrame.anchor');
    this.assertWritable();
    if (this.sim.labelAnchor === 'throws') throw new Error('anchor: the property is read-only');
    if (this.sim.labelAnchor === 'ignored') return;
    this._anchor = this.sim.in(this.document, v, 'anchor');
  }
  /** The unrotated glyph box around the baseline anchor: 0.6·size wide per character, from 0.25·size
   * below the baseline (descent) to 0.95·size above it (ascent), so its centre is 0.35·size above. */
  _box() {
    const size = this.textRange.characterAttributes.size, w = 0.6 * size * String(this.contents).length;
    const j = this.textRange.paragraphAttributes.justification;
    const x0 = j === Justification.CENTER ? -w / 2 : j === Justification.RIGHT ? -w : 0;
    return [[x0, -0.25 * size], [x0 + w, -0.25 * size], [x0 + w, 0.95 * size], [x0, 0.95 * size]];
  }
  _corners() {
    const a = (this.rotation * Math.PI) / 180;
    return this._box().map(([x, y]) => [this._anchor[0] + x * Math.cos(a) - y * Math.sin(a), this._anchor[1] + x * Math.sin(a) + y * Math.cos(a)]);
  }
  /** Visual centre: the centre of the rotated glyph box. */
  _center() {
    const c = this._corners();
    return [(c[0][0] + c[2][0]) / 2, (c[0][1] + c[2][1]) / 2];
  }
  _bounds() {
    const c = this._corners(), xs = c.map((p) => p[0]), ys = c.map((p) => p[1]);
    return [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
  }
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
  /** app.preferences: Illustrator's preference store (creold's Rescale reads and writes policyForPreservingCorners). */
  get preferences() {
    const sim = this.sim;
    const get = (kind) => (key) => { const v = sim.preferences[kind][key]; return v === undefined ? (kind === 'integer' ? 0 : false) : v; };
    const set = (kind) => (key, v) => { sim.hit(`preferences.set${kind}`); if (!sim.preferencesLocked) sim.preferences[kind][key] = v; };
    return {
      typename: 'Preferences',
      getIntegerPreference: get('integer'), setIntegerPreference: set('integer'),
      getBooleanPreference: get('boolean'), setBooleanPreference: set('boolean'),
    };
  }
  get coordinateSystem() { return this.sim.coordinateSystem; }
  set coordinateSystem(v) {
    const hit = Object.values(CoordinateSystem).find((m) => Number(m) === Number(v));
    if (!hit) throw new Error('coordinateSystem: expected a CoordinateSystem');
    this.sim.hit('app.coordinateSystem');
    this.sim.coordinateSystem = hit;
  }
}
