/* D-former panel (browser host): reads closed shapes out of an SVG file.
 * The file is parsed with DOMParser as XML (a real parser: entities, CDATA, namespaces, comments).
 * <path>, <rect>, <circle>, <ellipse>, <polygon> and <polyline> become SVG path data (circles,
 * ellipses and rounded corners as the arcs SVG defines), then core paths through the core's
 * `pathFromSvg` (which converts arcs as it does for any path); then the element's full transform
 * (its own and every ancestor's `transform`, nested <svg> viewports, and the root viewBox →
 * physical size) maps them to document points with y up. An affine map sends Bézier control
 * points to control points, so the mapping is exact. */
(function (DF) {
  'use strict';
  var SKIP = { defs: 1, clipPath: 1, mask: 1, symbol: 1, pattern: 1, marker: 1, metadata: 1, title: 1, desc: 1, style: 1, script: 1, namedview: 1 };
  /** Drawn elements that are not outlines: listed as skipped, with the reason the CLI gives too (messages/commands.json). */
  var NOT_OUTLINES = { text: 1, image: 1, use: 1, foreignObject: 1 };
  /** Points per CSS unit of SVG lengths (1 px = 1/96 in). */
  var CSS_PT = { px: 0.75, pt: 1, pc: 12, mm: 72 / 25.4, cm: 720 / 25.4, in: 72, '': 0.75 };

  function mul(a, b) {
    return [
      a[0] * b[0] + a[2] * b[1],
      a[1] * b[0] + a[3] * b[1],
      a[0] * b[2] + a[2] * b[3],
      a[1] * b[2] + a[3] * b[3],
      a[0] * b[4] + a[2] * b[5] + a[4],
      a[1] * b[4] + a[3] * b[5] + a[5],
    ];
  }
  var IDENTITY = [1, 0, 0, 1, 0, 0];

  /** Parses an SVG `transform` attribute into one matrix. */
  function parseTransform(text) {
    var m = IDENTITY;
    if (!text) return m;
    var re = /(matrix|translate|scale|rotate|skewX|skewY)\s*\(([^)]*)\)/g;
    var match;
    while ((match = re.exec(text))) {
      var v = match[2].split(/[\s,]+/).filter(function (s) { return s !== ''; }).map(Number);
      var t;
      var k = match[1];
      if (k === 'matrix') t = v.length === 6 ? v : IDENTITY;
      else if (k === 'translate') t = [1, 0, 0, 1, v[0] || 0, v[1] || 0];
      else if (k === 'scale') t = [v[0], 0, 0, v.length > 1 ? v[1] : v[0], 0, 0];
      else if (k === 'rotate') {
        var a = ((v[0] || 0) * Math.PI) / 180;
        var c = Math.cos(a);
        var s = Math.sin(a);
        t = [c, s, -s, c, 0, 0];
        if (v.length === 3) t = mul(mul([1, 0, 0, 1, v[1], v[2]], t), [1, 0, 0, 1, -v[1], -v[2]]);
      } else if (k === 'skewX') t = [1, 0, Math.tan(((v[0] || 0) * Math.PI) / 180), 1, 0, 0];
      else t = [1, Math.tan(((v[0] || 0) * Math.PI) / 180), 0, 1, 0, 0];
      m = mul(m, t);
    }
    return m;
  }

  function num(el, name) {
    var v = parseFloat(el.getAttribute(name));
    return isFinite(v) ? v : 0;
  }
  function f(x) {
    return String(Math.round(x * 1e9) / 1e9);
  }
  /**
   * A circle's or ellipse's outline as SVG defines it: four arcs from (cx + rx, cy). The core
   * splits each quarter arc into three Béziers (a circle's perimeter within ~2e-7 of 2πr; four
   * quarter Béziers with κ = 4(√2−1)/3 read 1.4e-4 long); the Inkscape extension sends the same.
   */
  function ellipseD(cx, cy, rx, ry) {
    var arc = ['A', f(rx), f(ry), '0 0 1'].join(' ');
    return ['M', f(cx + rx), f(cy), arc, f(cx), f(cy + ry), arc, f(cx - rx), f(cy), arc, f(cx), f(cy - ry), arc, f(cx + rx), f(cy), 'Z'].join(' ');
  }
  function rectD(el) {
    var x = num(el, 'x');
    var y = num(el, 'y');
    var w = num(el, 'width');
    var h = num(el, 'height');
    var rx = el.hasAttribute('rx') ? num(el, 'rx') : el.hasAttribute('ry') ? num(el, 'ry') : 0;
    var ry = el.hasAttribute('ry') ? num(el, 'ry') : rx;
    rx = Math.min(rx, w / 2);
    ry = Math.min(ry, h / 2);
    if (!(rx > 0 && ry > 0)) return ['M', f(x), f(y), 'H', f(x + w), 'V', f(y + h), 'H', f(x), 'Z'].join(' ');
    // Rounded corners are quarter arcs too, as SVG defines them (and the Inkscape extension sends).
    var arc = ['A', f(rx), f(ry), '0 0 1'].join(' ');
    return ['M', f(x + rx), f(y), 'H', f(x + w - rx), arc, f(x + w), f(y + ry), 'V', f(y + h - ry),
      arc, f(x + w - rx), f(y + h), 'H', f(x + rx), arc, f(x), f(y + h - ry), 'V', f(y + ry),
      arc, f(x + rx), f(y), 'Z'].join(' ');
  }
  /** The element's outline as SVG path data, or null when it is not a shape we read. */
  function shapeD(el) {
    var tag = el.localName;
    if (tag === 'path') return el.getAttribute('d') || '';
    if (tag === 'rect') return rectD(el);
    if (tag === 'circle') return ellipseD(num(el, 'cx'), num(el, 'cy'), num(el, 'r'), num(el, 'r'));
    if (tag === 'ellipse') return ellipseD(num(el, 'cx'), num(el, 'cy'), num(el, 'rx'), num(el, 'ry'));
    if (tag === 'line') return ['M', f(num(el, 'x1')), f(num(el, 'y1')), 'L', f(num(el, 'x2')), f(num(el, 'y2'))].join(' ');
    if (tag === 'polygon' || tag === 'polyline') {
      var v = (el.getAttribute('points') || '').trim().split(/[\s,]+/).map(Number);
      var n = v.length - (v.length % 2); // an odd last number is ignored, as SVG does
      if (n < 4) return '';
      // A polyline is closed only when it comes back to its first point (SVG draws no closing
      // segment); that last point is then the first one again. An open one stays open: it is
      // listed as skipped, an open path.
      var closed = tag === 'polygon' || (v[n - 2] === v[0] && v[n - 1] === v[1]);
      if (tag === 'polyline' && closed) n -= 2;
      var d = 'M ' + f(v[0]) + ' ' + f(v[1]);
      for (var i = 2; i + 1 < n; i += 2) d += ' L ' + f(v[i]) + ' ' + f(v[i + 1]);
      return closed ? d + ' Z' : d;
    }
    return null;
  }
  /** A path as a polygon: 16 points per Bézier segment (enough to tell inside from outside). */
  function flatten(path) {
    var pts = path.points;
    var out = [];
    var n = path.closed ? pts.length : pts.length - 1;
    for (var i = 0; i < n; i++) {
      var a = pts[i];
      var b = pts[(i + 1) % pts.length];
      var p0 = a.anchor;
      var p1 = a.right || a.anchor;
      var p2 = b.left || b.anchor;
      var p3 = b.anchor;
      for (var k = 0; k < 16; k++) {
        var t = k / 16;
        var u = 1 - t;
        var w0 = u * u * u;
        var w1 = 3 * u * u * t;
        var w2 = 3 * u * t * t;
        var w3 = t * t * t;
        out.push([w0 * p0[0] + w1 * p1[0] + w2 * p2[0] + w3 * p3[0], w0 * p0[1] + w1 * p1[1] + w2 * p2[1] + w3 * p3[1]]);
      }
    }
    if (!n && pts.length) out.push(pts[0].anchor);
    return out;
  }
  function polygonArea(poly) {
    var a = 0;
    for (var i = 0; i < poly.length; i++) {
      var p = poly[i];
      var q = poly[(i + 1) % poly.length];
      a += p[0] * q[1] - q[0] * p[1];
    }
    return Math.abs(a) / 2;
  }
  function insidePolygon(pt, poly) {
    var inside = false;
    for (var i = 0, j = poly.length - 1; i < poly.length; j = i++) {
      var a = poly[i];
      var b = poly[j];
      if ((a[1] > pt[1]) !== (b[1] > pt[1]) && pt[0] < ((b[0] - a[0]) * (pt[1] - a[1])) / (b[1] - a[1]) + a[0]) inside = !inside;
    }
    return inside;
  }
  /**
   * The sub-path of a compound path that encloses all the others (its holes), or -1 when there is
   * none (separate outlines side by side, or overlapping ones).
   */
  function outerIndex(paths) {
    var polys = paths.map(flatten);
    var best = 0;
    for (var i = 1; i < polys.length; i++) if (polygonArea(polys[i]) > polygonArea(polys[best])) best = i;
    for (var k = 0; k < polys.length; k++) {
      if (k === best) continue;
      for (var m = 0; m < polys[k].length; m++) if (!insidePolygon(polys[k][m], polys[best])) return -1;
    }
    return best;
  }
  /** Hidden with display:none (an Inkscape layer switched off, an old draft): not on the page, not read. */
  function hidden(el) {
    return el.getAttribute('display') === 'none' || /(^|;)\s*display\s*:\s*none\s*(;|$)/i.test(el.getAttribute('style') || '');
  }
  /** An SVG length ("210mm", "8.5in", "300") in points; `px` points per px (and per plain number). */
  function lengthPt(text, px) {
    var m = /^\s*([-+]?[\d.]+(?:e[-+]?\d+)?)\s*(px|pt|pc|mm|cm|in)?\s*$/i.exec(text || '');
    if (!m) return NaN;
    var u = (m[2] || '').toLowerCase();
    return parseFloat(m[1]) * (u === '' || u === 'px' ? px : CSS_PT[u]);
  }
  /**
   * Whether Adobe Illustrator wrote the file. Illustrator's SVG px is its point (72 per inch), not
   * the CSS px (96 per inch): read at 96 ppi, a 100 mm rectangle drawn in Illustrator is 75 mm.
   * "Save As" leaves a "Generator: Adobe Illustrator" comment; "Export As" marks the root with
   * data-name; older files declare Illustrator's namespaces (xmlns:x, xmlns:i → ns.adobe.com).
   */
  function fromIllustrator(doc, svg) {
    var nodes = Array.prototype.slice.call(doc.childNodes).concat(Array.prototype.slice.call(svg.childNodes));
    for (var i = 0; i < nodes.length; i++) {
      if (nodes[i].nodeType === 8 && /Adobe Illustrator/i.test(nodes[i].nodeValue)) return true;
    }
    if (svg.hasAttribute('data-name')) return true;
    for (var k = 0; k < svg.attributes.length; k++) {
      if (/ns\.adobe\.com/i.test(svg.attributes[k].value)) return true;
    }
    return false;
  }
  /**
   * Root matrix: user units → points, then y flipped to y up. The page is the viewBox fitted into
   * the physical width × height by preserveAspectRatio, as every SVG viewer draws it (a percentage
   * is a share of the viewBox's size in px, as Inkscape reads it; one side missing follows the
   * viewBox's proportions, both missing are the viewBox's size in px). With `none`
   * and unequal scales a length would depend on its direction, so a perimeter has no single value:
   * refused, as the Inkscape extension and the CLI refuse it.
   */
  function rootMatrix(svg, px, fileName) {
    var vb = viewBox(svg);
    if (!vb) return [px, 0, 0, -px, 0, 0];
    var size = [['width', vb[2]], ['height', vb[3]]].map(function (wh) {
      var text = (svg.getAttribute(wh[0]) || '').trim();
      if (!text || text === 'auto') return null;
      var pct = /^([-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?)\s*%$/i.exec(text);
      var v = pct ? (parseFloat(pct[1]) / 100) * wh[1] * px : lengthPt(text, px);
      if (!(v > 0 && isFinite(v))) throw new Error(fileName + ': the page\'s ' + wh[0] + '="' + text + '" is not a positive length.');
      return v;
    });
    // One side missing: the viewBox's proportions give it (as browsers size an SVG image).
    var w = size[0] !== null ? size[0] : size[1] !== null ? (size[1] * vb[2]) / vb[3] : vb[2] * px;
    var h = size[1] !== null ? size[1] : (w * vb[3]) / vb[2];
    var fit = fitViewBox(vb, w, h, svg.getAttribute('preserveAspectRatio'));
    if (fit.stretched && Math.abs(fit.sx - fit.sy) > 1e-9 * Math.max(fit.sx, fit.sy)) {
      throw new Error(fileName + ': the page stretches the drawing unequally (preserveAspectRatio="none", ' +
        +(fit.sx / px).toPrecision(6) + ' px per user unit across, ' + +(fit.sy / px).toPrecision(6) + ' down), so a length depends on its direction and a perimeter has no single value. ' +
        'Make the page size proportional to the viewBox, or remove preserveAspectRatio.');
    }
    return [fit.sx, 0, 0, -fit.sy, fit.tx, -fit.ty];
  }
  /** The element's viewBox as [x, y, width, height], or null when it has none that SVG would use. */
  function viewBox(el) {
    var vb = (el.getAttribute('viewBox') || '').trim().split(/[\s,]+/).map(Number);
    return vb.length === 4 && vb.every(isFinite) && vb[2] > 0 && vb[3] > 0 ? vb : null;
  }
  /**
   * The viewBox `vb` fitted into a w × h viewport at the origin (SVG 1.1 §7.8, "the viewBox
   * attribute" and preserveAspectRatio, default xMidYMid meet; unreadable values are the default):
   * x ↦ sx·x + tx, y ↦ sy·y + ty; `stretched` for `none`, where sx and sy may differ.
   */
  function fitViewBox(vb, w, h, preserve) {
    var par = /^\s*(?:defer\s+)?(none|x(Min|Mid|Max)Y(Min|Mid|Max))(?:\s+(meet|slice))?\s*$/.exec(preserve || '') ||
      [null, 'xMidYMid', 'Mid', 'Mid', 'meet'];
    var sx = w / vb[2];
    var sy = h / vb[3];
    var tx = 0;
    var ty = 0;
    if (par[1] !== 'none') {
      sx = sy = par[4] === 'slice' ? Math.max(sx, sy) : Math.min(sx, sy);
      var k = { Min: 0, Mid: 0.5, Max: 1 };
      tx = k[par[2]] * (w - vb[2] * sx);
      ty = k[par[3]] * (h - vb[3] * sy);
    }
    return { sx: sx, sy: sy, tx: tx - vb[0] * sx, ty: ty - vb[1] * sy, stretched: par[1] === 'none' };
  }
  /** CSS px per unit: lengths on a nested <svg> are in its parent's user units (1 user unit = 1 px). */
  var CSS_PX = { px: 1, pt: 96 / 72, pc: 16, mm: 96 / 25.4, cm: 960 / 25.4, in: 96, '': 1 };
  /** An SVG length in user units; `ref` is what 100 % is. NaN when it cannot be read; `fallback` when absent. */
  function userLength(text, ref, fallback) {
    if (text === null || text === undefined || !String(text).trim() || String(text).trim() === 'auto') return fallback;
    var m = /^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?)\s*(px|pt|pc|mm|cm|in|%)?\s*$/i.exec(text);
    if (!m) return NaN;
    var v = parseFloat(m[1]);
    var u = (m[2] || '').toLowerCase();
    return u === '%' ? (v / 100) * ref : v * CSS_PX[u];
  }
  /**
   * A nested <svg>'s viewport: the matrix from its content's user units to its parent's, and the
   * size of its viewport in its own user units (what % inside it refers to). null when it draws
   * nothing (zero width or height). Throws (naming the element) when a length cannot be read.
   * x, y, width, height (default 0, 0, 100 %, 100 %), viewBox and preserveAspectRatio (default
   * xMidYMid meet), as SVG places them; the viewport's clipping is not applied.
   */
  function viewport(el, parent, fileName) {
    var label = el.getAttribute('id') ? '<svg id="' + el.getAttribute('id') + '">' : 'a nested <svg>';
    var x = userLength(el.getAttribute('x'), parent[0], 0);
    var y = userLength(el.getAttribute('y'), parent[1], 0);
    var w = userLength(el.getAttribute('width'), parent[0], parent[0]);
    var h = userLength(el.getAttribute('height'), parent[1], parent[1]);
    if (![x, y, w, h].every(isFinite)) {
      throw new Error(fileName + ': cannot place ' + label + ' (its x, y, width or height is not a length, or is a percentage of a page that has no size).');
    }
    if (!(w > 0 && h > 0)) return null;
    var vb = viewBox(el);
    if (!vb) return { m: [1, 0, 0, 1, x, y], size: [w, h] };
    var fit = fitViewBox(vb, w, h, el.getAttribute('preserveAspectRatio'));
    return { m: [fit.sx, 0, 0, fit.sy, x + fit.tx, y + fit.ty], size: [vb[2], vb[3]] };
  }
  /** The root viewport's size in user units (its viewBox, else its width/height in px); NaN when unknown. */
  function rootSize(svg) {
    var vb = viewBox(svg);
    if (vb) return [vb[2], vb[3]];
    return [userLength(svg.getAttribute('width'), NaN, NaN), userLength(svg.getAttribute('height'), NaN, NaN)];
  }
  /** The unit the file was drawn in, for display ("mm" when it does not say). */
  function fileUnit(svg) {
    var m = /(mm|cm|in|pt|pc)\s*$/i.exec(svg.getAttribute('width') || '');
    return m ? m[1].toLowerCase() : 'mm';
  }

  /**
   * Parses SVG text → { unit, shapes: [{ name, id, label, path, measure }], skipped: [{ name, reason }],
   * notes: [text] } (document points, y up), in document order. `shapes` are the closed outlines
   * that can be pieces, each measured by the core; everything else drawn is in `skipped` with why
   * (open paths, text, images, clones, outlines the core refuses such as self-crossing ones), so one
   * stray stroke never blocks the file. A compound path (several sub-paths in one `d`) is one shape:
   * its outer outline, its holes ignored (said in `notes`); one of separate outlines side by side has
   * no outline to use and is skipped. Throws an Error naming the file when it is not SVG or holds no
   * closed shape at all (naming what was skipped).
   */
  function parse(text, fileName) {
    var doc = new DOMParser().parseFromString(text, 'image/svg+xml');
    var err = doc.getElementsByTagName('parsererror')[0];
    if (err) throw new Error(fileName + ' is not well-formed SVG: ' + err.textContent.replace(/\s+/g, ' ').trim().slice(0, 160));
    var svg = doc.documentElement;
    if (svg.localName !== 'svg') throw new Error(fileName + ' is not an SVG file (its root element is <' + svg.localName + '>).');
    var shapes = [];
    var skipped = [];
    var notes = [];
    var root = rootMatrix(svg, fromIllustrator(doc, svg) ? 1 : CSS_PT.px, fileName);
    (function walk(el, m, size) {
      for (var c = el.firstElementChild; c; c = c.nextElementSibling) {
        if (SKIP[c.localName] || hidden(c)) continue;
        var label = c.getAttribute('inkscape:label') || '';
        var id = c.getAttribute('id') || '';
        var name = id || label || '<' + c.localName + '>';
        if (NOT_OUTLINES[c.localName]) {
          skipped.push({ name: name, reason: DF.commands.skipped(c.localName) });
          continue;
        }
        var cm = mul(m, parseTransform(c.getAttribute('transform')));
        var d = shapeD(c);
        if (d === null && c.localName === 'svg') {
          var vp = viewport(c, size, fileName);
          if (vp) walk(c, mul(cm, vp.m), vp.size);
          continue;
        }
        if (d === null) {
          walk(c, cm, size);
          continue;
        }
        if (!d.trim()) continue;
        var paths;
        try {
          paths = DF.core.pathFromSvg(d).map(function (p) { return DF.core.transformPath(p, cm); });
        } catch (e) {
          skipped.push({ name: name, reason: e.message });
          continue;
        }
        if (!paths.length) continue;
        if (paths.every(function (p) { return !p.closed; })) {
          skipped.push({ name: name, reason: DF.commands.skipped('open') });
          continue;
        }
        // Open strokes inside a compound path draw no area: its closed outlines are what counts.
        paths = paths.filter(function (p) { return p.closed; });
        var outer = paths.length > 1 ? outerIndex(paths) : 0;
        if (outer < 0) {
          skipped.push({ name: name, reason: 'a compound path of ' + paths.length + ' separate outlines: split it into separate shapes' });
          continue;
        }
        var measure;
        try {
          measure = DF.core.measure(paths[outer]);
        } catch (e) {
          // Measuring one path, the core calls it "the first path".
          skipped.push({ name: name, reason: e.message.replace(/^The first path /, 'The path ') });
          continue;
        }
        if (paths.length > 1) {
          var holes = paths.length - 1;
          notes.push('“' + name + '” is a compound path: its outer outline is used, ' + (holes === 1 ? 'its hole is' : 'its ' + holes + ' holes are') + ' ignored.');
        }
        shapes.push({ name: name, id: id, label: label, path: paths[outer], measure: measure });
      }
    })(svg, root, rootSize(svg));
    if (!shapes.length && skipped.length) throw new Error(fileName + ': no closed shape to use (skipped: ' + skipped.map(function (s) { return s.name + ', ' + s.reason; }).join('; ') + ').');
    if (!shapes.length) throw new Error(fileName + ' has no <path>, <rect>, <circle>, <ellipse>, <polygon> or <polyline> to use.');
    return { unit: fileUnit(svg), shapes: shapes, skipped: skipped, notes: notes };
  }
  DF.svgImport = { parse: parse, parseTransform: parseTransform, ellipseD: ellipseD };
})(window.DF = window.DF || {});
