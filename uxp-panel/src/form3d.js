/* D-former panel: the 3D tab's design figures as text and the connectors on the form — pure
 * functions over the core's results, so app.js only wires them to the page. Host-agnostic. */
(function (DF) {
  'use strict';
  function sig(x) {
    return x.toLocaleString('en-US', Math.abs(x) < 100 ? { maximumSignificantDigits: 3 } : { maximumFractionDigits: 0 });
  }

  /** "Casting 2.05 kg · height 47.14 mm × width 68.23 mm × depth 68.23 mm" from formFigures. */
  function castText(f, fmt) {
    return 'Casting ' + sig(f.mass) + ' kg · height ' + fmt(f.height) + ' × width ' + fmt(f.width) + ' × depth ' + fmt(f.depth);
  }

  /** The sweep's progress, or what it found (largest, tallest, how many did not converge). */
  function sweepText(st, best, fmt) {
    var n = st.points.length;
    var text = '';
    if (st.error) return 'No sweep: ' + st.error;
    if (st.offsetFree && st.done && n) {
      var p = st.points[0];
      return 'One piece is a circle, so the seam offset does not change the form: ' + sig(p.litres) + ' L, height ' + fmt(p.height) +
        ' at every offset' + (p.converged ? '' : ' (not converged ×)');
    }
    if (st.running) text = 'Sampling the seam: ' + n + ' of ' + st.count + ' offsets…';
    else if (st.done) {
      text = n + ' offsets';
      if (best.largest) text += ' · largest ' + sig(best.largest.litres) + ' L at ' + fmt(best.largest.offset);
      if (best.tallest) text += ' · tallest ' + fmt(best.tallest.height) + ' at ' + fmt(best.tallest.offset);
    }
    var unconverged = st.points.filter(function (p) { return !p.converged; }).length;
    if (unconverged) text += ' · ' + unconverged + ' not converged (×)';
    return text;
  }

  /**
   * Holes (centres), numbers (anchors) and start marks (polylines) of the design's two pieces
   * carried onto the form by the core's placeOnForm (each flat point by its barycentric
   * coordinates in simulate's `flat`). Null when the core cannot map them.
   */
  function marksOnForm(pieces, form) {
    var split = pieces.map(function (p) {
      var lines = (p.marks || []).map(function (m) { return m.points.map(function (q) { return q.anchor; }); });
      var flat = [];
      (p.holes || []).forEach(function (h) { flat.push(h.center); });
      (p.labels || []).forEach(function (l) { flat.push(l.at); });
      lines.forEach(function (l) { flat = flat.concat(l); });
      return { piece: p, lines: lines, flat: flat };
    });
    var placed;
    try {
      placed = DF.core.placeOnForm(form, split.map(function (x) { return x.flat; }));
    } catch (e) {
      void e; // a form the core cannot map onto: drawn without connectors
      return null;
    }
    var m = { holes: [], holeOf: [], labels: [], lines: [] };
    split.forEach(function (x, i) {
      var at = placed[i];
      var k = 0;
      (x.piece.holes || []).forEach(function (h) { m.holes.push(at[k++]); m.holeOf.push({ piece: i, flat: h.center }); });
      (x.piece.labels || []).forEach(function (l) { m.labels.push({ at: at[k++], text: l.text, piece: i, flat: l.at }); });
      x.lines.forEach(function (l) { m.lines.push(at.slice(k, k + l.length)); k += l.length; });
    });
    return m;
  }

  DF.form3d = { castText: castText, sweepText: sweepText, marksOnForm: marksOnForm };
})(window.DF = window.DF || {});
