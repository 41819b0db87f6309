/* D-former panel: the browser host — the ONLY module that touches the browser's files.
 * The "document" is the shapes the user opened (SVG files via DOMParser, see svg-import.js) or a
 * bundled sample set, held in memory in points, y up, laid out side by side. "Apply" updates them
 * (normalized outlines) and downloads the laser-ready SVG. Same host interface as host-cep.js. */
(function (DF) {
  'use strict';
  var GAP = 10 * (72 / 25.4); // 10 mm between pieces

  function createBrowserHost(win) {
    var listener = null;
    var state = { document: 'No file', unit: 'mm', shapes: [], skipped: [], note: '' };
    var chosenUnit = null; // set by setUnit: the user's choice wins over each file's unit
    var media = win.matchMedia ? win.matchMedia('(prefers-color-scheme: dark)') : null;

    function selection() {
      return {
        ok: true,
        document: state.document,
        units: state.unit,
        pieces: state.shapes.map(function (s, i) {
          return { id: 'shape:' + i, name: s.name, path: s.path, selectedAnchors: [], allSelected: true };
        }),
        skipped: state.skipped,
        note: state.note,
      };
    }
    function emit() {
      if (listener) listener.selection(selection());
    }
    /** Places the shapes left to right with GAP between them, tops aligned (exact core bounds). */
    function layout(shapes) {
      var x = 0;
      return shapes.map(function (s) {
        var b;
        try {
          b = DF.core.measure(s.path).bounds;
        } catch (e) {
          // Name the file and the shape: measuring one path, the core calls it "the first path".
          throw new Error(s.file + ', shape “' + s.name + '”: ' + e.message.replace(/^The first path /, 'The path '));
        }
        var moved = DF.core.transformPath(s.path, [1, 0, 0, 1, x - b.min[0], -b.max[1]]);
        x += b.max[0] - b.min[0] + GAP;
        return { name: s.name, path: moved };
      });
    }
    /** Uses parsed files: the first two shapes (in file order) become pieces A and B. */
    function useFiles(files) {
      var shapes = [];
      var unit = null;
      var skipped = [];
      var notes = [];
      files.forEach(function (file) {
        var parsed = DF.svgImport.parse(file.text, file.name);
        unit = unit || parsed.unit;
        skipped = skipped.concat(parsed.skipped || []);
        notes = notes.concat(parsed.notes || []);
        var base = file.name.replace(/\.svg$/i, '');
        parsed.shapes.forEach(function (s) {
          // One shape per file: the file's name says it; several: the shape's own id.
          var name = parsed.shapes.length === 1 && files.length > 1 ? base : s.name;
          shapes.push({ name: name, path: s.path, file: file.name });
        });
      });
      var used = layout(shapes.slice(0, 2));
      // Everything read without error: only now replace the loaded design (a failed open keeps it).
      state.skipped = skipped.concat(shapes.slice(2).map(function (s) {
        return { name: s.name, reason: 'only the first two shapes are used' };
      }));
      state.note = (shapes.length > 2 ? [shapes.length + ' shapes found; using the first two.'] : []).concat(notes).join(' ');
      state.shapes = used;
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
      /** Saves a text file (3D exports): a download. */
      saveText: function (name, text, type) {
        download(name, text, type);
        return Promise.resolve({ ok: true, message: 'Downloaded ' + name + '.' });
      },
      /** Writes the normalized outlines back into the loaded shapes and downloads the laser SVG. */
      apply: function (plan) {
        plan.updates.forEach(function (u) {
          var i = Number(u.id.split(':')[1]);
          if (state.shapes[i]) state.shapes[i].path = u.path;
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
