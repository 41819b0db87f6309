/* D-former panel: document ruler units.
 * Classic script (no ES modules: CEP 8's Chromium 57 has none). Everything the panel computes is in
 * document points (1/72 in, y up), as Illustrator's scripting DOM reports coordinates; lengths are
 * converted to the document's ruler unit only for display and entry. */
(function (DF) {
  'use strict';
  /** Points per unit (72 pt = 1 in = 25.4 mm; CSS/Illustrator px = 1 pt; 1 pc = 12 pt). */
  var PER_UNIT = { mm: 72 / 25.4, cm: 720 / 25.4, in: 72, pt: 1, px: 1, pc: 12 };
  /** Decimals shown per unit: about 0.01 mm everywhere. */
  var DECIMALS = { mm: 2, cm: 3, in: 4, pt: 2, px: 2, pc: 3 };

  function known(unit) {
    return Object.prototype.hasOwnProperty.call(PER_UNIT, unit) ? unit : 'pt';
  }
  function toUnits(points, unit) {
    return points / PER_UNIT[known(unit)];
  }
  function toPoints(value, unit) {
    return value * PER_UNIT[known(unit)];
  }
  function format(points, unit, decimals) {
    var u = known(unit);
    var d = decimals === undefined ? DECIMALS[u] : decimals;
    var v = toUnits(points, u);
    return (Math.abs(v) < 0.5 * Math.pow(10, -d) ? 0 : v).toFixed(d) + ' ' + u;
  }
  /** Parses "12.5", "12,5", "12.5 mm", "0.5in" → points; a unit typed by the user wins. NaN if invalid. */
  function parse(text, unit) {
    var m = /^\s*([-+]?(?:\d+[.,]?\d*|[.,]\d+)(?:e[-+]?\d+)?)\s*([a-z]*)\s*$/i.exec(String(text));
    if (!m) return NaN;
    var value = parseFloat(m[1].replace(',', '.'));
    var u = m[2] ? m[2].toLowerCase() : unit;
    if (!Object.prototype.hasOwnProperty.call(PER_UNIT, u)) return NaN;
    return toPoints(value, u);
  }
  DF.units = { PER_UNIT: PER_UNIT, DECIMALS: DECIMALS, known: known, toUnits: toUnits, toPoints: toPoints, format: format, parse: parse };
})(window.DF = window.DF || {});
