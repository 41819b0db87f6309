/* D-former panel: the plot of volume and height against the seam offset (one full turn) under the
 * 3D slider, as inline SVG. Volume (litres, solid blue, left) and height (document unit, dashed
 * orange, right) through the converged offsets only: where the solve did not converge the curves
 * break and a grey × on the axis says so. The current offset is a vertical line; the largest
 * volume and the tallest form are ringed. Host-agnostic: render(svg, state, fraction, fmt). */
(function (DF) {
  'use strict';
  var NS = 'http://www.w3.org/2000/svg';
  var PAD = { l: 6, r: 6, t: 8, b: 10 };

  function el(name, attrs, parent) {
    var e = document.createElementNS(NS, name);
    Object.keys(attrs).forEach(function (k) { e.setAttribute(k, attrs[k]); });
    if (parent) parent.appendChild(e);
    return e;
  }
  function box(svg) {
    var w = Math.max(120, svg.clientWidth || 300);
    var h = Math.max(40, svg.clientHeight || 84);
    return { w: w, h: h, pw: w - PAD.l - PAD.r, ph: h - PAD.t - PAD.b };
  }
  /** Offset fraction [0, 1) under a click at clientX. */
  function fractionAt(svg, clientX) {
    var r = svg.getBoundingClientRect();
    var b = box(svg);
    var f = (clientX - r.left - PAD.l) / b.pw;
    return Math.min(Math.max(f, 0), 1) % 1;
  }

  function render(svg, st, fraction) {
    while (svg.firstChild) svg.removeChild(svg.firstChild);
    var b = box(svg);
    svg.setAttribute('viewBox', '0 0 ' + b.w + ' ' + b.h);
    var pts = st.points;
    var ok = pts.filter(function (p) { return p.converged; });
    var vmax = Math.max.apply(null, [0].concat(ok.map(function (p) { return p.litres; }))) || 1;
    var hmax = Math.max.apply(null, [0].concat(ok.map(function (p) { return p.height; }))) || 1;
    var x = function (f) { return PAD.l + f * b.pw; };
    var yv = function (v) { return PAD.t + b.ph * (1 - v / vmax); };
    var yh = function (v) { return PAD.t + b.ph * (1 - v / hmax); };
    el('path', { class: 'axis', d: 'M' + PAD.l + ',' + (PAD.t + b.ph) + 'H' + (PAD.l + b.pw) }, svg);
    [0.25, 0.5, 0.75].forEach(function (f) {
      el('path', { class: 'grid', d: 'M' + x(f) + ',' + PAD.t + 'V' + (PAD.t + b.ph) }, svg);
    });
    // The turn closes on itself: the point at 0 is also the point at 1.
    var loop = pts.slice();
    if (pts.length && pts[0].index === 0 && st.done) loop.push(Object.assign({}, pts[0], { fraction: 1 }));
    [['litres', yv, 'volume'], ['height', yh, 'height']].forEach(function (c) {
      var d = '';
      var pen = false;
      loop.forEach(function (p) {
        if (!p.converged) { pen = false; return; }
        d += (pen ? 'L' : 'M') + x(p.fraction).toFixed(1) + ',' + c[1](p[c[0]]).toFixed(1);
        pen = true;
      });
      el('path', { class: 'curve ' + c[2], id: 'sweep-' + c[2], d: d }, svg);
    });
    pts.forEach(function (p) {
      if (p.converged) {
        el('circle', { class: 'sample', cx: x(p.fraction), cy: yv(p.litres), r: 1.6, 'data-offset': p.offset }, svg);
      } else {
        var cx = x(p.fraction);
        var cy = PAD.t + b.ph - 4;
        var u = el('path', { class: 'unconverged', d: 'M' + (cx - 3) + ',' + (cy - 3) + 'l6,6m0,-6l-6,6', 'data-offset': p.offset }, svg);
        el('title', {}, u).textContent = 'No converged form at this offset';
      }
    });
    // With a circle every offset is one form (st.offsetFree): none is the largest or tallest.
    var big = st.offsetFree ? null : DF.sweep.best(pts, 'volume');
    var tall = st.offsetFree ? null : DF.sweep.best(pts, 'height');
    if (big) el('circle', { class: 'best volume', id: 'sweep-max-volume', cx: x(big.fraction), cy: yv(big.litres), r: 4 }, svg);
    if (tall) el('circle', { class: 'best height', id: 'sweep-max-height', cx: x(tall.fraction), cy: yh(tall.height), r: 4 }, svg);
    if (fraction !== null && fraction !== undefined && isFinite(fraction)) {
      el('path', { class: 'current', id: 'sweep-current', d: 'M' + x(fraction).toFixed(1) + ',' + PAD.t + 'V' + (PAD.t + b.ph), 'data-fraction': fraction }, svg);
    }
    return { largest: big, tallest: tall };
  }

  DF.sweepPlot = { render: render, fractionAt: fractionAt };
})(window.DF = window.DF || {});
