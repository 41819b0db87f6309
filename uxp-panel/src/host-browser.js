/* D-former panel: the browser host — the ONLY module that touches the browser's files.
 * The "document" is the shapes the user opened (SVG files via DOMParser, see svg-import.js) or a
 * bundled sample set, held in memory in points, y up. Every closed shape is a candidate; the user
 * picks pieces A and B among them (the two with the longest perimeters preselected, as the CLI's
 * `--largest 2`), and they are laid out side by side. "Apply" updates them (normalized outlines) and
 * downloads the laser-ready SVG. Same host interface as host-cep.js, plus `choose` and the
 * selection's `candidates`. Messages name no menu: plain words from the commands table. */
(function (DF) {
  'use strict';
  var GAP = 10 * (72 / 25.4); // 10 mm between pieces

  function createBrowserHost(win) {
    var listener = null;
    // candidates: every closed shape [{ name, id, label, file, path, measure }]; chosen: the
    // candidates' indices of pieces A and B.
    var state = { document: 'No file', unit: 'mm', candidates: [], chosen: [], skipped: [], note: '' };
    var placed = []; // translation of each chosen piece in the side-by-side layout
    var chosenUnit = null; // set by setUnit: the user's choice wins over each file's unit
    var media = win.matchMedia ? win.matchMedia('(prefers-color-scheme: dark)') : null;

    function selection() {
      var chosen = state.chosen.map(function (k) { return state.candidates[k]; });
      var laid = layout(chosen);
      placed = laid.map(function (l) { return l.shift; });
      return {
        ok: true,
        document: state.document,
        units: state.unit,
        pieces: laid.map(function (s, i) {
          return { id: 'shape:' + state.chosen[i], name: s.name, path: s.path, selectedAnchors: [], allSelected: true };
        }),
        candidates: state.candidates.map(function (c, k) {
          return { index: k, name: c.name, id: c.id, label: c.label, file: c.file, path: c.path, perimeter: c.measure.perimeter, piece: ['A', 'B'][state.chosen.indexOf(k)] || '' };
        }),
        skipped: state.skipped,
        note: state.note,
      };
    }
    /** Indices of the `n` candidates with the longest perimeters (ties: larger area, file order), in file order. */
    function largest(candidates, n) {
      return candidates.map(function (c, k) { return k; }).sort(function (i, j) {
        var a = candidates[i].measure;
        var b = candidates[j].measure;
        return b.perimeter - a.perimeter || b.area - a.area || i - j;
      }).slice(0, n).sort(function (i, j) { return i - j; });
    }
    function emit() {
      if (listener) listener.selection(selection());
    }
    /** Places the shapes left to right with GAP between them, tops aligned (exact core bounds). */
    function layout(shapes) {
      var x = 0;
      return shapes.map(function (s) {
        var b = s.measure.bounds;
        var shift = [x - b.min[0], -b.max[1]];
        var moved = DF.core.transformPath(s.path, [1, 0, 0, 1, shift[0], shift[1]]);
        x += b.max[0] - b.min[0] + GAP;
        return { name: s.name, path: moved, shift: shift };
      });
    }
    /** Uses parsed files: every closed shape is a candidate, the two largest become pieces A and B. */
    function useFiles(files) {
      var shapes = [];
      var unit = null;
      var skipped = [];
      var notes = [];
      var right = null; // several files: each file's shapes right of the previous file's, for the picker's map
      files.forEach(function (file) {
        var parsed = DF.svgImport.parse(file.text, file.name);
        if (files.length > 1 && parsed.shapes.length) {
          var left = Math.min.apply(null, parsed.shapes.map(function (s) { return s.measure.bounds.min[0]; }));
          var dx = right === null ? 0 : right + GAP - left;
          parsed.shapes.forEach(function (s) {
            s.path = DF.core.transformPath(s.path, [1, 0, 0, 1, dx, 0]);
            s.measure = DF.core.measure(s.path);
          });
          right = Math.max.apply(null, parsed.shapes.map(function (s) { return s.measure.bounds.max[0]; }));
        }
        unit = unit || parsed.unit;
        skipped = skipped.concat(parsed.skipped || []);
        notes = notes.concat(parsed.notes || []);
        var base = file.name.replace(/\.svg$/i, '');
        parsed.shapes.forEach(function (s) {
          // One shape per file: the file's name says it; several: the shape's own id.
          var name = parsed.shapes.length === 1 && files.length > 1 ? base : s.name;
          shapes.push({ name: name, id: s.id, label: s.label, path: s.path, measure: s.measure, file: file.name });
        });
      });
      // Everything read without error: only now replace the loaded design (a failed open keeps it).
      // A new file resets the choice.
      state.candidates = shapes;
      state.chosen = largest(shapes, 2);
      state.skipped = skipped;
      state.note = notes.join(' ');
      state.unit = chosenUnit || unit || 'mm';
      state.document = files.map(function (f) { return f.name; }).join(' + ');
      emit();
    }
    function readFile(file) {
      return new Promise(function (resolve, reject) {
        var reader = new FileReader();
        reader.onload = function () {
          resolve({ name: file.name, text: String(reader.result) });
        };
        reader.onerror = function () {
          reject(new Error('Could not read ' + file.name + '.'));
        };
        reader.readAsText(file);
      });
    }
    function theme() {
      var dark = !!(media && media.matches);
      return { background: dark ? [50, 50, 50] : [240, 240, 240], dark: dark };
    }
    function download(name, text, type) {
      var blob = new Blob([text], { type: type || 'image/svg+xml' });
      var url = URL.createObjectURL(blob);
      var a = win.document.createElement('a');
      a.href = url;
      a.download = name;
      win.document.body.appendChild(a);
      a.click();
      a.remove();
      setTimeout(function () {
        URL.revokeObjectURL(url);
      }, 1000);
    }
    return {
      kind: 'browser',
      capabilities: { document: false, openFiles: true, samples: true, download: true },
      start: function (l) {
        listener = l;
        if (media && media.addListener) {
          media.addListener(function () {
            if (listener) listener.theme(theme());
          });
        }
        emit();
        return Promise.resolve();
      },
      refresh: function () {
        emit();
        return Promise.resolve();
      },
      theme: theme,
      /** The user's unit: used from now on, also for the next files (which otherwise bring their own). */
      setUnit: function (unit) {
        state.unit = chosenUnit = DF.units.known(unit);
        emit();
      },
      /** Opens SVG files chosen by the user (File objects); rejects with a message naming the file. */
      openFiles: function (fileList) {
        var files = Array.prototype.slice.call(fileList);
        return Promise.all(files.map(readFile)).then(useFiles);
      },
      useSample: function (id) {
        var set = DF.samples.filter(function (s) { return s.id === id; })[0];
        if (!set) return Promise.reject(new Error('Unknown sample "' + id + '".'));
        useFiles(set.files);
        state.document = 'Sample: ' + set.name;
        emit();
        return Promise.resolve();
      },
      /** Makes candidate `index` piece `slot` (0 = A, 1 = B); the shape it replaces there moves to the other slot if it held this one. */
      choose: function (slot, index) {
        if (!(slot === 0 || slot === 1) || !state.candidates[index] || state.candidates.length < 2) return;
        var other = state.chosen.indexOf(index);
        if (other === slot) return;
        if (other >= 0) state.chosen[other] = state.chosen[slot];
        state.chosen[slot] = index;
        emit();
      },
      /** A message in this host's words: plain, no menu of any editor (messages/commands.json). */
      advise: function (text) {
        return DF.commands.render(text, 'plain');
      },
      /** Saves a text file (3D exports): a download. */
      saveText: function (name, text, type) {
        download(name, text, type);
        return Promise.resolve({ ok: true, message: 'Downloaded ' + name + '.' });
      },
      /** Writes the normalized outlines back into the loaded shapes and downloads the laser SVG. */
      apply: function (plan) {
        plan.updates.forEach(function (u) {
          var k = Number(u.id.split(':')[1]);
          var slot = state.chosen.indexOf(k);
          if (!state.candidates[k] || slot < 0) return;
          // Back from the side-by-side layout to where the shape is in the file.
          var path = DF.core.transformPath(u.path, [1, 0, 0, 1, -placed[slot][0], -placed[slot][1]]);
          state.candidates[k].path = path;
          state.candidates[k].measure = DF.core.measure(path);
        });
        var text = DF.svgExport.laserSvg(plan.design, plan.layers, plan.labelSize, state.unit);
        download('d-former-laser.svg', text);
        emit();
        return Promise.resolve({ ok: true, message: 'Downloaded d-former-laser.svg (cut, score and engrave layers).' });
      },
    };
  }
  DF.createBrowserHost = createBrowserHost;
})(window.DF = window.DF || {});
