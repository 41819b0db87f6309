/* D-former panel: the live 2D preview (SVG) of both pieces with their connectors, numbers and start
 * marks, drawn before anything is written. Pieces are shown side by side at one common scale on a
 * white "artboard" so the layer colours read as on the laser bed. Host-agnostic. */
(function (DF) {
  'use strict';
  var NS = 'http://www.w3.org/2000/svg';
  var X = DF.svgExport;

  function el(name, attrs, parent) {
    var e = document.createElementNS(NS, name);
    Object.keys(attrs).forEach(function (k) {
      e.setAttribute(k, attrs[k]);
    });
    if (parent) parent.appendChild(e);
    return e;
  }

  /**
   * Draws `pieces` ([{ key, name, path, outline?, holes?, slots?, seam?, labels?, marks? }], document
   * points, y up)
   * into the <svg> element. `layers` gives colours; `labelSize` in points; `pitch` (points, optional)
   * caps the label size so neighbouring numbers never overlap on screen.
   */
  function render(svg, pieces, layers, labelSize, pitch) {
    while (svg.firstChild) svg.removeChild(svg.firstChild);
    if (!pieces || !pieces.length) {
      svg.setAttribute('viewBox', '0 0 100 60');
      el('text', { x: 50, y: 30, class: 'empty', 'text-anchor': 'middle', 'dominant-baseline': 'central' }, svg).textContent = 'No pieces';
      return;
    }
    var boxes = pieces.map(function (p) {
      var paths = [p.outline || p.path];
      (p.holes || []).forEach(function (h) { paths.push(h.path); });
      return X.boundsOf(paths);
    });
    var maxH = 0;
    var maxW = 0;
    boxes.forEach(function (b) {
      maxH = Math.max(maxH, b[3] - b[1]);
      maxW = Math.max(maxW, b[2] - b[0]);
    });
    var gap = 0.18 * Math.max(maxW, maxH);
    var margin = 0.1 * Math.max(maxW, maxH);
    var head = 0.12 * Math.max(maxW, maxH);
    var rect = svg.getBoundingClientRect();
    var total = boxes.reduce(function (s, b) { return s + (b[2] - b[0]); }, 0) + gap * (boxes.length - 1);
    var vbW = total + 2 * margin;
    var vbH = maxH + 2 * margin + head;
    svg.setAttribute('viewBox', [-margin, -margin - head, vbW, vbH].join(' '));
    var pxPerUnit = rect.width > 0 ? Math.min(rect.width / vbW, rect.height > 0 ? rect.height / vbH : Infinity) : 1;
    var minFont = 8 / pxPerUnit;
    var x = 0;
    pieces.forEach(function (p, i) {
      var b = boxes[i];
      var g = el('g', { class: 'piece', 'data-piece': p.key, transform: 'translate(' + X.n(x - b[0]) + ' ' + X.n(-b[1]) + ')' }, svg);
      el('path', { class: 'outline', d: X.pathD(p.outline || p.path), stroke: layers.cut.color }, g);
      (p.holes || []).forEach(function (h) {
        el('path', { class: 'hole', d: X.pathD(h.path), stroke: layers.cut.color }, g);
      });
      (p.slots || []).forEach(function (s) {
        el('path', { class: 'slot', d: X.pathD(s), stroke: layers.cut.color }, g);
      });
      if (p.seam) el('path', { class: 'seam', d: X.pathD(p.seam), stroke: layers.score.color, 'stroke-dasharray': '4 2' }, g);
      (p.marks || []).forEach(function (m) {
        el('path', { class: 'mark', d: X.pathD(m), stroke: layers.score.color }, g);
      });
      var font = Math.max(labelSize, minFont);
      if (pitch > 0) font = Math.min(font, 0.55 * pitch);
      (p.labels || []).forEach(function (l) {
        // The core sizes each number to clear holes, slots and the cut line: never larger.
        var size = l.size > 0 ? Math.min(font, Math.max(l.size, minFont)) : font;
        var t = el('text', {
          class: 'label',
          x: X.n(l.at[0]),
          y: X.n(-l.at[1]),
          'font-size': X.n(size),
          fill: layers.engrave.color,
          'text-anchor': 'middle',
          'dominant-baseline': 'central',
        }, g);
        if (l.angle) t.setAttribute('transform', 'rotate(' + X.n(-l.angle) + ' ' + X.n(l.at[0]) + ' ' + X.n(-l.at[1]) + ')');
        t.textContent = l.text;
      });
      var title = el('text', { class: 'piece-title', x: X.n(b[0]), y: X.n(b[1] - head * 0.45), 'font-size': X.n(Math.max(head * 0.45, minFont * 1.2)) }, g);
      title.textContent = p.key + '  ' + p.name;
      x += b[2] - b[0] + gap;
    });
  }
  DF.preview = { render: render };
})(window.DF = window.DF || {});
