/* D-former panel: SVG drawing helpers and the laser-ready SVG file.
 * Laser convention: cut = red hairline, score = blue, engrave = black (colours and widths from
 * the panel's layer settings). One Inkscape-compatible layer per operation, one group per piece
 * inside each layer. The file's viewBox is in points, y down; width/height carry the physical size. */
(function (DF) {
  'use strict';
  function n(x) {
    return String(Math.round(x * 1e4) / 1e4);
  }
  /** SVG path data of a core path, with y negated (document y up → SVG y down). */
  function pathD(path) {
    var p = path.points;
    if (!p.length) return '';
    function xy(q) {
      return n(q[0]) + ' ' + n(-q[1]);
    }
    var d = 'M' + xy(p[0].anchor);
    var count = path.closed ? p.length : p.length - 1;
    for (var i = 0; i < count; i++) {
      var a = p[i];
      var b = p[(i + 1) % p.length];
      var c1 = a.right || a.anchor;
      var c2 = b.left || b.anchor;
      var straight = c1[0] === a.anchor[0] && c1[1] === a.anchor[1] && c2[0] === b.anchor[0] && c2[1] === b.anchor[1];
      d += straight ? 'L' + xy(b.anchor) : 'C' + xy(c1) + ' ' + xy(c2) + ' ' + xy(b.anchor);
    }
    return d + (path.closed ? 'Z' : '');
  }
  function esc(s) {
    return String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
  }
  /** Bounds [minX, minY, maxX, maxY] of anchors and handles (a safe box for Béziers), y down. */
  function boundsOf(paths) {
    var b = [Infinity, Infinity, -Infinity, -Infinity];
    paths.forEach(function (path) {
      path.points.forEach(function (q) {
        [q.anchor, q.left, q.right].forEach(function (p) {
          if (!p) return;
          b[0] = Math.min(b[0], p[0]);
          b[1] = Math.min(b[1], -p[1]);
          b[2] = Math.max(b[2], p[0]);
          b[3] = Math.max(b[3], -p[1]);
        });
      });
    });
    return b;
  }
  function labelEl(label, size) {
    // The core's size keeps the number clear of holes, slots and the cut line: never larger.
    if (label.size > 0 && label.size < size) size = label.size;
    var x = n(label.at[0]);
    var y = n(-label.at[1]);
    var rot = label.angle ? ' transform="rotate(' + n(-label.angle) + ' ' + x + ' ' + y + ')"' : '';
    return '<text x="' + x + '" y="' + y + '" font-size="' + n(size) + '" text-anchor="middle" dominant-baseline="central"' + rot + '>' + esc(label.text) + '</text>';
  }

  function movePath(path, dx, dy) {
    return DF.core.transformPath(path, [1, 0, 0, 1, dx, dy]);
  }
  /**
   * The pieces placed left to right, GAP apart, tops aligned (document points, y up). Normalizing
   * scales each piece about its own centre, so pieces that were side by side can overlap: a laser
   * file must never stack one cut over another.
   */
  var GAP = 10 * (72 / 25.4); // 10 mm
  function separate(pieces) {
    var x = 0;
    return pieces.map(function (p) {
      var b = boundsOf([p.outline].concat(p.holes.map(function (h) { return h.path; }), p.marks));
      var dx = x - b[0];
      var dy = b[1]; // y down → the top (−b[1] in y up) goes to 0
      x += b[2] - b[0] + GAP;
      var moved = {};
      Object.keys(p).forEach(function (k) { moved[k] = p[k]; });
      moved.outline = movePath(p.outline, dx, dy);
      moved.holes = p.holes.map(function (h) {
        var c = {};
        Object.keys(h).forEach(function (k) { c[k] = h[k]; });
        c.path = movePath(h.path, dx, dy);
        return c;
      });
      moved.marks = p.marks.map(function (m) { return movePath(m, dx, dy); });
      moved.slots = (p.slots || []).map(function (s) { return movePath(s, dx, dy); });
      if (p.seam) moved.seam = movePath(p.seam, dx, dy);
      moved.labels = p.labels.map(function (l) {
        var c = {};
        Object.keys(l).forEach(function (k) { c[k] = l[k]; });
        c.at = [l.at[0] + dx, l.at[1] + dy];
        return c;
      });
      return moved;
    });
  }

  /**
   * The laser file for a design: { pieces: [{ name, outline, holes, slots?, seam?, labels, marks }] } (document
   * points, y up), layers settings { cut, score, engrave: { name, color, width } }, labelSize (pt),
   * unit for width/height. Returns SVG text.
   */
  function laserSvg(design, layers, labelSize, unit) {
    var all = [];
    design = { pieces: separate(design.pieces) };
    design.pieces.forEach(function (p) {
      all.push(p.outline);
      p.holes.forEach(function (h) { all.push(h.path); });
      p.marks.forEach(function (m) { all.push(m); });
    });
    var b = boundsOf(all);
    var margin = 9; // pt
    var x0 = b[0] - margin;
    var y0 = b[1] - margin;
    var w = b[2] - b[0] + 2 * margin;
    var h = b[3] - b[1] + 2 * margin;
    var u = unit === 'px' || unit === 'pt' || !DF.units.PER_UNIT[unit] ? 'pt' : unit;
    var size = function (pt) { return n(DF.units.toUnits(pt, u)) + u; };
    var out = [];
    out.push('<?xml version="1.0" encoding="UTF-8"?>');
    out.push('<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"' +
      ' width="' + size(w) + '" height="' + size(h) + '" viewBox="' + [x0, y0, w, h].map(n).join(' ') + '">');
    out.push('<title>D-former laser file</title>');
    function layer(key, body) {
      var l = layers[key];
      var paint = key === 'engrave'
        ? ' fill="' + l.color + '" stroke="none" font-family="Helvetica, Arial, sans-serif"'
        : ' fill="none" stroke="' + l.color + '" stroke-width="' + n(l.width) + '"';
      out.push('<g id="layer-' + key + '" inkscape:groupmode="layer" inkscape:label="' + esc(l.name) + '"' + paint + '>');
      out.push(body.join('\n'));
      out.push('</g>');
    }
    layer('cut', design.pieces.map(function (p) {
      var items = ['<path class="outline" d="' + pathD(p.outline) + '"/>'];
      p.holes.forEach(function (hole, i) {
        items.push('<path class="hole" data-index="' + (i + 1) + '" d="' + pathD(hole.path) + '"/>');
      });
      (p.slots || []).forEach(function (slot, i) {
        items.push('<path class="slot" data-index="' + (i + 1) + '" d="' + pathD(slot) + '"/>');
      });
      return '<g id="cut-' + esc(p.key) + '" inkscape:label="' + esc(p.name) + ' connectors">' + items.join('') + '</g>';
    }));
    layer('score', design.pieces.map(function (p) {
      return '<g id="score-' + esc(p.key) + '" inkscape:label="' + esc(p.name) + ' marks">' +
        p.marks.map(function (m) { return '<path class="mark" d="' + pathD(m) + '"/>'; }).join('') +
        (p.seam ? '<path class="seam" d="' + pathD(p.seam) + '"/>' : '') + '</g>';
    }));
    layer('engrave', design.pieces.map(function (p) {
      return '<g id="engrave-' + esc(p.key) + '" inkscape:label="' + esc(p.name) + ' labels">' +
        p.labels.map(function (l) { return labelEl(l, labelSize); }).join('') + '</g>';
    }));
    out.push('</svg>');
    return out.join('\n') + '\n';
  }
  DF.svgExport = { pathD: pathD, laserSvg: laserSvg, separate: separate, boundsOf: boundsOf, labelEl: labelEl, esc: esc, n: n };
})(window.DF = window.DF || {});
