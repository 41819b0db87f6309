/* D-former panel: settings remembered between sessions (localStorage; CEP keeps it per extension).
 * Layer colours/widths, the last design parameters and the unit the user chose. Lengths are stored
 * in points. */
(function (DF) {
  'use strict';
  var KEY = 'dformer.settings.v1';
  var HAIRLINE = 0.072; // pt = 0.001 in, the usual laser "hairline"
  var DEFAULTS = {
    layers: {
      cut: { name: 'Cut', color: '#ff0000', width: HAIRLINE },
      score: { name: 'Score', color: '#0000ff', width: HAIRLINE },
      engrave: { name: 'Engrave', color: '#000000', width: HAIRLINE },
    },
    labelSize: 6,
    density: 2400, // kg/m³ of the casting material (concrete), for the 3D tab's mass
    params: null,
    unit: null, // the unit the user chose (browser app); null: each file's own unit
  };

  function clone(x) {
    return JSON.parse(JSON.stringify(x));
  }
  function load() {
    var s = clone(DEFAULTS);
    try {
      var saved = JSON.parse(window.localStorage.getItem(KEY) || 'null');
      if (saved && typeof saved === 'object') {
        ['cut', 'score', 'engrave'].forEach(function (k) {
          var l = saved.layers && saved.layers[k];
          if (l && /^#[0-9a-f]{6}$/i.test(l.color)) s.layers[k].color = l.color;
          if (l && typeof l.width === 'number' && l.width > 0 && l.width < 100) s.layers[k].width = l.width;
          if (l && typeof l.name === 'string' && l.name.trim()) s.layers[k].name = l.name.trim();
        });
        if (typeof saved.labelSize === 'number' && saved.labelSize > 0) s.labelSize = saved.labelSize;
        if (typeof saved.density === 'number' && saved.density > 0 && isFinite(saved.density)) s.density = saved.density;
        if (saved.params && typeof saved.params === 'object') s.params = saved.params;
        if (/^(mm|cm|in|pt|px|pc)$/.test(saved.unit)) s.unit = saved.unit;
      }
    } catch (unreadable) {
      void unreadable; // unreadable storage: defaults
    }
    return s;
  }
  function save(settings) {
    try {
      window.localStorage.setItem(KEY, JSON.stringify(settings));
    } catch (full) {
      void full; // storage full or disabled: settings last for this session only
    }
  }
  function hexToRgb(hex) {
    var n = parseInt(hex.slice(1), 16);
    return [(n >> 16) & 255, (n >> 8) & 255, n & 255];
  }
  DF.settings = { load: load, save: save, defaults: function () { return clone(DEFAULTS); }, hexToRgb: hexToRgb, HAIRLINE: HAIRLINE };
})(window.DF = window.DF || {});
