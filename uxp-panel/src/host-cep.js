/* D-former panel: the CEP host — the ONLY module that talks to Illustrator.
 * Document access goes through ExtendScript (illustrator-scripts/dformer-bridge.jsx, loaded by the
 * manifest's <ScriptPath>); every bridge call returns a JSON string, documented in
 * illustrator-scripts/BRIDGE.md. Coordinates are document points, y up.
 *
 * Host interface (shared with host-browser.js; a future UXP host implements the same):
 *   kind, capabilities { document, openFiles, samples, download }
 *   start(listener)          listener.selection(sel) on every selection change, listener.theme(theme)
 *   refresh()                re-reads the selection now
 *   apply(plan)              Promise<{ ok, error?, message }>; plan = { document, updates, pieces, layers, labelSize }
 *   theme()                  { background: [r,g,b], dark: bool }
 *   saveText(name, text, type)  Promise<{ ok, message }>: save an export (OBJ, STL)
 * Selection = { ok, error?, document, units, pieces: [{ id, name, path, selectedAnchors, allSelected }], skipped, note } */
(function (DF) {
  'use strict';
  var POLL_MS = 400;

  function parseReply(text, what) {
    if (text === 'EvalScript error.' || text === undefined || text === null || text === '') {
      return { ok: false, error: 'Illustrator did not answer ' + what + ': the D-former script bridge is not loaded (reinstall the extension).' };
    }
    try {
      return JSON.parse(text);
    } catch (notJson) {
      void notJson;
      return { ok: false, error: 'Unexpected answer from Illustrator to ' + what + ': ' + String(text).slice(0, 120) };
    }
  }
  /** A JSON payload as an ExtendScript string literal (JSON is a valid ES3 string literal once U+2028/9 are escaped). */
  function scriptString(value) {
    return JSON.stringify(JSON.stringify(value)).replace(/\u2028/g, '\\u2028').replace(/\u2029/g, '\\u2029');
  }

  function createCepHost(cs) {
    var listener = null;
    var lastKey = null;
    var timer = null;
    var busy = false;

    function call(script, what) {
      return cs.evalScriptAsync(script).then(function (text) {
        return parseReply(text, what);
      });
    }
    function theme() {
      var env = cs.getHostEnvironment();
      var c = env && env.appSkinInfo && env.appSkinInfo.panelBackgroundColor && env.appSkinInfo.panelBackgroundColor.color;
      var rgb = c ? [Math.round(c.red), Math.round(c.green), Math.round(c.blue)] : [83, 83, 83];
      var luminance = (0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]) / 255;
      return { background: rgb, dark: luminance < 0.5 };
    }
    function readSelection() {
      return call('dformer_selection()', 'the selection request').then(function (r) {
        if (!r.ok) return { ok: false, error: r.error, pieces: [], units: 'pt', skipped: [] };
        return {
          ok: true,
          document: r.document,
          units: DF.units.known(r.units),
          pieces: (r.items || []).map(function (it) {
            return { id: it.id, name: it.name, path: it.path, selectedAnchors: it.selectedAnchors || [], allSelected: !!it.allSelected };
          }),
          skipped: r.skipped || [],
          // A Print (CMYK) document would change the laser colours; the bridge refuses Apply there
          // (illustrator-scripts/BRIDGE.md, "Colour mode"), so say so before the student presses it.
          note: r.colorMode === 'CMYK' ? 'CMYK document: switch to File > Document Color Mode > RGB Color before Apply, so the laser colours stay exact' : '',
        };
      });
    }
    function refresh() {
      return readSelection().then(function (sel) {
        if (listener) listener.selection(sel);
        return sel;
      });
    }
    /** Cheap poll of the selection fingerprint; the full read only when it changes. */
    function poll() {
      if (busy) return Promise.resolve();
      busy = true;
      return call('dformer_selectionKey()', 'the selection check')
        .then(function (r) {
          var key = r.ok ? r.key : 'error:' + r.error;
          if (key !== lastKey) {
            lastKey = key;
            return refresh();
          }
          return null;
        })
        .then(
          function () {
            busy = false;
          },
          function () {
            busy = false;
          }
        );
    }
    return {
      kind: 'cep',
      capabilities: { document: true, openFiles: false, samples: false, download: false },
      /** A message in Illustrator's words: its menus for what to do (messages/commands.json). */
      advise: function (text) {
        return DF.commands.render(text, 'illustrator');
      },
      start: function (l) {
        listener = l;
        cs.addEventListener(DF.CSInterface.THEME_COLOR_CHANGED_EVENT, function () {
          if (listener) listener.theme(theme());
        });
        ['documentAfterActivate', 'documentAfterDeactivate'].forEach(function (type) {
          cs.addEventListener(type, function () {
            lastKey = null;
            poll();
          });
        });
        timer = setInterval(poll, POLL_MS);
        return poll();
      },
      stop: function () {
        clearInterval(timer);
      },
      refresh: function () {
        lastKey = null;
        return poll();
      },
      theme: theme,
      /** Saves a text file (3D exports) through CEP's native file API (window.cep.fs, no Node.js needed). */
      saveText: function (name, text) {
        var fs = window.cep && window.cep.fs;
        if (!fs) return Promise.reject(new Error('This CEP version offers no file dialog (window.cep.fs).'));
        var ext = name.split('.').pop();
        var chosen = fs.showSaveDialogEx('Export ' + ext.toUpperCase(), '', [ext], name);
        if (chosen.err || !chosen.data) return Promise.resolve({ ok: false });
        var path = /\.[a-z]+$/i.test(chosen.data) ? chosen.data : chosen.data + '.' + ext;
        var written = fs.writeFile(path, text);
        if (written.err) return Promise.reject(new Error('Could not write ' + path + ' (CEP error ' + written.err + ').'));
        return Promise.resolve({ ok: true, message: 'Saved ' + path + '.' });
      },
      apply: function (plan) {
        var payload = {
          document: plan.document,
          updates: plan.updates,
          pieces: plan.pieces,
          labelSize: plan.labelSize,
          replace: true,
          layers: {},
        };
        ['cut', 'score', 'engrave'].forEach(function (k) {
          var l = plan.layers[k];
          payload.layers[k] = { name: l.name, color: DF.settings.hexToRgb(l.color), width: l.width };
        });
        return call('dformer_apply(' + scriptString(payload) + ')', 'Apply').then(function (r) {
          if (!r.ok) return { ok: false, error: r.error };
          lastKey = null; // our own write changes the selection fingerprint; re-read it
          return { ok: true, message: 'Updated ' + r.updated + ' path(s), created ' + r.created + ' item(s) on ' + (r.layers || []).join(', ') + '.' };
        });
      },
    };
  }
  DF.createCepHost = createCepHost;
})(window.DF = window.DF || {});
