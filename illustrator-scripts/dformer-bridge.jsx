/*
 * D-former document bridge for Adobe Illustrator (ExtendScript, strict ES3).
 * The CEP panel calls the dformer_* functions through CSInterface.evalScript; each returns a JSON
 * string and never throws. Contract and selection rules: BRIDGE.md next to this file.
 * Coordinates are Illustrator scripting coordinates in DOCUMENTCOORDINATESYSTEM: points, y axis up.
 */

// ---------------------------------------------------------------------------------------------
// JSON (ExtendScript has no JSON object). Strict RFC 8259 reader, writer with round-trip numbers.
// ---------------------------------------------------------------------------------------------

/** @param {*} v @returns {boolean} */
function dformer_isArray(v) {
  return Object.prototype.toString.call(v) === "[object Array]";
}

/**
 * JSON string literal in plain ASCII: everything outside printable ASCII is a \uXXXX escape, so the
 * answer survives any text encoding between ExtendScript and the panel (BRIDGE.md, "Text encoding").
 * @param {string} s @returns {string}
 */
function dformer_quote(s) {
  var out = "\"";
  for (var i = 0; i < s.length; i++) {
    var c = s.charAt(i);
    var code = s.charCodeAt(i);
    if (c === "\"") out += "\\\"";
    else if (c === "\\") out += "\\\\";
    else if (c === "\n") out += "\\n";
    else if (c === "\r") out += "\\r";
    else if (c === "\t") out += "\\t";
    else if (code < 0x20 || code > 0x7e) {
      var hex = code.toString(16);
      while (hex.length < 4) hex = "0" + hex;
      out += "\\u" + hex;
    } else out += c;
  }
  return out + "\"";
}

/**
 * Shortest text that reads back as the same double where the engine allows it; 17 significant
 * digits always round-trip an IEEE double.
 * @param {number} n @returns {string}
 */
function dformer_number(n) {
  if (!isFinite(n)) return "null";
  if (n === 0) return "0";
  var s = String(n);
  if (Number(s) !== n) s = n.toPrecision(17);
  return s;
}

/** @param {*} v @returns {string} */
function dformer_stringify(v) {
  if (v === null || v === undefined) return "null";
  var t = typeof v;
  if (t === "number") return dformer_number(v);
  if (t === "boolean") return v ? "true" : "false";
  if (t === "string") return dformer_quote(v);
  var parts = [];
  if (dformer_isArray(v)) {
    for (var i = 0; i < v.length; i++) parts.push(dformer_stringify(v[i]));
    return "[" + parts.join(",") + "]";
  }
  for (var k in v) {
    if (Object.prototype.hasOwnProperty.call(v, k) && v[k] !== undefined && typeof v[k] !== "function") {
      parts.push(dformer_quote(k) + ":" + dformer_stringify(v[k]));
    }
  }
  return "{" + parts.join(",") + "}";
}

/**
 * Parse JSON text; throws {dformer: message} naming the character position on malformed input.
 * @param {string} text @returns {*}
 */
function dformer_parse(text) {
  var at = 0;
  /** @param {string} what @returns {never} */
  function bad(what) {
    throw { dformer: "The panel sent malformed data (" + what + " at character " + at + ")." };
  }
  function white() {
    while (at < text.length) {
      var c = text.charAt(at);
      if (c === " " || c === "\t" || c === "\n" || c === "\r") at++;
      else break;
    }
  }
  /** @returns {string} */
  function str() {
    var out = "";
    at++; // opening quote
    while (at < text.length) {
      var c = text.charAt(at++);
      if (c === "\"") return out;
      if (c === "\\") {
        var e = text.charAt(at++);
        if (e === "\"" || e === "\\" || e === "/") out += e;
        else if (e === "b") out += "\b";
        else if (e === "f") out += "\f";
        else if (e === "n") out += "\n";
        else if (e === "r") out += "\r";
        else if (e === "t") out += "\t";
        else if (e === "u") {
          var hex = text.substring(at, at + 4);
          if (!/^[0-9a-fA-F]{4}$/.test(hex)) bad("bad \\u escape");
          out += String.fromCharCode(parseInt(hex, 16));
          at += 4;
        } else bad("bad escape");
      } else if (c.charCodeAt(0) < 0x20) bad("control character in string");
      else out += c;
    }
    return bad("unterminated string");
  }
  /** @returns {number} */
  function num() {
    var start = at;
    while (at < text.length && "+-0123456789.eE".indexOf(text.charAt(at)) >= 0) at++;
    var s = text.substring(start, at);
    if (!/^-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+\-]?[0-9]+)?$/.test(s)) bad("bad number");
    return Number(s);
  }
  /** @param {string} word @param {*} value @returns {*} */
  function lit(word, value) {
    if (text.substring(at, at + word.length) !== word) bad("unexpected token");
    at += word.length;
    return value;
  }
  /** @returns {*} */
  function value() {
    white();
    var c = text.charAt(at);
    if (c === "{") {
      /** @type {Object<string, *>} */
      var obj = {};
      at++;
      white();
      if (text.charAt(at) === "}") { at++; return obj; }
      while (true) {
        white();
        if (text.charAt(at) !== "\"") bad("expected a property name");
        var key = str();
        white();
        if (text.charAt(at) !== ":") bad("expected ':'");
        at++;
        obj[key] = value();
        white();
        c = text.charAt(at++);
        if (c === "}") return obj;
        if (c !== ",") bad("expected ',' or '}'");
      }
    }
    if (c === "[") {
      var arr = [];
      at++;
      white();
      if (text.charAt(at) === "]") { at++; return arr; }
      while (true) {
        arr.push(value());
        white();
        c = text.charAt(at++);
        if (c === "]") return arr;
        if (c !== ",") bad("expected ',' or ']'");
      }
    }
    if (c === "\"") return str();
    if (c === "t") return lit("true", true);
    if (c === "f") return lit("false", false);
    if (c === "n") return lit("null", null);
    if (c === "-" || (c >= "0" && c <= "9")) return num();
    return bad(at >= text.length ? "unexpected end" : "unexpected character");
  }
  var result = value();
  white();
  if (at < text.length) bad("trailing characters");
  return result;
}

// ---------------------------------------------------------------------------------------------
// Shared helpers
// ---------------------------------------------------------------------------------------------

/** @param {string} message @returns {never} */
function dformer_fail(message) {
  throw { dformer: message };
}

/**
 * Run body and turn its result or any thrown value into the bridge's JSON answer.
 * Coordinates: app.coordinateSystem is one global setting that other scripts often leave on
 * ARTBOARDCOORDINATESYSTEM, where positions are relative to whichever artboard is active. Every
 * entry point runs in DOCUMENTCOORDINATESYSTEM, so that what is read on one artboard is written back
 * to the same place after the student clicks another one, and restores the previous value afterwards
 * (the finally also runs when body throws).
 * @param {function(): Object} body @returns {string}
 */
function dformer_run(body) {
  var out;
  /** @type {*} */
  var saved = null;
  try {
    if (app.documents.length > 0 && app.coordinateSystem != CoordinateSystem.DOCUMENTCOORDINATESYSTEM) {
      saved = app.coordinateSystem;
      app.coordinateSystem = CoordinateSystem.DOCUMENTCOORDINATESYSTEM;
    }
    var r = body();
    r.ok = true;
    out = dformer_stringify(r);
  } catch (e) {
    var err = /** @type {*} */ (e);
    var msg;
    if (err && typeof err.dformer === "string") msg = err.dformer;
    else msg = "Illustrator reported an error: " + (err && err.message ? err.message : String(err)) +
      (err && err.line ? " (dformer-bridge.jsx line " + err.line + ")" : "");
    out = dformer_stringify({ ok: false, error: msg });
  } finally {
    if (saved !== null) {
      try { app.coordinateSystem = saved; } catch (e2) { /* the answer matters more than the setting */ }
    }
  }
  return out;
}

/** @returns {Document} */
function dformer_doc() {
  if (app.documents.length === 0) dformer_fail("No document is open. Open or create a document, then select two paths.");
  return app.activeDocument;
}

/**
 * Ruler units of a document as one of mm cm in pt px pc (nearest family for the others).
 * @param {Document} doc @returns {{units: string, pointsPerUnit: number, rulerUnits: string}}
 */
function dformer_unitsOf(doc) {
  var u = doc.rulerUnits;
  var name = String(u);
  var units = "pt";
  if (u == RulerUnits.Millimeters || u == RulerUnits.Qs) units = "mm";
  else if (u == RulerUnits.Centimeters) units = "cm";
  else if (u == RulerUnits.Inches) units = "in";
  else if (u == RulerUnits.Points) units = "pt";
  else if (u == RulerUnits.Pixels) units = "px";
  else if (u == RulerUnits.Picas) units = "pc";
  else if (/Meter/.test(name)) units = "mm";
  else if (/Feet|Yard|Inch/.test(name)) units = "in";
  /** @type {Object<string, number>} */
  var perUnit = { mm: 72 / 25.4, cm: 720 / 25.4, "in": 72, pt: 1, px: 1, pc: 12 };
  return { units: units, pointsPerUnit: perUnit[units], rulerUnits: name };
}

/**
 * Document.scaleFactor: 1, or 10 in a Large Canvas document, whose scripting DOM reports and takes
 * every length divided by it (creold/illustrator-scripts Rescale, StrokesWeightDown, NumeratesPoints
 * read it the same way; the Scripting Reference does not list it). Feature-detected: 1 where the
 * property is missing (Illustrator before Large Canvas) or not a positive number.
 * @param {Document} doc @returns {number}
 */
function dformer_scaleOf(doc) {
  var sf;
  try { sf = /** @type {*} */ (doc).scaleFactor; } catch (e) { sf = undefined; }
  return typeof sf === "number" && isFinite(sf) && sf > 0 ? sf : 1;
}

/** Display name of a page item for messages. @param {PageItem} it @returns {string} */
function dformer_nameOf(it) {
  if (it.name) return it.name;
  return "<" + it.typename.replace(/Item$/, "") + ">";
}

/** @param {*} p @returns {boolean} */
function dformer_hasUuid(p) {
  var doc = app.activeDocument;
  var u;
  try { u = p.uuid; } catch (e) { u = undefined; }
  return u !== undefined && u !== null && u !== "" && dformer_canLookUpUuid(doc);
}

/** Document.getPageItemFromUuid exists (Illustrator 24+). @param {Document} doc @returns {boolean} */
function dformer_canLookUpUuid(doc) {
  try { return doc.getPageItemFromUuid !== undefined; } catch (e) { return false; }
}

/**
 * Index of child in a collection (DOM references compare with ==).
 * @param {*} coll @param {*} child @returns {number}
 */
function dformer_indexIn(coll, child) {
  for (var i = 0; i < coll.length; i++) if (coll[i] == child) return i;
  return -1;
}

/**
 * Handle for a path: "u:<uuid>" (Illustrator 24+), "c:<compound path uuid>/<sub-path index>#<point count>"
 * for the sub-path of a compound path (whether getPageItemFromUuid finds a sub-path is not documented),
 * or "p:<position>#<point count>" (older Illustrator, or a compound path without uuid).
 * @param {PathItem} p @returns {string}
 */
function dformer_idOf(p) {
  /** @type {*} */
  var owner = p.parent;
  if (owner && owner.typename === "CompoundPathItem") {
    if (dformer_hasUuid(owner)) return "c:" + owner.uuid + "/" + dformer_indexIn(owner.pathItems, p) + "#" + p.pathPoints.length;
  } else if (dformer_hasUuid(p)) return "u:" + p.uuid;
  var parts = [];
  /** @type {*} */
  var node = p;
  while (node.typename !== "Document") {
    var parent = node.parent;
    if (node.typename === "Layer") parts.unshift("L" + dformer_indexIn(parent.layers, node));
    else if (parent.typename === "CompoundPathItem") parts.unshift("C" + dformer_indexIn(parent.pathItems, node));
    else parts.unshift(String(dformer_indexIn(parent.pageItems, node)));
    node = parent;
  }
  return "p:" + parts.join("/") + "#" + p.pathPoints.length;
}

/**
 * The PathItem an id names, or a user error saying why not.
 * @param {Document} doc @param {*} id @param {string} where @returns {PathItem}
 */
function dformer_resolve(doc, id, where) {
  if (typeof id !== "string" || id === "") dformer_fail(where + ": missing path id.");
  var stale = where + ": the path (" + id + ") is no longer in the document or changed since it was read; select the paths again.";
  /** @type {*} */
  var found = null;
  if (id.substring(0, 2) === "u:") {
    if (!dformer_canLookUpUuid(doc)) dformer_fail(stale);
    try { found = doc.getPageItemFromUuid ? doc.getPageItemFromUuid(id.substring(2)) : null; } catch (e) { found = null; }
  } else if (id.substring(0, 2) === "c:") {
    var slash = id.lastIndexOf("/"), mark = id.lastIndexOf("#");
    if (!dformer_canLookUpUuid(doc) || slash < 0 || mark < slash) dformer_fail(stale);
    try {
      /** @type {*} */
      var compound = doc.getPageItemFromUuid ? doc.getPageItemFromUuid(id.substring(2, slash)) : null;
      found = compound && compound.typename === "CompoundPathItem" ? compound.pathItems[Number(id.substring(slash + 1, mark))] : null;
      if (found && String(found.pathPoints.length) !== id.substring(mark + 1)) found = null;
    } catch (e1) {
      found = null;
    }
  } else if (id.substring(0, 2) === "p:") {
    var hash = id.lastIndexOf("#");
    var parts = id.substring(2, hash < 0 ? id.length : hash).split("/");
    try {
      /** @type {*} */
      var node = doc;
      for (var i = 0; i < parts.length; i++) {
        var part = parts[i];
        if (part.charAt(0) === "L") node = node.layers[Number(part.substring(1))];
        else if (part.charAt(0) === "C") node = node.pathItems[Number(part.substring(1))];
        else node = node.pageItems[Number(part)];
      }
      found = node;
      if (hash < 0 || found.typename !== "PathItem" || String(found.pathPoints.length) !== id.substring(hash + 1)) found = null;
    } catch (e2) {
      found = null;
    }
  } else {
    dformer_fail(where + ": \"" + id + "\" is not a D-former path id.");
  }
  if (!found || found.typename !== "PathItem") dformer_fail(stale);
  return /** @type {PathItem} */ (found);
}

/**
 * Why an item (or its layer) cannot be written, or "" if it can.
 * @param {*} it @returns {string}
 */
function dformer_blocked(it) {
  /** @type {*} */
  var node = it;
  while (node && node.typename !== "Document") {
    if (node.typename === "Layer") {
      if (node.locked) return "its layer \"" + node.name + "\" is locked";
      if (!node.visible) return "its layer \"" + node.name + "\" is hidden";
    } else {
      if (node.locked) return (node == it ? "it" : "its group \"" + dformer_nameOf(node) + "\"") + " is locked";
      if (node.hidden) return (node == it ? "it" : "its group \"" + dformer_nameOf(node) + "\"") + " is hidden";
    }
    node = node.parent;
  }
  return "";
}

// ---------------------------------------------------------------------------------------------
// Reading the selection
// ---------------------------------------------------------------------------------------------

/** Reasons for page items D-former does not read. */
var DFORMER_SKIP = {
  TextFrame: "text frame: D-former works on paths; outline the text first (Type > Create Outlines)",
  LegacyTextItem: "legacy text: update and outline it first",
  RasterItem: "image: D-former works on vector paths",
  PlacedItem: "placed image: D-former works on vector paths",
  SymbolItem: "symbol instance: break the link to the symbol first",
  MeshItem: "gradient mesh: not a path",
  GraphItem: "graph: ungroup it first",
  PluginItem: "plug-in art (blend, live effect, envelope...): expand it first (Object > Expand)",
  NonNativeItem: "non-native art: not a path"
};

/** A D-form has two pieces: the poll and the selection read the geometry of at most this many paths. */
var DFORMER_PIECES = 2;
/** Selected objects looked at before the walk gives up with `more` (two paths and thousands of text
 * frames would otherwise cost several reads per object on every poll). */
var DFORMER_VISITS = 500;

/**
 * Walk the selection into readable paths and skipped items (rules in BRIDGE.md). Stops at the
 * (DFORMER_PIECES + 1)th path or the DFORMER_VISITS-th object (`more`): a Select All of hundreds of
 * paths costs a few reads, not a walk of every item (ExtendScript runs on Illustrator's main thread).
 * @param {Document} doc
 * @returns {{paths: Array<{item: PathItem, id: string}>, skipped: Array<{name: string, reason: string}>, more: boolean, selected: number}}
 */
function dformer_collect(doc) {
  /** @type {Array<{item: PathItem, id: string}>} */
  var paths = [];
  /** @type {Array<{name: string, reason: string}>} */
  var skipped = [];
  /** @type {Object<string, boolean>} */
  var seen = {};
  var more = false;
  var visits = 0;
  /** @param {PathItem} p @param {string} label */
  function takePath(p, label) {
    if (p.clipping) { skipped.push({ name: label, reason: "clipping path: it masks its group; D-former leaves it alone" }); return; }
    if (p.guides) { skipped.push({ name: label, reason: "guide: not artwork" }); return; }
    if (p.pathPoints.length < 2) { skipped.push({ name: label, reason: "single anchor point (a stray point, not an outline)" }); return; }
    var id = dformer_idOf(p);
    if (seen[id]) return;
    seen[id] = true;
    if (paths.length === DFORMER_PIECES) { more = true; return; }
    paths.push({ item: p, id: id });
  }
  /** @param {*} it */
  function visit(it) {
    if (more) return;
    if (++visits > DFORMER_VISITS) { more = true; return; }
    var t = it.typename;
    var label = dformer_nameOf(it);
    // Selecting a group selects everything in it, also what the student hid or locked there
    // (construction lines, a reference copy): such items are not pieces, and could not be written.
    if (it.hidden) { skipped.push({ name: label, reason: "hidden inside a selected group: D-former leaves hidden art alone (Object > Show All to use it)" }); return; }
    if (it.locked) { skipped.push({ name: label, reason: "locked inside a selected group: unlock it (Object > Unlock All) to use it" }); return; }
    if (t === "PathItem") takePath(it, label);
    else if (t === "GroupItem") {
      var g = /** @type {GroupItem} */ (it);
      for (var j = 0; j < g.pageItems.length && !more; j++) visit(g.pageItems[j]);
    } else if (t === "CompoundPathItem") {
      var c = /** @type {CompoundPathItem} */ (it);
      if (c.pathItems.length === 1) takePath(c.pathItems[0], label);
      else skipped.push({ name: label, reason: "compound path with " + c.pathItems.length +
        " sub-paths: release it (Object > Compound Path > Release) and select one outline" });
    } else {
      var why = /** @type {Object<string, string>} */ (DFORMER_SKIP)[t];
      skipped.push({ name: label, reason: why ? why : t + ": not a path" });
    }
  }
  var sel = doc.selection;
  if (sel === null || sel === undefined) return { paths: paths, skipped: skipped, more: false, selected: 0 };
  if (typeof sel.length !== "number" || sel.typename) {
    skipped.push({ name: "<Text selection>", reason: "text is being edited: press Esc and select the paths" });
    return { paths: paths, skipped: skipped, more: false, selected: 0 };
  }
  var n = sel.length;
  for (var i = 0; i < n && !more; i++) visit(sel[i]);
  if (more) { paths = []; skipped = []; }
  return { paths: paths, skipped: skipped, more: more, selected: n };
}

/**
 * The core's path JSON for a PathItem, with its anchor selection; coordinates multiplied by `sf`
 * (Document.scaleFactor: real points from a Large Canvas document's DOM values; 1 or omitted to copy them).
 * @param {PathItem} p @param {number} [sf]
 */
function dformer_readPath(p, sf) {
  if (sf === undefined) sf = 1;
  var pts = [];
  var selectedAnchors = [];
  var n = p.pathPoints.length;
  for (var i = 0; i < n; i++) {
    var pp = p.pathPoints[i];
    var a = pp.anchor, l = pp.leftDirection, r = pp.rightDirection;
    pts.push({ anchor: [sf * a[0], sf * a[1]], left: [sf * l[0], sf * l[1]], right: [sf * r[0], sf * r[1]] });
    if (pp.selected == PathPointSelection.ANCHORPOINT) selectedAnchors.push(i);
  }
  return { path: { closed: p.closed, points: pts }, selectedAnchors: selectedAnchors, allSelected: n > 0 && selectedAnchors.length === n };
}

// ---------------------------------------------------------------------------------------------
// Public functions (the panel's contract; see BRIDGE.md)
// ---------------------------------------------------------------------------------------------

/** @returns {string} */
function dformer_info() {
  return dformer_run(function () {
    return { bridge: "dformer-bridge", version: "1", hasDocument: app.documents.length > 0, app: String(app.version) };
  });
}

/** @returns {string} */
function dformer_units() {
  return dformer_run(function () {
    var doc = dformer_doc();
    var u = dformer_unitsOf(doc);
    return { document: doc.name, units: u.units, pointsPerUnit: u.pointsPerUnit, rulerUnits: u.rulerUnits, colorMode: dformer_isCmyk(doc) ? "CMYK" : "RGB",
      scaleFactor: dformer_scaleOf(doc) };
  });
}

/** @returns {string} */
function dformer_selectionKey() {
  return dformer_run(function () {
    if (app.documents.length === 0) return { key: "", hasDocument: false };
    var doc = app.activeDocument;
    var c = dformer_collect(doc);
    // Colour mode too: switching it (File > Document Color Mode) changes what the panel tells the student.
    var parts = [doc.name, String(doc.rulerUnits), dformer_isCmyk(doc) ? "CMYK" : "RGB", String(dformer_scaleOf(doc)), String(c.skipped.length)];
    // More than two paths: the panel shows "select two paths" and needs no geometry, so the key is
    // the number of selected objects only (bounded however much is selected).
    if (c.more) return { key: parts.join(";") + ";more:" + c.selected, hasDocument: true };
    for (var i = 0; i < c.paths.length; i++) {
      var p = c.paths[i].item;
      var sel = [];
      // Every anchor and handle goes into two weighted sums: moving a point inside the bounds
      // (a notch, a handle) or re-ordering the points (rotating a square by 90 degrees) leaves
      // geometricBounds alone but must still make the panel read the path again.
      var h1 = 0, h2 = 0;
      var n = p.pathPoints.length;
      for (var j = 0; j < n; j++) {
        var pp = p.pathPoints[j];
        if (pp.selected == PathPointSelection.ANCHORPOINT) sel.push(j);
        var a = pp.anchor, l = pp.leftDirection, r = pp.rightDirection;
        h1 += (j + 1) * (a[0] + 3 * a[1] + 5 * l[0] + 7 * l[1] + 11 * r[0] + 13 * r[1]);
        h2 += ((j % 7) + 1) * (2 * a[0] - a[1]) + ((j % 5) + 2) * (l[0] - 3 * r[1]) + ((j % 3) + 3) * (r[0] - 5 * l[1]);
      }
      parts.push(c.paths[i].id + "|" + n + "|" + p.closed + "|" + p.geometricBounds.join(",") + "|" +
        dformer_number(h1) + "," + dformer_number(h2) + "|" + sel.join(","));
    }
    return { key: parts.join(";"), hasDocument: true };
  });
}

/** @returns {string} */
function dformer_selection() {
  return dformer_run(function () {
    var doc = dformer_doc();
    var u = dformer_unitsOf(doc);
    var c = dformer_collect(doc);
    var sf = dformer_scaleOf(doc);
    var items = [];
    for (var i = 0; i < c.paths.length; i++) {
      var p = c.paths[i].item;
      var r = dformer_readPath(p, sf);
      items.push({
        id: c.paths[i].id, name: dformer_nameOf(p), layer: p.layer ? p.layer.name : "",
        path: r.path, selectedAnchors: r.selectedAnchors, allSelected: r.allSelected, length: sf * p.length
      });
    }
    return { document: doc.name, units: u.units, pointsPerUnit: u.pointsPerUnit, colorMode: dformer_isCmyk(doc) ? "CMYK" : "RGB",
      scaleFactor: sf, items: items, more: c.more, selected: c.selected, skipped: c.skipped };
  });
}

// ---------------------------------------------------------------------------------------------
// dformer_apply: validate everything, then write (with rollback if Illustrator throws midway)
// ---------------------------------------------------------------------------------------------

var DFORMER_LAYER_DEFAULTS = {
  cut: { name: "Cut", color: [255, 0, 0], width: 0.072 },
  score: { name: "Score", color: [0, 0, 255], width: 0.072 },
  engrave: { name: "Engrave", color: [0, 0, 0], width: 0.072 }
};

/** Illustrator's type sizes in points (the Character panel's range); a label outside it would make
 * Illustrator throw mid-write, so it is refused before anything is written. */
var DFORMER_TYPE_SIZE = [0.1, 1296];

/**
 * What a piece puts on each role's layer: the group title and how many items it holds.
 * @param {*} pc @returns {Array<{role: string, title: string, count: number}>}
 */
function dformer_jobs(pc) {
  return [
    { role: "cut", title: "connectors", count: pc.holes.length + pc.slots.length + (pc.outline ? 1 : 0) },
    { role: "score", title: "marks", count: pc.marks.length + (pc.seam ? 1 : 0) },
    { role: "engrave", title: "labels", count: pc.labels.length }
  ];
}

/** @param {*} v @param {string} where @returns {number} */
function dformer_finite(v, where) {
  if (typeof v !== "number" || !isFinite(v)) {
    dformer_fail(where + ": expected a finite number, got " + (typeof v === "number" ? String(v) : dformer_stringify(v)) + ".");
  }
  return v;
}

/** @param {*} v @param {string} where @returns {Array<number>} */
function dformer_pair(v, where) {
  if (!dformer_isArray(v) || v.length !== 2) dformer_fail(where + ": expected [x, y], got " + dformer_stringify(v) + ".");
  return [dformer_finite(v[0], where + " x"), dformer_finite(v[1], where + " y")];
}

/**
 * Check a core path and return it normalised ({closed, points:[{anchor,left,right}]}), in DOM units:
 * the panel's real points divided by `sf` (Document.scaleFactor; pass dformer_scaleOf(doc): omitted
 * means 1, right only outside Large Canvas documents).
 * @param {*} path @param {string} where @param {number} [sf]
 * @returns {{closed: boolean, points: Array<{anchor: Array<number>, left: Array<number>, right: Array<number>}>}}
 */
function dformer_checkPath(path, where, sf) {
  if (sf === undefined) sf = 1;
  if (!path || typeof path !== "object" || !dformer_isArray(path.points)) dformer_fail(where + ": expected a path {closed, points:[...]}.");
  if (path.points.length < 2) dformer_fail(where + ": a path needs at least 2 points, got " + path.points.length + ".");
  var out = [];
  for (var i = 0; i < path.points.length; i++) {
    var q = path.points[i];
    var w = where + " point " + i;
    if (!q || typeof q !== "object") dformer_fail(w + ": expected {anchor, left, right}.");
    var a = dformer_pair(q.anchor, w + " anchor");
    var l = q.left === undefined || q.left === null ? a : dformer_pair(q.left, w + " left");
    var r = q.right === undefined || q.right === null ? a : dformer_pair(q.right, w + " right");
    out.push({ anchor: [a[0] / sf, a[1] / sf], left: [l[0] / sf, l[1] / sf], right: [r[0] / sf, r[1] / sf] });
  }
  return { closed: path.closed !== false, points: out };
}

/** @param {*} v @param {string} where @returns {Array<number>} */
function dformer_checkColor(v, where) {
  if (!dformer_isArray(v) || v.length !== 3) dformer_fail(where + ": expected [r, g, b] from 0 to 255, got " + dformer_stringify(v) + ".");
  for (var i = 0; i < 3; i++) {
    dformer_finite(v[i], where);
    if (v[i] < 0 || v[i] > 255) dformer_fail(where + ": colour components go from 0 to 255, got " + v[i] + ".");
  }
  return [v[0], v[1], v[2]];
}

/**
 * Validate an apply request against the document; returns the write plan. Writes nothing.
 * @param {Document} doc @param {*} req
 */
function dformer_plan(doc, req) {
  if (!req || typeof req !== "object" || dformer_isArray(req)) dformer_fail("The panel sent no apply request.");
  if (req.document !== undefined && req.document !== null && req.document !== doc.name) {
    dformer_fail("The active document is \"" + doc.name + "\", not \"" + req.document + "\" where the paths were read; switch back or select the paths again.");
  }
  // Lengths in the request are real points; a Large Canvas document's DOM takes them divided by sf.
  var sf = dformer_scaleOf(doc);
  var labelSize = req.labelSize === undefined || req.labelSize === null ? 6 : dformer_finite(req.labelSize, "labelSize");
  if (labelSize < DFORMER_TYPE_SIZE[0] || labelSize > DFORMER_TYPE_SIZE[1]) {
    dformer_fail("labelSize must be from " + DFORMER_TYPE_SIZE[0] + " to " + DFORMER_TYPE_SIZE[1] + " pt (Illustrator's type sizes), got " + labelSize + ".");
  }

  // Layers: defaults merged with the request.
  /** @type {Object<string, {name: string, color: Array<number>, width: number, layer: *, needed: boolean}>} */
  var layers = {};
  var roles = ["cut", "score", "engrave"];
  var reqLayers = req.layers && typeof req.layers === "object" ? req.layers : {};
  for (var r = 0; r < roles.length; r++) {
    var role = roles[r];
    var d = /** @type {*} */ (DFORMER_LAYER_DEFAULTS)[role];
    var given = reqLayers[role] && typeof reqLayers[role] === "object" ? reqLayers[role] : {};
    var name = given.name === undefined || given.name === null ? d.name : given.name;
    if (typeof name !== "string" || name === "") dformer_fail("layers." + role + ".name: expected a layer name.");
    var color = dformer_checkColor(given.color === undefined || given.color === null ? d.color : given.color, "layers." + role + ".color");
    var width = given.width === undefined || given.width === null ? d.width : dformer_finite(given.width, "layers." + role + ".width");
    if (width <= 0) dformer_fail("layers." + role + ".width: stroke width must be greater than 0, got " + width + ".");
    layers[role] = { name: name, color: color, width: width / sf, layer: null, needed: false };
  }

  // In-place updates.
  var updates = [];
  var reqUpdates = req.updates === undefined || req.updates === null ? [] : req.updates;
  if (!dformer_isArray(reqUpdates)) dformer_fail("updates: expected a list.");
  /** @type {Object<string, boolean>} */
  var seenIds = {};
  for (var u = 0; u < reqUpdates.length; u++) {
    var up = reqUpdates[u];
    var where = "updates[" + u + "]";
    if (!up || typeof up !== "object") dformer_fail(where + ": expected {id, path}.");
    var item = dformer_resolve(doc, up.id, where);
    where = where + " (\"" + dformer_nameOf(item) + "\")";
    if (seenIds[up.id]) dformer_fail(where + ": the same path is updated twice.");
    seenIds[up.id] = true;
    var why = dformer_blocked(item);
    if (why) dformer_fail(where + ": cannot change the path because " + why + ".");
    var path = dformer_checkPath(up.path, where, sf);
    var n = item.pathPoints.length;
    if (path.points.length !== n) {
      dformer_fail(where + ": the path has " + n + " anchors in Illustrator but the new path has " + path.points.length +
        "; in-place updates keep the anchor count.");
    }
    updates.push({ item: item, path: path });
  }

  // Pieces.
  var pieces = [];
  var reqPieces = req.pieces === undefined || req.pieces === null ? [] : req.pieces;
  if (!dformer_isArray(reqPieces)) dformer_fail("pieces: expected a list.");
  /** @type {Object<string, boolean>} */
  var seenNames = {};
  for (var k = 0; k < reqPieces.length; k++) {
    var pc = reqPieces[k];
    var pw = "pieces[" + k + "]";
    if (!pc || typeof pc !== "object") dformer_fail(pw + ": expected {name, holes, labels, marks}.");
    if (pc.id !== undefined && pc.id !== null) dformer_resolve(doc, pc.id, pw);
    var pname = pc.name === undefined || pc.name === null ? "piece " + String.fromCharCode(65 + k) : pc.name;
    if (typeof pname !== "string" || pname === "") dformer_fail(pw + ": name must be a non-empty string.");
    if (seenNames[pname]) dformer_fail(pw + ": two pieces are both named \"" + pname + "\".");
    seenNames[pname] = true;
    pw = pw + " (\"" + pname + "\")";
    var piece = { name: pname, outline: /** @type {*} */ (null), seam: /** @type {*} */ (null), holes: /** @type {Array<*>} */ ([]), slots: /** @type {Array<*>} */ ([]), marks: /** @type {Array<*>} */ ([]), labels: /** @type {Array<*>} */ ([]) };
    if (pc.outline !== undefined && pc.outline !== null) piece.outline = dformer_checkPath(pc.outline, pw + " outline", sf);
    // With a seam allowance: the seam line, scored so the user can fold or stitch along it.
    if (pc.seam !== undefined && pc.seam !== null) piece.seam = dformer_checkPath(pc.seam, pw + " seam", sf);
    var lists = ["holes", "slots", "marks", "labels"];
    for (var li = 0; li < lists.length; li++) {
      var lv = pc[lists[li]];
      if (lv === undefined || lv === null) lv = [];
      if (!dformer_isArray(lv)) dformer_fail(pw + " " + lists[li] + ": expected a list.");
    }
    var holes = pc.holes || [];
    for (var h = 0; h < holes.length; h++) {
      var hp = holes[h] && holes[h].path && !holes[h].points ? holes[h].path : holes[h];
      piece.holes.push(dformer_checkPath(hp, pw + " holes[" + h + "]", sf));
    }
    // Slots that receive the other piece's locking leaves: cuts, like holes.
    var slots = pc.slots || [];
    for (var sl = 0; sl < slots.length; sl++) piece.slots.push(dformer_checkPath(slots[sl], pw + " slots[" + sl + "]", sf));
    var marks = pc.marks || [];
    for (var m = 0; m < marks.length; m++) piece.marks.push(dformer_checkPath(marks[m], pw + " marks[" + m + "]", sf));
    var labels = pc.labels || [];
    for (var b = 0; b < labels.length; b++) {
      var lb = labels[b];
      var lw = pw + " labels[" + b + "]";
      if (!lb || typeof lb !== "object") dformer_fail(lw + ": expected {text, at, angle}.");
      if (typeof lb.text !== "string" && typeof lb.text !== "number") dformer_fail(lw + ": text must be a string.");
      var size = lb.size === undefined || lb.size === null ? labelSize : dformer_finite(lb.size, lw + " size");
      if (size < DFORMER_TYPE_SIZE[0] || size > DFORMER_TYPE_SIZE[1]) {
        dformer_fail(lw + ": size must be from " + DFORMER_TYPE_SIZE[0] + " to " + DFORMER_TYPE_SIZE[1] + " pt (Illustrator's type sizes), got " + size + ".");
      }
      var at = dformer_pair(lb.at, lw + " at");
      piece.labels.push({
        text: String(lb.text), at: [at[0] / sf, at[1] / sf],
        angle: lb.angle === undefined || lb.angle === null ? 0 : dformer_finite(lb.angle, lw + " angle"), size: size / sf
      });
    }
    if (piece.outline || piece.holes.length || piece.slots.length) layers.cut.needed = true;
    if (piece.marks.length || piece.seam) layers.score.needed = true;
    if (piece.labels.length) layers.engrave.needed = true;
    pieces.push(piece);
  }

  // Colours: the layer colours are the exact RGB values laser software matches cut/score/engrave by.
  // In a CMYK document Illustrator translates an RGBColor into CMYK inks (CMYKColor in the Scripting
  // Reference: the translation "can lose information"), and no CMYKColor comes back out as exactly
  // 255,0,0 either; only the student can change the mode (documentColorSpace is read-only).
  var colored = [];
  for (var rc = 0; rc < roles.length; rc++) {
    var CL = layers[roles[rc]];
    if (CL.needed) colored.push(CL.name + " " + CL.color.join(","));
  }
  if (colored.length && dformer_isCmyk(doc)) {
    dformer_fail("This document uses CMYK colour (a Print document): Illustrator would turn the laser colours (" +
      colored.join("; ") + ") into CMYK ink values, and laser software that tells cut, score and engrave apart by " +
      "exact RGB colour would no longer recognise them. Choose File > Document Color Mode > RGB Color, then Apply again. Nothing was changed.");
  }

  // Target layers: existing ones must be writable.
  for (var t = 0; t < roles.length; t++) {
    var L = layers[roles[t]];
    if (!L.needed) continue;
    for (var x = 0; x < doc.layers.length; x++) {
      if (doc.layers[x].name === L.name) { L.layer = doc.layers[x]; break; }
    }
    if (L.layer && (L.layer.locked || !L.layer.visible)) {
      dformer_fail("Layer \"" + L.name + "\" is " + (L.layer.locked ? "locked" : "hidden") + "; unlock and show it in the Layers panel, then apply again.");
    }
  }
  // Replace: the pieces' previous groups, found now so that one Illustrator cannot remove stops
  // Apply before anything is written (removed one by one at the end, a locked one would otherwise
  // fail half way, after the others were gone).
  var old = [];
  if (req.replace !== false) {
    for (var op = 0; op < pieces.length; op++) {
      var jobs = dformer_jobs(pieces[op]);
      for (var oj = 0; oj < jobs.length; oj++) {
        var OL = layers[jobs[oj].role];
        if (jobs[oj].count === 0 || !OL.layer) continue;
        var gname = "D-former " + pieces[op].name + " " + jobs[oj].title;
        for (var og = 0; og < OL.layer.groupItems.length; og++) {
          var prev = OL.layer.groupItems[og];
          if (prev.name !== gname || dformer_indexIn(old, prev) >= 0) continue;
          var stuck = dformer_blocked(prev);
          if (stuck) {
            dformer_fail("The previous \"" + gname + "\" group on layer \"" + OL.name + "\" cannot be replaced because " + stuck +
              ": unlock and show it (Object > Unlock All, Object > Show All), or delete it, then apply again. Nothing was changed.");
          }
          old.push(prev);
        }
      }
    }
  }
  return { updates: updates, pieces: pieces, layers: layers, old: old };
}

/** Document.documentColorSpace is CMYK (File > Document Color Mode). @param {Document} doc @returns {boolean} */
function dformer_isCmyk(doc) {
  return doc.documentColorSpace == DocumentColorSpace.CMYK;
}

/** @param {Array<number>} c @returns {RGBColor} */
function dformer_rgb(c) {
  var col = new RGBColor();
  col.red = c[0];
  col.green = c[1];
  col.blue = c[2];
  return col;
}

/**
 * SMOOTH when both handles lie on one line through the anchor on opposite sides, else CORNER. Only
 * for NEW art (the core's doubles); an in-place update keeps each point's type (dformer_setPoints).
 * @param {{anchor: Array<number>, left: Array<number>, right: Array<number>}} q @returns {PointType}
 */
function dformer_pointType(q) {
  var lx = q.left[0] - q.anchor[0], ly = q.left[1] - q.anchor[1];
  var rx = q.right[0] - q.anchor[0], ry = q.right[1] - q.anchor[1];
  var ll = Math.sqrt(lx * lx + ly * ly), rl = Math.sqrt(rx * rx + ry * ry);
  if (ll === 0 || rl === 0) return PointType.CORNER;
  var cross = lx * ry - ly * rx, dot = lx * rx + ly * ry;
  return Math.abs(cross) <= 1e-9 * ll * rl && dot < 0 ? PointType.SMOOTH : PointType.CORNER;
}

/**
 * Set every PathPoint of p from a checked path (same count). `types`: the point types to keep (an
 * in-place update: a uniform scale or a move preserves tangency, while re-deriving the type from
 * coordinates Illustrator stored as 32-bit floats turned smooth points into corners); null derives
 * them (new art).
 * @param {PathItem} p @param {{points: Array<{anchor: Array<number>, left: Array<number>, right: Array<number>}>}} path
 * @param {Array<PointType>|null} [types]
 */
function dformer_setPoints(p, path, types) {
  for (var i = 0; i < path.points.length; i++) {
    var q = path.points[i];
    var pp = p.pathPoints[i];
    pp.anchor = [q.anchor[0], q.anchor[1]];
    pp.leftDirection = [q.left[0], q.left[1]];
    pp.rightDirection = [q.right[0], q.right[1]];
    pp.pointType = types ? types[i] : dformer_pointType(q);
  }
}

/**
 * Draw a new stroked path into a group.
 * @param {GroupItem} group @param {*} path @param {string} name @param {*} style @returns {PathItem}
 */
function dformer_draw(group, path, name, style) {
  var p = group.pathItems.add();
  var anchors = [];
  for (var i = 0; i < path.points.length; i++) anchors.push([path.points[i].anchor[0], path.points[i].anchor[1]]);
  p.setEntirePath(/** @type {*} */ (anchors));
  dformer_setPoints(p, path, null);
  p.closed = path.closed;
  p.name = name;
  dformer_plainStroke(group, p);
  p.filled = false;
  p.stroked = true;
  p.strokeColor = dformer_rgb(style.color);
  p.strokeWidth = style.width;
  return p;
}

/**
 * New art takes the document's current style (what the student last drew with: dashes, round caps,
 * 50 % opacity, Multiply, a brush). Laser software needs a plain hairline, so reset all of it: the
 * [Default] graphic style first (GraphicStyle.applyTo: the only DOM route that removes a brush),
 * then every stroke and transparency attribute explicitly, in case the student edited [Default].
 * Best effort for the graphic style; the explicit attributes must stick.
 * @param {GroupItem} group @param {PathItem} p
 */
function dformer_plainStroke(group, p) {
  try {
    /** @type {*} */
    var styles = dformer_docOf(group).graphicStyles;
    // Only the built-in first style ("[Default]", bracketed in every language): a style the student
    // made could carry effects (a drop shadow) that no attribute below would undo.
    if (styles && styles.length > 0 && /^\[.*\]$/.test(String(styles[0].name))) styles[0].applyTo(p);
  } catch (e) { /* no [Default] style: the attributes below still make a plain stroke */ }
  p.strokeDashes = [];
  p.strokeDashOffset = 0;
  p.strokeCap = StrokeCap.BUTTENDCAP;
  p.strokeJoin = StrokeJoin.MITERENDJOIN;
  p.strokeMiterLimit = 10;
  p.strokeOverprint = false;
  p.fillOverprint = false;
  p.opacity = 100;
  p.blendingMode = BlendModes.NORMAL;
}

/** The Document an item belongs to. @param {*} it @returns {Document} */
function dformer_docOf(it) {
  /** @type {*} */
  var node = it;
  while (node && node.typename !== "Document") node = node.parent;
  return node || app.activeDocument;
}

/** @param {TextFrame} tf @returns {Array<number>} centre of its geometricBounds */
function dformer_boundsCentre(tf) {
  var b = tf.geometricBounds;
  return [(b[0] + b[2]) / 2, (b[1] + b[3]) / 2];
}

/**
 * Point-text label, centre-justified, rotated by angle (degrees CCW), its visual centre at `at`.
 * The documented, widely used route (TextFrameItems.pointText, rotate, translate; no script writes
 * TextFrameItem.anchor after rotate(), and Illustrator need not honour it): create the text at `at`,
 * rotate it about its centre, then move the centre of its bounds (the centre of the rotated glyph
 * box) onto `at`, and read the bounds back to check it landed there.
 * @param {GroupItem} group @param {*} label @param {string} name @param {*} style @returns {TextFrame}
 */
function dformer_label(group, label, name, style) {
  var tf = group.textFrames.pointText([label.at[0], label.at[1]]);
  tf.contents = label.text;
  tf.name = name;
  tf.textRange.characterAttributes.size = label.size;
  tf.textRange.characterAttributes.fillColor = dformer_rgb(style.color);
  tf.textRange.characterAttributes.strokeColor = new NoColor();
  tf.textRange.paragraphAttributes.justification = Justification.CENTER;
  tf.opacity = 100;
  tf.blendingMode = BlendModes.NORMAL;
  if (label.angle !== 0) tf.rotate(label.angle);
  var c = dformer_boundsCentre(tf);
  tf.translate(label.at[0] - c[0], label.at[1] - c[1]);
  c = dformer_boundsCentre(tf);
  var off = Math.sqrt((c[0] - label.at[0]) * (c[0] - label.at[0]) + (c[1] - label.at[1]) * (c[1] - label.at[1]));
  if (!(off <= 0.01 * label.size + 1e-6)) {
    throw new Error("label \"" + label.text + "\" did not land where it was placed (" + off + " pt away)");
  }
  return tf;
}

/**
 * Apply a validated plan. Records what it does so that a failure midway can be undone.
 * @param {Document} doc @param {*} plan
 */
function dformer_write(doc, plan) {
  var journal = { saved: /** @type {Array<*>} */ ([]), groups: /** @type {Array<*>} */ ([]), layers: /** @type {Array<*>} */ ([]) };
  var created = 0;
  var groupNames = [];
  var layerNames = [];
  // Layers.add() makes the new layer the current one; the student's next shape must still go
  // where they were drawing, not onto the laser's Engrave layer.
  /** @type {*} */
  var active = null;
  try { active = doc.activeLayer; } catch (e0) { active = null; }
  try {
    for (var u = 0; u < plan.updates.length; u++) {
      var item = plan.updates[u].item;
      var types = dformer_types(item);
      journal.saved.push({ item: item, path: dformer_readPath(item, 1).path, types: types });
      dformer_setPoints(item, plan.updates[u].path, types);
    }
    var roles = ["cut", "score", "engrave"];
    for (var r = 0; r < roles.length; r++) {
      var L = plan.layers[roles[r]];
      if (!L.needed) continue;
      // Roles may share one layer name (e.g. everything on "Laser", told apart by colour):
      // create that layer once, not once per role.
      for (var q = 0; q < r && !L.layer; q++) {
        var M = plan.layers[roles[q]];
        if (M.needed && M.layer && M.name === L.name) L.layer = M.layer;
      }
      if (!L.layer) {
        L.layer = doc.layers.add();
        L.layer.name = L.name;
        L.layer.color = dformer_rgb(L.color);
        journal.layers.push(L.layer);
      }
      if (dformer_indexIn(layerNames, L.name) < 0) layerNames.push(L.name);
    }
    for (var k = 0; k < plan.pieces.length; k++) {
      var pc = plan.pieces[k];
      var jobs = dformer_jobs(pc);
      for (var j = 0; j < jobs.length; j++) {
        if (jobs[j].count === 0) continue;
        var style = plan.layers[jobs[j].role];
        var gname = "D-former " + pc.name + " " + jobs[j].title;
        var group = style.layer.groupItems.add();
        journal.groups.push(group);
        group.name = gname;
        groupNames.push(gname);
        var i;
        if (jobs[j].role === "cut") {
          if (pc.outline) { dformer_draw(group, pc.outline, "outline", style); created++; }
          for (i = 0; i < pc.holes.length; i++) { dformer_draw(group, pc.holes[i], "hole " + (i + 1), style); created++; }
          for (i = 0; i < pc.slots.length; i++) { dformer_draw(group, pc.slots[i], "slot " + (i + 1), style); created++; }
        } else if (jobs[j].role === "score") {
          for (i = 0; i < pc.marks.length; i++) { dformer_draw(group, pc.marks[i], i === 0 ? "start mark" : "mark " + (i + 1), style); created++; }
          if (pc.seam) { dformer_draw(group, pc.seam, "seam line", style); created++; }
        } else {
          for (i = 0; i < pc.labels.length; i++) { dformer_label(group, pc.labels[i], "label " + (i + 1), style); created++; }
        }
      }
    }
    for (var o = 0; o < plan.old.length; o++) plan.old[o].remove();
  } catch (e) {
    var err = /** @type {*} */ (e);
    var undone = dformer_undo(journal);
    dformer_restoreActive(doc, active);
    dformer_fail("Illustrator reported an error while writing: " + (err && err.message ? err.message : String(err)) +
      (undone ? " (the changes were undone)." : " (some changes could not be undone; use Edit > Undo)."));
  }
  dformer_restoreActive(doc, active);
  return { created: created, updated: plan.updates.length, groups: groupNames, layers: layerNames };
}

/** Make `layer` the current layer again if it still exists (best effort). @param {Document} doc @param {*} layer */
function dformer_restoreActive(doc, layer) {
  if (!layer) return;
  try { if (doc.activeLayer != layer) doc.activeLayer = layer; } catch (e) { /* removed or not settable: leave it */ }
}

/** @param {PathItem} p @returns {Array<PointType>} */
function dformer_types(p) {
  var t = [];
  for (var i = 0; i < p.pathPoints.length; i++) t.push(p.pathPoints[i].pointType);
  return t;
}

/**
 * Undo a partial write: remove new groups and layers, restore updated paths. True if all went well.
 * @param {*} journal @returns {boolean}
 */
function dformer_undo(journal) {
  var ok = true;
  var i;
  for (i = journal.groups.length - 1; i >= 0; i--) {
    try { journal.groups[i].remove(); } catch (e1) { ok = false; }
  }
  for (i = journal.layers.length - 1; i >= 0; i--) {
    try { journal.layers[i].remove(); } catch (e2) { ok = false; }
  }
  for (i = journal.saved.length - 1; i >= 0; i--) {
    try {
      var s = journal.saved[i];
      dformer_setPoints(s.item, s.path, s.types);
    } catch (e3) { ok = false; }
  }
  return ok;
}

/**
 * Write the panel's results into the active document (see BRIDGE.md). Validates everything first.
 * @param {*} payload JSON text or an object
 * @returns {string}
 */
function dformer_apply(payload) {
  return dformer_run(function () {
    var doc = dformer_doc();
    var req = typeof payload === "string" ? dformer_parse(payload) : payload;
    var plan = dformer_plan(doc, req);
    return dformer_write(doc, plan);
  });
}
