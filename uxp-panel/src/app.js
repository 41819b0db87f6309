/* D-former panel: the UI controller. Talks to the host only through the host interface
 * (host-cep.js in Illustrator, host-browser.js in a browser; a UXP host module would plug in here),
 * to the core only through core.js. Every parameter change recomputes the whole design and redraws
 * the preview; Apply writes only a design that computed without error. */
(function (DF) {
  'use strict';
  var DEFAULT_PARAMS = {
    normalize: true, target: 'largest', exact: 0, pivot: 'center',
    kind: 'stitch', spacing: 'count', count: null, pitch: null, pitchTyped: false, slide: 0,
    // Sizes 0: automatic (the core's fractions of the pitch); count and angle null: the core's
    // defaults() — no number of the panel's own. Pitch until typed: the one the core's default
    // count gives (startingPitch).
    diameter: 0, inset: 0, length: 0, angle: null, leaf: 'tab', allowance: 0, invert: false, kerf: 0, labels: true,
    start: [{ mode: 'first', anchor: 1, offset: 0 }, { mode: 'first', anchor: 1, offset: 0 }],
  };

  var $ = function (sel, root) { return (root || document).querySelector(sel); };
  var $$ = function (sel, root) { return Array.prototype.slice.call((root || document).querySelectorAll(sel)); };

  var host = null;
  var settings = DF.settings.load();
  var params = Object.assign({}, JSON.parse(JSON.stringify(DEFAULT_PARAMS)), settings.params || {});
  if (!Array.isArray(params.start) || params.start.length !== 2) params.start = JSON.parse(JSON.stringify(DEFAULT_PARAMS.start));
  var selection = { ok: true, pieces: [], units: 'mm', skipped: [] };
  var design = null;
  var unit = 'mm';
  var pending = false;
  var applying = false;
  var view = '2d';
  var viewer = null;
  var mesh = null; // last simulate() result and the pieces it was solved for (warm start)
  var meshKey = '';
  var meshOffset = 0;
  var solving = false;
  var solveAgain = false;
  var solveStarted = 0; // Date.now() when the solve under way was started
  var supersede = null; // the timer that stops a solve the slider has moved on from
  var interim = null; // a first look on show (a coarser converged form of a long solve) until a result replaces it
  var lookedAt = false; // the solve under way has shown its first look
  var exportWanted = ''; // 'obj' / 'stl' clicked while a solve was running: written when it is done
  var exportWhenSolved = null;
  var sweeper = null; // the seam-offset sweep behind the 3D tab's plot (sweep.js)
  var sweepKey = '';
  var figures = null; // formFigures of the mesh on show
  var loadedSample = ''; // browser: the sample the loaded design came from ('' = opened files)
  var fieldErrors = {}; // field → why the value typed there is not used (shown instead of the design's message)

  /** Length fields: where each value (points) lives. */
  var LEN = {
    exact: { get: function () { return params.exact; }, set: function (v) { params.exact = v; }, min: 0 },
    pitch: { get: function () { return params.pitch || 0; }, set: function (v) { params.pitch = v; params.pitchTyped = true; }, min: 0 },
    diameter: { get: function () { return params.diameter; }, set: function (v) { params.diameter = v; }, min: 0 },
    inset: { get: function () { return params.inset; }, set: function (v) { params.inset = v; }, min: 0 },
    length: { get: function () { return params.length; }, set: function (v) { params.length = v; }, min: 0 },
    kerf: { get: function () { return params.kerf; }, set: function (v) { params.kerf = v; }, min: 0 },
    allowance: { get: function () { return params.allowance; }, set: function (v) { params.allowance = v; }, min: 0 },
    offsetA: { get: function () { return params.start[0].offset; }, set: function (v) { params.start[0].offset = v; }, min: -Infinity },
    offsetB: { get: function () { return params.start[1].offset; }, set: function (v) { params.start[1].offset = v; }, min: -Infinity },
    wcut: { get: function () { return settings.layers.cut.width; }, set: function (v) { settings.layers.cut.width = v; }, min: 0, layer: true },
    wscore: { get: function () { return settings.layers.score.width; }, set: function (v) { settings.layers.score.width = v; }, min: 0, layer: true },
    wengrave: { get: function () { return settings.layers.engrave.width; }, set: function (v) { settings.layers.engrave.width = v; }, min: 0, layer: true },
  };

  /** Sizes left empty take the core's default, a fraction of the pitch (shown as the placeholder). */
  var AUTO = { diameter: true, inset: true, length: true };
  var coreDefaults = null;
  function autoText(name) {
    var p = design && design.pitch;
    if (!coreDefaults || !(p > 0)) return 'auto';
    var d = coreDefaults.options.filter(function (o) {
      return o.name === name && o.kinds.indexOf(params.kind) >= 0 && (!o.leaf || o.leaf === params.leaf);
    })[0];
    if (!d || d.pitch === undefined) return 'auto';
    var len = params.length > 0 ? params.length : 0.5 * p;
    return 'auto ' + lenText(d.pitch * p + (d.length || 0) * len);
  }
  /** Fills what the panel leaves to the core (count, angle) from `defaults()`, and the invert label. */
  function applyCoreDefaults() {
    if (!DF.core.has('defaults')) return;
    coreDefaults = DF.core.defaults();
    coreDefaults.options.forEach(function (o) {
      if (o.name === 'count' && params.count == null) params.count = o.value;
      if (o.name === 'angle' && params.angle == null) params.angle = o.value;
    });
    syncControls();
  }

  /** Spacing by distance with a pitch the user has not typed: perimeter / defaults().count (the
   * pitch the core's default count gives), rounded to 0.01 of the display unit. The perimeter is
   * the one connect spaces along (after normalizing), else the first piece's as measured. */
  function startingPitch() {
    if (params.spacing !== 'pitch' || params.pitchTyped || !coreDefaults) return;
    var count = coreDefaults.options.filter(function (o) { return o.name === 'count'; })[0].value;
    var d = DF.design.compute(selection, Object.assign({}, params, { spacing: 'count', count: count }));
    var m = d.measures && d.measures[0];
    var perimeter = d.ok && d.perimeter > 0 ? d.perimeter : m && m.ok ? m.m.perimeter : 0;
    if (!(perimeter > 0)) return;
    var pitch = DF.units.toPoints(Math.round(DF.units.toUnits(perimeter / count, unit) * 100) / 100, unit);
    if (pitch === params.pitch) return;
    params.pitch = pitch;
    var input = $('#pitch');
    if (input && document.activeElement !== input) input.value = lenText(pitch);
  }

  function fmt(points) {
    return DF.units.format(points, unit);
  }
  /** The design's error with its lengths in the current unit (the core prints points). */
  function errorText(d) {
    if (d && d.pieceCount !== undefined && host && host.kind === 'browser') return browserCountText(d.pieceCount);
    return d && d.error ? advise(DF.messages.humanize(d.error, fmt)) : '';
  }
  /** A message in the host's own words (its menus, or plain words in the browser). */
  function advise(text) {
    return host && host.advise ? host.advise(text) : text;
  }
  /** The browser has no selection: it asks for a file with two shapes. */
  function browserCountText(n) {
    if (n === 1) return 'Only one closed shape is loaded: a D-form joins two pieces. Open an SVG file with two closed shapes, or two SVG files with one shape each.';
    return 'Open an SVG file with two closed shapes (or two SVG files with one shape each), or pick a sample.';
  }
  function lenText(points) {
    // About 0.01 mm everywhere; one more decimal for sub-unit values in the coarse-grained units.
    var d = DF.units.DECIMALS[unit] + (DF.units.DECIMALS[unit] === 2 && Math.abs(DF.units.toUnits(points, unit)) < 1 && points !== 0 ? 1 : 0);
    return String(parseFloat(DF.units.toUnits(points, unit).toFixed(d)));
  }
  function save() {
    if (document.getElementById('status')) document.getElementById('status').textContent = '';
    settings.params = params;
    DF.settings.save(settings);
  }

  // ---------------------------------------------------------------- theme
  function applyTheme(theme) {
    var c = theme.background;
    var body = document.body;
    body.classList.toggle('theme-dark', theme.dark);
    body.classList.toggle('theme-light', !theme.dark);
    body.style.setProperty('--bg', 'rgb(' + c.join(',') + ')');
    var shift = theme.dark ? -1 : 1;
    function shade(k) {
      return 'rgb(' + c.map(function (v) { return Math.max(0, Math.min(255, Math.round(v + shift * k))); }).join(',') + ')';
    }
    body.style.setProperty('--field', theme.dark ? shade(14) : 'rgb(255,255,255)');
    body.style.setProperty('--raised', shade(-10));
    body.style.setProperty('--line', shade(theme.dark ? -28 : 38));
  }

  // ---------------------------------------------------------------- view sync
  function showUnits() {
    $('#units-badge').textContent = unit;
    $$('.u').forEach(function (s) {
      if (s.textContent !== '°' && s.textContent !== 'pt') s.textContent = unit;
    });
    $$('.u').forEach(function (s) {
      if (s.previousElementSibling && s.previousElementSibling.id === 'label-size') s.textContent = 'pt';
    });
    $$('input.len').forEach(function (input) {
      var auto = AUTO[input.dataset.len] && !(LEN[input.dataset.len].get() > 0);
      if (document.activeElement !== input) input.value = auto ? '' : lenText(LEN[input.dataset.len].get());
      if (AUTO[input.dataset.len]) input.placeholder = autoText(input.dataset.len);
      input.classList.remove('invalid');
    });
  }
  function syncControls() {
    $('#normalize-on').checked = params.normalize;
    $('#norm-target').value = params.target;
    $('#row-exact').hidden = params.target !== 'exact';
    $('#norm-pivot').value = params.pivot;
    $$('#sec-normalize .row').forEach(function (r) { r.classList.toggle('disabled', !params.normalize); });
    $$('#kind button').forEach(function (b) {
      var on = b.dataset.kind === params.kind;
      b.classList.toggle('selected', on);
      b.setAttribute('aria-checked', on ? 'true' : 'false');
    });
    $$('#sec-connectors .row[class*="k-"]').forEach(function (r) {
      r.hidden = !r.classList.contains('k-' + params.kind);
    });
    $('#spacing').value = params.spacing;
    $('#count').hidden = params.spacing !== 'count';
    $('#pitch').hidden = $('#pitch-u').hidden = params.spacing !== 'pitch';
    $('#count').value = params.count;
    $('#slide').value = params.slide;
    $('#slide-out').textContent = Number(params.slide).toFixed(2);
    $('#angle').value = params.angle == null ? '' : params.angle;
    $('#leaf').value = params.leaf || 'tab';
    $('#invert').checked = params.invert;
    $('#invert-text').textContent = coreDefaults ? coreDefaults.invert[params.kind] : 'Invert';
    $('#labels-on').checked = params.labels !== false;
    $$('.start').forEach(function (row) {
      var s = params.start[Number(row.dataset.piece)];
      $('.start-mode', row).value = s.mode;
      $('.start-anchor', row).value = s.anchor; // the number in use: a rejected entry is dropped
      $('.start-anchor', row).classList.remove('invalid');
      delete fieldErrors['anchor' + row.dataset.piece];
      $('.start-anchor', row).hidden = s.mode !== 'anchor';
    });
    $$('.layer-row').forEach(function (row) {
      var l = settings.layers[row.dataset.layer];
      $('.layer-name', row).value = l.name;
      $('.layer-color', row).value = l.color;
    });
    $('#label-size').value = settings.labelSize;
    showUnits();
  }

  function renderMeasure() {
    var tbody = $('#measure-table tbody');
    tbody.innerHTML = '';
    var ms = design ? design.measures : [];
    ms.forEach(function (m, i) {
      var tr = document.createElement('tr');
      var key = selection.pieces.length === 2 ? ['A', 'B'][i] : String(i + 1);
      tr.innerHTML = '<th></th><td class="name"></td><td class="perimeter"></td>';
      tr.children[0].textContent = key;
      tr.children[1].textContent = m.name;
      tr.children[1].title = m.name;
      tr.children[2].textContent = m.ok ? fmt(m.m.perimeter) : '—';
      if (!m.ok) tr.children[2].title = m.error;
      tbody.appendChild(tr);
    });
    var n = selection.pieces.length;
    var text;
    if (!selection.ok) text = selection.error;
    else if (!n) text = host.kind === 'browser' ? 'Open two SVG shapes or pick a sample.' : 'No paths selected.';
    else text = n + (n === 1 ? ' path' : ' paths') + (host.kind === 'browser' ? ' loaded' : ' selected') + (selection.document ? ' · ' + selection.document : '');
    if (selection.candidates && selection.candidates.length) text = selection.candidates.length + (selection.candidates.length === 1 ? ' closed shape' : ' closed shapes') + ' · ' + selection.document;
    if (selection.note) text += ' · ' + selection.note;
    // The picker lists what was skipped, with why; without one the summary says it.
    if (!selection.candidates && selection.skipped && selection.skipped.length) {
      text += ' · skipped: ' + selection.skipped.map(function (s) { return s.name + ' (' + advise(s.reason) + ')'; }).join('; ');
    }
    $('#selection-summary').textContent = text;
    DF.picker.render($('#picker'), selection, { fmt: fmt, advise: advise, choose: function (slot, index) { host.choose(slot, index); } });
    if (ms.length === 2 && ms[0].ok && ms[1].ok) {
      var d = ms[0].m.perimeter - ms[1].m.perimeter;
      var tr2 = document.createElement('tr');
      tr2.className = 'diff';
      tr2.innerHTML = '<th>Δ</th><td class="name">difference</td><td class="perimeter"></td>';
      tr2.children[2].textContent = fmt(Math.abs(d));
      tbody.appendChild(tr2);
    }
  }

  function renderResult() {
    var msg = $('#message');
    var stats = $('#stats');
    var norm = $('#normalize-result');
    norm.textContent = '';
    if (design && design.normalized) {
      var sc = design.normalized.scales;
      norm.textContent = '→ ' + fmt(design.normalized.perimeter) + '  (' + (sc.length === 1 ? '×' + sc[0].toFixed(4) : 'A ×' + sc[0].toFixed(4) + ', B ×' + sc[1].toFixed(4)) + ')';
    }
    var layers = settings.layers;
    var fieldError = Object.keys(fieldErrors).map(function (k) { return fieldErrors[k]; }).join(' ');
    if (design && design.ok && !fieldError) {
      DF.preview.render($('#preview'), design.pieces, layers, settings.labelSize, design.pitch);
      if (design.single) stats.textContent = 'one path → perimeter ' + fmt(design.perimeter) + ' (Apply scales it in place)';
      stats.textContent = design.count + (design.count === 1 ? ' connector' : ' connectors') + ' · pitch ' + fmt(design.pitch) + ' · perimeter ' + fmt(design.perimeter);
      msg.className = 'message' + (design.warnings.length ? ' warning' : '');
      msg.textContent = design.warnings.map(function (w) { return DF.messages.humanize(w, fmt); }).join(' ');
    } else {
      var pieces = selection.pieces.map(function (p, i) { return { key: ['A', 'B', 'C', 'D', 'E', 'F'][i] || String(i + 1), name: p.name, path: p.path }; });
      DF.preview.render($('#preview'), pieces.slice(0, 6), layers, settings.labelSize, 0);
      stats.textContent = '';
      msg.className = 'message' + (fieldError || (design && !design.idle) ? ' error' : '');
      msg.textContent = fieldError || errorText(design);
    }
    $('#apply-btn').disabled = !(design && design.ok) || applying || !!fieldError;
  }

  function recompute() {
    if (pending) return;
    pending = true;
    window.requestAnimationFrame(function () {
      pending = false;
      startingPitch();
      design = DF.design.compute(selection, params);
      renderMeasure();
      renderResult();
      document.body.dataset.state = design.ok ? 'ready' : 'error';
      if (sweeper && sweepKey && sweepKey !== piecesKey(design)) {
        sweepKey = '';
        sweeper.cancel(); // the pieces changed: the curve being sampled is not theirs any more
      }
      if (view === '3d') solve3d();
    });
  }

  function changed() {
    setStatus('', true);
    save();
    syncControls();
    recompute();
  }

  // ---------------------------------------------------------------- events
  function bind() {
    $('#normalize-on').addEventListener('change', function (e) { params.normalize = e.target.checked; changed(); });
    $('#norm-target').addEventListener('change', function (e) {
      params.target = e.target.value;
      if (params.target === 'exact' && !(params.exact > 0) && design && design.measures[0] && design.measures[0].ok) {
        params.exact = design.measures[0].m.perimeter;
      }
      changed();
    });
    $('#norm-pivot').addEventListener('change', function (e) { params.pivot = e.target.value; changed(); });
    $$('#kind button').forEach(function (b) {
      b.addEventListener('click', function () { params.kind = b.dataset.kind; changed(); });
    });
    $('#spacing').addEventListener('change', function (e) { params.spacing = e.target.value; changed(); });
    $('#count').addEventListener('input', function (e) {
      var v = Number(e.target.value);
      e.target.classList.toggle('invalid', !(v >= 1 && v === Math.round(v)));
      if (v >= 1 && v === Math.round(v)) { params.count = v; save(); recompute(); }
    });
    $('#slide').addEventListener('input', function (e) {
      params.slide = Number(e.target.value);
      $('#slide-out').textContent = params.slide.toFixed(2);
      save();
      recompute();
    });
    $('#angle').addEventListener('input', function (e) {
      var v = Number(e.target.value);
      var ok = v > 0 && v < 180; // the flank against the edge: 90° square, more a dovetail
      e.target.classList.toggle('invalid', !ok);
      if (ok) { params.angle = v; save(); recompute(); }
    });
    $('#invert').addEventListener('change', function (e) { params.invert = e.target.checked; changed(); });
    $('#leaf').addEventListener('change', function (e) { params.leaf = e.target.value; changed(); });
    $('#labels-on').addEventListener('change', function (e) { params.labels = e.target.checked; changed(); });
    $$('input.len').forEach(function (input) {
      var spec = LEN[input.dataset.len];
      input.addEventListener('input', function () {
        var auto = AUTO[input.dataset.len] && input.value.trim() === '';
        var v = auto ? 0 : DF.units.parse(input.value, unit);
        var zeroOk = auto || input.dataset.len === 'kerf' || input.dataset.len === 'allowance';
        var ok = isFinite(v) && v >= spec.min && !(spec.min === 0 && v === 0 && !zeroOk);
        input.classList.toggle('invalid', !ok);
        if (ok) {
          spec.set(v);
          save();
          recompute();
        }
      });
      input.addEventListener('change', function () { showUnits(); });
      input.addEventListener('keydown', function (e) {
        if (e.key !== 'ArrowUp' && e.key !== 'ArrowDown') return;
        var step = DF.units.toPoints(e.shiftKey ? 10 : unit === 'mm' ? 0.1 : unit === 'in' ? 0.01 : 1, unit);
        var v = spec.get() + (e.key === 'ArrowUp' ? step : -step);
        if (v >= spec.min) { spec.set(v); input.value = lenText(v); save(); recompute(); }
        e.preventDefault();
      });
    });
    $$('.start').forEach(function (row) {
      $('.start-mode', row).addEventListener('change', function (e) { params.start[Number(row.dataset.piece)].mode = e.target.value; changed(); });
      var i = Number(row.dataset.piece);
      $('.start-anchor', row).addEventListener('input', function (e) {
        var v = Number(e.target.value);
        var ok = e.target.value !== '' && v >= 1 && v === Math.round(v);
        e.target.classList.toggle('invalid', !ok);
        if (ok) {
          delete fieldErrors['anchor' + i];
          params.start[i].anchor = v;
          save();
        } else {
          var piece = selection.pieces[i];
          var n = piece && piece.path ? piece.path.points.length : 0;
          fieldErrors['anchor' + i] = 'Anchor # for piece ' + ['A', 'B'][i] + ' must be a whole number' + (n ? ' from 1 to ' + n + '.' : ', 1 or more.');
        }
        recompute();
      });
      // Leaving the field: it shows the number in use again.
      $('.start-anchor', row).addEventListener('change', function (e) {
        if (!fieldErrors['anchor' + i]) return;
        delete fieldErrors['anchor' + i];
        e.target.value = params.start[i].anchor;
        e.target.classList.remove('invalid');
        recompute();
      });
    });
    $$('.layer-row').forEach(function (row) {
      var l = function () { return settings.layers[row.dataset.layer]; };
      $('.layer-color', row).addEventListener('input', function (e) { l().color = e.target.value; save(); recompute(); });
      $('.layer-name', row).addEventListener('change', function (e) { if (e.target.value.trim()) { l().name = e.target.value.trim(); save(); } });
    });
    $('#label-size').addEventListener('input', function (e) {
      var v = Number(e.target.value);
      if (v > 0) { settings.labelSize = v; save(); recompute(); }
    });
    $('#layers-reset').addEventListener('click', function () {
      var d = DF.settings.defaults();
      settings.layers = d.layers;
      settings.labelSize = d.labelSize;
      changed();
    });
    $('#refresh-btn').addEventListener('click', function () { host.refresh(); });
    $('#apply-btn').addEventListener('click', apply);
    window.addEventListener('resize', function () {
      recompute();
      if (viewer) viewer.draw();
      renderSweep();
    });
  }

  function bindBrowser() {
    $('#browser-bar').hidden = false;
    $('#apply-btn').textContent = 'Download SVG';
    $('#refresh-btn').hidden = true;
    $$('.cep-only').forEach(function (o) { o.remove(); });
    var select = $('#sample-select');
    DF.samples.forEach(function (s) {
      var o = document.createElement('option');
      o.value = s.id;
      o.textContent = s.name;
      select.appendChild(o);
    });
    select.addEventListener('change', function () {
      if (select.value) openDesign(host.useSample(select.value), select.value);
      else select.value = loadedSample; // "—" unloads nothing: the menu keeps naming what is loaded
    });
    $('#open-btn').addEventListener('click', function () { $('#open-input').click(); });
    $('#open-input').addEventListener('change', function (e) {
      var files = e.target.files;
      if (!files || !files.length) return;
      openDesign(host.openFiles(files), '');
      e.target.value = '';
    });
    $('#unit-select').addEventListener('change', function (e) {
      settings.unit = e.target.value; // remembered: the next files and sessions use it
      save();
      host.setUnit(e.target.value);
    });
    document.addEventListener('dragover', function (e) { e.preventDefault(); });
    document.addEventListener('drop', function (e) {
      e.preventDefault();
      if (e.dataTransfer && e.dataTransfer.files.length) openDesign(host.openFiles(e.dataTransfer.files), '');
    });
  }
  /**
   * A sample or files being opened (`opening`, the host's promise). The host replaces the design
   * only when everything was read, so the Sample menu changes only then: on success it shows
   * `menuValue` (the sample, or "—" for files); on failure the previous design is still loaded and
   * the menu goes back to naming it.
   */
  function openDesign(opening, menuValue) {
    return opening.then(function () {
      setStatus('', true); // "Downloaded …" was about the design just replaced
      loadedSample = menuValue;
      $('#sample-select').value = menuValue;
    }, function (e) {
      $('#sample-select').value = loadedSample;
      showError(e);
    });
  }

  // ---------------------------------------------------------------- 3D form
  function volumeText(v) {
    var perUnit = DF.units.PER_UNIT[unit];
    var litres = (v * Math.pow(25.4 / 72, 3)) / 1e6;
    var inUnits = v / Math.pow(perUnit, 3);
    return 'Volume ' + inUnits.toLocaleString('en-US', { maximumFractionDigits: inUnits < 100 ? 3 : 0 }) + ' ' + unit + '³ (' +
      // Three significant digits: a student's form is often 0.01–0.1 L, where fixed decimals read 0.0196 L as "0.02".
      litres.toLocaleString('en-US', litres < 100 ? { maximumSignificantDigits: 3 } : { maximumFractionDigits: 1 }) + ' L)';
  }
  function areaText(a) {
    var inUnits = a / Math.pow(DF.units.PER_UNIT[unit], 2);
    return 'area ' + inUnits.toLocaleString('en-US', { maximumFractionDigits: inUnits < 100 ? 3 : 0 }) + ' ' + unit + '²';
  }
  function showFigures() {
    var el = $('#cast3d');
    figures = null;
    el.textContent = '';
    var form = interim || mesh;
    if (!form) return;
    try {
      figures = DF.core.formFigures(form, { mmPerUnit: 25.4 / 72, density: settings.density });
      el.textContent = DF.form3d.castText(figures, fmt);
    } catch (e) {
      el.textContent = e.message;
    }
  }
  /** Holes, numbers and start marks of the design `d` on the form solved for it (or its first look). */
  function showMarks(d) {
    var form = interim || mesh;
    if (viewer && form && d && d.pieces) viewer.setMarks(DF.form3d.marksOnForm(d.pieces, form));
  }
  function piecesKey(d) {
    return d && d.ok ? JSON.stringify(d.pieces.map(function (p) { return p.path; })) : '';
  }
  /** The plot under the slider: progress, curves, current offset, the two buttons. */
  function renderSweep() {
    if (!sweeper) return;
    var st = sweeper.state();
    var d = design;
    var current = d && d.ok && st.key && st.key === piecesKey(d) ? d.offset / d.perimeter : null;
    var best = DF.sweepPlot.render($('#sweep-plot'), st, current);
    $('#sweep-progress').value = st.points.length;
    $('#sweep-progress').max = st.count;
    $('#sweep-progress').hidden = !st.running;
    $('#sweep-status').textContent = DF.form3d.sweepText(st, best, fmt);
    $('#sweep-largest').disabled = !best.largest || current === null;
    $('#sweep-tallest').disabled = !best.tallest || current === null;
    showExact();
    document.body.dataset.sweep = st.error ? 'error' : st.done ? 'done' : st.running ? 'running' : '';
  }
  /**
   * Where the form on show is approximate, the sweep under the slider may already know seam
   * offsets whose form is exact (two copies of an organic piece converge at most offsets and
   * fold or stretch at a few): the nearest of them, or null. Only for the pieces on show.
   */
  function nearestExact() {
    if (!sweeper || !mesh || mesh.stats.converged || !design || !design.ok || view !== '3d') return null;
    var st = sweeper.state();
    if (!st.key || st.key !== meshKey || st.key !== piecesKey(design)) return null;
    return DF.sweep.nearest(st.points, meshOffset / design.perimeter);
  }
  /** The "Nearest exact" button and the approximate warning's pointer to it, for the sweep so far. */
  function showExact() {
    var p = nearestExact();
    $('#sweep-exact').disabled = !p;
    var warn = $('#warn3d');
    if (warn.hidden || !mesh) return;
    warn.textContent = approximateText(mesh.stats) + (p ? ' Other seam offsets give an exact form; the nearest found so far is ' +
      fmt(p.offset) + ': Nearest exact, under the plot, moves the slider there.' : '');
  }
  /** Moves the seam offset to arc length `o` (what the slider does, without its 1/1000 steps). */
  function seek(o) {
    if (!design || !design.ok) return;
    var P = design.perimeter;
    // B's start = its anchor-based start + offset; choose the offset so that sB − sA ≡ o.
    var off = (o + design.starts[0].arc - design.starts[1].base) % P;
    params.start[1].offset = off < 0 ? off + P : off;
    save();
    showUnits();
    recompute();
  }

  /**
   * The solver may stop without the real D-form, and says why (stats.shortfall): the pieces would
   * have to stretch (near-square rectangles on a circle, spiky outlines), the sheets pass through
   * each other, both keep their flat shape but one is creased (an L or a drawn heart on a
   * circle: the circle bends sharply along a line), or the seam's samples are too coarse for a
   * tight curve (A's and B's chords between two seam points differ by more than 1e-3). Each gets its own plain words: a creased form
   * is no stretched guess, and telling a student it "stretches up to 0 %" explained nothing. The
   * fold's advice is what the core's tests find (simulate_nonconvex.rs,
   * test_issue_14_a_shallower_bay_avoids_the_crease_that_rounded_corners_keep): an L whose notch
   * is half its width creases the circle with its corners sharp, and rounded by 2–10 mm it bends
   * by 84–130° depending on the mesh (on either side of the 90° line); with a notch of a quarter,
   * its corners rounded, it does not crease (sharp, it bends by about 90°, on the line).
   */
  function approximateText(st) {
    var tail = ' OBJ/STL export this approximate shape.';
    if (st.shortfall === 'fold') {
      return '⚠ Approximate preview: both pieces keep their flat shape here, but one is bent sharply, by up to ' +
        (st.maxBend * 180 / Math.PI).toFixed(0) + '°, along a line inside it (drawn in violet, dashed where it is behind the surface), where real material creases. The real D-form will ' +
        'look different there: it may crease, or take a smoother shape the solver did not find. Making a deep inward bay ' +
        '(an L\'s notch, a heart\'s dip) shallower usually avoids it; rounding its corners alone may not.' + tail;
    }
    if (st.shortfall === 'sampling') {
      return '⚠ Approximate preview: the outline turns too tightly somewhere (a corner rounded by a fraction of a millimetre, or the tips of a star) ' +
        'for the preview\'s seam points, which alone force edges up to ' + (st.strainFloor * 100).toFixed(2) + ' % off their ' +
        'flat lengths, more than the 0.1 % a true D-form allows. The shape is close to the real D-form but not exact; ' +
        'rounding the tightest turns a little more gives an exact preview.' + tail;
    }
    if (st.shortfall === 'unsettled') {
      return '⚠ Approximate preview: the solver stopped before this shape settled (after ' + st.iterations + ' steps). The real ' +
        'D-form will look different; the volume and area are rough guesses.' + tail;
    }
    if (st.shortfall === 'crossing') {
      return '⚠ Approximate preview: in the shape the solver found, the two pieces pass through each other, which real ' +
        'material cannot. The real D-form will look different; the volume and area are rough guesses.' + tail;
    }
    return '⚠ Approximate preview: the solver found no form in which both pieces keep their flat shape ' +
      '(they stretch up to ' + (st.maxStrain * 100).toFixed(st.maxStrain < 0.01 ? 2 : 0) + ' % here). The real D-form will look ' +
      'different; the volume and area are rough guesses, and OBJ/STL export this approximate shape (it may not be a clean closed solid).';
  }
  function setApproximate(st) {
    var el = $('#warn3d');
    var approx = !!st && !st.converged;
    el.hidden = !approx;
    el.textContent = approx ? approximateText(st) : '';
    document.body.dataset.approximate = approx ? 'yes' : '';
  }
  function set3dMessage(text, ok, st) {
    var el = $('#stats3d');
    setApproximate(ok ? st : null);
    el.textContent = text;
    el.className = 'stats' + (ok ? '' : ' error-text');
    $('#export-obj').disabled = $('#export-stl').disabled = !ok;
    document.body.dataset.solve = ok ? 'ok' : 'error';
  }
  /**
   * A solve the design has moved on from (the slider was dragged on) is stopped once it has run
   * this long, ms, and the latest design solved instead. Issue 14 gives a non-convex solve 1 s;
   * most take 0.3–0.9 s in WebAssembly and are waited for, so a drag keeps showing forms as it
   * goes. Some take far longer: two copies of the kidney glued at 13/16 of the perimeter
   * or beyond took 4–9 s each in Chromium, and every slider position after one waited for it. The
   * solver thread cannot be interrupted, so it is replaced (DF.solver.cancel).
   */
  var SUPERSEDE_MS = 1000;

  /** Stops the solve under way SUPERSEDE_MS after it started if a newer one is still wanted then;
   *  at once when its first look is on show (the drag has seen this position's form). */
  function supersedeLater() {
    clearTimeout(supersede);
    if (lookedAt) {
      DF.solver.cancel();
      return;
    }
    supersede = setTimeout(function () {
      if (solving && solveAgain) DF.solver.cancel();
    }, Math.max(0, solveStarted + SUPERSEDE_MS - Date.now()));
  }

  /**
   * Solves the 3D form for the current design (on the solver thread when possible). Requests made
   * while a solve runs are coalesced: when it finishes, the latest design is solved, warm-started
   * from the last solution of the same pieces when the offset moved only a little. A solve that
   * is no longer wanted is stopped after SUPERSEDE_MS; the form on show stays until the new one
   * replaces it. A long non-convex solve shows its first look (the core's `interim`: the form at
   * half the seam points, converged, usually within 0.2 % of the final volume) as soon as it is
   * there, often seconds before the result, and a drag moves on from it at once.
   */
  function solve3d() {
    if (!viewer) viewer = DF.view3d.create($('#view3d'));
    if (solving) {
      solveAgain = true;
      supersedeLater();
      return;
    }
    if (!DF.core.has('simulate')) {
      viewer.setMesh(null);
      return set3dMessage('This build of the geometry core has no simulate(): rebuild it to see the 3D form.', false);
    }
    if (!design || !design.ok || design.single) {
      if (exportWanted) {
        exportWanted = '';
        setStatus('', true);
      }
      viewer.setMesh(null);
      mesh = null;
      dropInterim();
      showFigures();
      if (sweeper) {
        sweepKey = '';
        sweeper.cancel();
      }
      return set3dMessage(design && design.error ? errorText(design) : host.kind === 'browser' ? browserCountText(0) : 'Select two closed paths.', false);
    }
    var d = design;
    var pieces = d.pieces.map(function (p) { return p.path; });
    var key = JSON.stringify(pieces);
    if (!sweeper) sweeper = DF.sweep.create({ onChange: renderSweep });
    if (DF.core.has('formFigures')) {
      sweepKey = key;
      sweeper.request(key, pieces, d.perimeter);
    }
    renderSweep();
    var options = { offset: d.offset };
    // Warm start only for small steps (a slider drag); a far-away shape is a worse start than none.
    var step = mesh ? Math.abs(d.offset - meshOffset) : Infinity;
    step = Math.min(step, d.perimeter - step);
    if (mesh && meshKey === key && step <= 0.05 * d.perimeter) options.warm = mesh.vertices;
    $('#offset3d').value = String(Math.round((d.offset / d.perimeter) * 1000));
    $('#offset3d-out').textContent = fmt(d.offset);
    solving = true;
    solveStarted = Date.now();
    document.body.dataset.solving = 'yes';
    var stats3d = $('#stats3d');
    stats3d.dataset.progress = '';
    lookedAt = false;
    DF.solver.solve(pieces, options, function (p) {
      // A non-convex pair takes seconds: the share of its stages done, after "solving…".
      stats3d.dataset.progress = Math.round((100 * p.done) / p.total) + ' %';
      if (p.interim) showInterim(p.interim, d);
    }).then(function (result) {
      dropInterim();
      mesh = result;
      meshKey = key;
      meshOffset = d.offset;
      viewer.setMesh(mesh);
      showMarks(d);
      showFigures();
      var st = mesh.stats;
      set3dMessage(volumeText(st.volume) + ' · ' + areaText(st.area) + ' · strain ' + (st.maxStrain * 100).toFixed(2) + ' %' +
        (st.converged ? '' : ' · not converged'), true, st);
      showExact();
    }, function (e) {
      if (e.superseded) return; // the design moved on: its solve follows, the form on show stays
      dropInterim();
      mesh = null;
      viewer.setMesh(null);
      showFigures();
      set3dMessage(e.message, false);
    }).then(function () {
      clearTimeout(supersede);
      solving = false;
      document.body.dataset.solving = '';
      stats3d.dataset.progress = '';
      if (solveAgain && view === '3d') {
        solveAgain = false;
        solve3d();
      } else if (exportWanted) {
        var kind = exportWanted;
        exportWanted = '';
        if (!solveAgain && !pending && document.body.dataset.solve === 'ok') exportWhenSolved(kind);
        else setStatus('', true);
      }
    });
  }
  /** No first look on show any more (a result, an error or no design to solve replaces it). */
  function dropInterim() {
    interim = null;
    document.body.dataset.interim = '';
  }
  /** The first look `form` at the design `d` while its result is solved: drawn with its marks and
   *  figures, worded as such; a newer position already wanted is solved at once. */
  function showInterim(form, d) {
    interim = form;
    lookedAt = true;
    document.body.dataset.interim = 'yes';
    viewer.setMesh(form);
    showMarks(d);
    showFigures();
    setApproximate(null);
    var el = $('#stats3d');
    el.textContent = 'First look: ' + volumeText(form.stats.volume) + ' · ' + areaText(form.stats.area);
    el.className = 'stats';
    if (solveAgain) supersedeLater();
  }
  function showView(which) {
    view = which;
    document.body.dataset.view = which; // a docked panel gives the 3D tab more height (panel.css)
    $$('.tabs button').forEach(function (b) {
      var on = b.dataset.view === which;
      b.classList.toggle('selected', on);
      b.setAttribute('aria-selected', on ? 'true' : 'false');
    });
    $('#preview').style.display = which === '2d' ? '' : 'none';
    $('#pane-3d').hidden = which !== '3d';
    if (which === '3d') solve3d();
  }
  function bind3d() {
    $$('.tabs button').forEach(function (b) {
      b.addEventListener('click', function () { showView(b.dataset.view); });
    });
    $('#offset3d').addEventListener('input', function (e) {
      if (design && design.ok) seek((Number(e.target.value) / 1000) * design.perimeter);
    });
    $('#sweep-plot').addEventListener('click', function (e) {
      if (design && design.ok) seek(DF.sweepPlot.fractionAt($('#sweep-plot'), e.clientX) * design.perimeter);
    });
    $('#sweep-exact').addEventListener('click', function () {
      var p = nearestExact();
      if (p) seek(p.offset);
    });
    [['#sweep-largest', 'volume'], ['#sweep-tallest', 'height']].forEach(function (b) {
      $(b[0]).addEventListener('click', function () {
        var p = sweeper && DF.sweep.best(sweeper.state().points, b[1]);
        if (p) seek(p.offset);
      });
    });
    $('#density').value = settings.density;
    $('#density').addEventListener('input', function (e) {
      var v = Number(e.target.value);
      var ok = e.target.value !== '' && v > 0 && isFinite(v);
      e.target.classList.toggle('invalid', !ok);
      if (!ok) return;
      settings.density = v;
      save();
      showFigures();
    });
    // Meshes are always written in millimetres, whatever unit the panel shows: STL has no unit and
    // slicers read it as mm; OBJ has none either and CAD/CAM tools assume mm (the header says mm).
    var toMm = 1 / DF.units.PER_UNIT.mm;
    function exportNow(kind) {
      if (!mesh) return;
      if (kind === 'obj') host.saveText('d-form-mm.obj', DF.view3d.toObj(mesh, toMm, 'mm'), 'model/obj').then(report3d, showError);
      else host.saveText('d-form-mm.stl', DF.view3d.toStl(mesh, toMm), 'model/stl').then(report3d, showError);
    }
    // While the form for the slider's position is still being solved, the mesh on hand is an
    // earlier position's: export the one the slider shows as soon as it is there.
    exportWhenSolved = exportNow;
    function exportClicked(kind) {
      if (solving || pending) {
        exportWanted = kind;
        setStatus('Exporting ' + kind.toUpperCase() + ' as soon as the form for this seam offset is solved…', true);
        return;
      }
      exportNow(kind);
    }
    $('#export-obj').addEventListener('click', function () { exportClicked('obj'); });
    $('#export-stl').addEventListener('click', function () { exportClicked('stl'); });
  }
  function report3d(r) {
    var approx = mesh && mesh.stats && !mesh.stats.converged;
    if (r && r.message) setStatus(r.message + ' Mesh in millimetres.' + (approx ? ' It is the approximate preview shape, not the real D-form.' : ''), true);
  }

  /** The outcome of Apply / exports: stays until the next change the user makes. */
  function setStatus(text, ok) {
    var el = $('#status');
    el.className = 'message ' + (ok ? 'success' : 'error');
    el.textContent = text || '';
  }

  function showError(e) {
    setStatus(advise(e && e.message ? e.message : String(e)), false);
  }

  function apply() {
    // Recompute from the current selection and parameters: never write a stale preview.
    var fresh = DF.design.compute(selection, params);
    design = fresh;
    if (!fresh.ok) {
      renderResult();
      return Promise.resolve();
    }
    applying = true;
    $('#apply-btn').disabled = true;
    var plan = DF.design.plan(fresh, params, settings, selection.document);
    return host.apply(plan).then(function (r) {
      applying = false;
      setStatus(r.ok ? r.message : r.error, r.ok);
      $('#apply-btn').disabled = false;
      document.body.dataset.applied = r.ok ? 'ok' : 'error';
    }, function (e) {
      applying = false;
      setStatus(e && e.message ? e.message : String(e), false);
      $('#apply-btn').disabled = false;
      document.body.dataset.applied = 'error';
    });
  }

  function onSelection(sel) {
    selection = sel;
    if (sel.units && sel.units !== unit) {
      unit = sel.units;
      if (host.kind === 'browser') $('#unit-select').value = unit;
      showUnits();
    }
    recompute();
  }

  function start() {
    host = window.__adobe_cep__ ? DF.createCepHost(new DF.CSInterface(window.__adobe_cep__)) : DF.createBrowserHost(window);
    document.body.dataset.host = host.kind;
    applyTheme(host.theme());
    bind();
    bind3d();
    if (host.kind === 'browser') bindBrowser();
    if (host.kind === 'browser' && settings.unit) host.setUnit(settings.unit);
    syncControls();
    DF.core.load().then(function () {
      applyCoreDefaults();
      $('#version').textContent = DF.core.version() ? 'D-former ' + DF.core.version() : '';
      return host.start({ selection: onSelection, theme: applyTheme });
    }).then(function () {
      // The browser app opens on the first sample, so there is something to look at right away.
      if (host.kind === 'browser' && !selection.pieces.length && DF.samples.length) {
        $('#sample-select').value = DF.samples[0].id;
        return host.useSample(DF.samples[0].id).then(function () { loadedSample = DF.samples[0].id; });
      }
      return null;
    }).then(function () {
      document.body.dataset.core = 'loaded';
    }, function (e) {
      showError(e);
      document.body.dataset.core = 'error';
    });
  }

  DF.app = {
    start: start, params: function () { return params; }, design: function () { return design; }, mesh: function () { return mesh; }, interim: function () { return interim; },
    sweep: function () { return sweeper ? sweeper.state() : null; }, figures: function () { return figures; },
    marks: function () { return viewer ? viewer.marks() : null; },
  };
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})(window.DF = window.DF || {});
