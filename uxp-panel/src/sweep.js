/* D-former panel: the seam-offset sweep behind the 3D tab's plot — the form's volume and height at
 * N offsets over one full turn, solved one offset at a time on a worker thread of its own (so the
 * slider's solves never wait behind it), coarse first: every 4th offset of 32, then every 2nd, then
 * the rest, so the curve's shape shows after a quarter of the work. A new set of pieces cancels the
 * sweep (results of the old pieces are dropped, nothing more is queued). When one piece is a
 * circle the offset does not change the form (the first point says so, `offsetFree`): the sweep
 * ends there, every offset a copy of it. Host-agnostic.
 * create({ onChange }) → { request(key, pieces, perimeter), cancel(), state() }. */
(function (DF) {
  'use strict';
  var COUNT = 32;
  var LEVELS = [4, 2, 1]; // offset index steps of the passes: 8, then 16, then 32 offsets
  var MM_PER_PT = 25.4 / 72;

  /** Offset indices 0 … COUNT−1, coarse passes first. */
  function order(count) {
    var out = [];
    LEVELS.forEach(function (step, level) {
      for (var k = 0; k < count; k += step) {
        if (level === 0 || k % LEVELS[level - 1] !== 0) out.push(k);
      }
    });
    return out;
  }

  /** Runs sweep points on a worker of their own (DF.solver.channel); on the page without one. */
  function runner() {
    var job = DF.solver.channel(function (m) {
      return new Promise(function (resolve) {
        // Let the page paint between points when there is no worker.
        window.setTimeout(function () {
          resolve(DF.sweepPoint({ simulate: DF.core.simulate, formFigures: DF.core.formFigures }, m.pieces, m.options, m.figures));
        }, 0);
      });
    });
    return function run(pieces, options, figures) {
      return job({ op: 'figures', pieces: pieces, options: options, figures: figures });
    };
  }

  function create(hooks) {
    var run = runner();
    var gen = 0;
    var st = { key: '', perimeter: 0, count: COUNT, points: [], done: false, running: false, error: '', offsetFree: false };
    var queue = [];
    var pieces = null;

    function changed() {
      if (hooks && hooks.onChange) hooks.onChange(st);
    }
    function next(g) {
      if (g !== gen) return;
      if (!queue.length) {
        st.running = false;
        st.done = true;
        return changed();
      }
      var k = queue.shift();
      var offset = (k / st.count) * st.perimeter;
      run(pieces, { offset: offset }, { mmPerUnit: MM_PER_PT }).then(function (p) {
        if (g !== gen) return; // the pieces changed meanwhile: an old form's figures
        p.index = k;
        p.fraction = k / st.count;
        st.points.push(p);
        if (p.offsetFree) {
          // One piece is a circle: the core gives this very form at every offset, so the other
          // offsets are copies of it and need no solve.
          st.offsetFree = true;
          queue.splice(0).forEach(function (j) {
            st.points.push(Object.assign({}, p, { index: j, fraction: j / st.count, offset: (j / st.count) * st.perimeter }));
          });
        }
        st.points.sort(function (a, b) { return a.index - b.index; });
        changed();
        next(g);
      }, function (e) {
        if (g !== gen) return;
        // Pieces simulate() refuses fail at every offset: say why once, stop.
        st.error = e.message;
        st.running = false;
        changed();
      });
    }
    /** Sweeps `pieces` (key: their identity) unless that sweep is already done or under way. */
    function request(key, newPieces, perimeter) {
      if (key === st.key && (st.running || st.done || st.error)) return;
      gen++;
      pieces = newPieces;
      st = { key: key, perimeter: perimeter, count: COUNT, points: [], done: false, running: true, error: '', offsetFree: false };
      queue = order(COUNT);
      changed();
      next(gen);
    }
    /** Stops the sweep (pieces changed or gone); what was computed is dropped. */
    function cancel() {
      if (!st.key) return;
      gen++;
      queue = [];
      st = { key: '', perimeter: 0, count: COUNT, points: [], done: false, running: false, error: '', offsetFree: false };
      changed();
    }
    return { request: request, cancel: cancel, state: function () { return st; } };
  }

  /** The sampled point with the largest `field` among converged ones (the first on ties). */
  function best(points, field) {
    var out = null;
    points.forEach(function (p) {
      if (p.converged && (!out || p[field] > out[field])) out = p;
    });
    return out;
  }

  /** The converged sampled point nearest to `fraction` of the perimeter, going either way round
   *  the seam (the offset is periodic), or null when none converged. */
  function nearest(points, fraction) {
    var out = null;
    var dist = Infinity;
    points.forEach(function (p) {
      if (!p.converged) return;
      var d = Math.abs(p.fraction - fraction) % 1;
      d = Math.min(d, 1 - d);
      if (d < dist) {
        dist = d;
        out = p;
      }
    });
    return out;
  }

  DF.sweep = { create: create, order: order, best: best, nearest: nearest, COUNT: COUNT };
})(window.DF = window.DF || {});
