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
 * Selection = { ok, error?, document, units, pieces: [{ id, name, path, selectedAnchors, allSelected }], skipped, note }
 *
 * ExtendScript runs on Illustrator's main thread (CEP 12 Cookbook, "evalScript … runs in host
 * application's main thread"), so the selection poll is cheap and bounded (the bridge reads the
 * geometry of two paths at most), and it runs only while the panel is shown
 * (com.adobe.csxs.events.panelWindowStatusChanged, which Illustrator sends to its persistent panels)
 * and a document is open. Every evalScript has a timeout (a lost callback must not stop polling and
 * Apply forever), and when the engine has lost the bridge's functions (CEP-Resources issue 39: the
 * manifest's ScriptPath is loaded only at panel start-up) the bridge is reloaded with $.evalFile from
 * the extension folder. Scripts sent to Illustrator are plain ASCII (\uXXXX escapes). */
(function (DF) {
  'use strict';
  var DEFAULTS = { pollMs: 400, timeoutMs: 10000, applyTimeoutMs: 120000 };
  var PANEL_STATUS_EVENT = 'com.adobe.csxs.events.panelWindowStatusChanged';
  var EVAL_ERROR = 'EvalScript error.';
  var TIMEOUT = {};

  /** Every character outside printable ASCII (accents, U+2028/9, controls) as a \uXXXX escape, so no
   * text encoding between CEP and ExtendScript can change the script (bolt-cep issues 137, 159). */
  function ascii(text) {
    return text.replace(/[^\x20-\x7e]/g, function (c) {
      return '\\u' + ('000' + c.charCodeAt(0).toString(16)).slice(-4);
    });
  }
  /** A value as an ExtendScript expression: JSON text, strictly escaped to ASCII, is an ES3 object
   * (or string) literal, which ExtendScript parses natively instead of the bridge's ES3 JSON loop. */
  function scriptLiteral(value) {
    return ascii(JSON.stringify(value));
  }
  function parseReply(text, what) {
    try {
      return JSON.parse(text);
    } catch (notJson) {
      void notJson;
      return { ok: false, error: 'Unexpected answer from Illustrator to ' + what + ': ' + String(text).slice(0, 120) };
    }
  }
  function lostBridge(text) {
    return text === EVAL_ERROR || text === undefined || text === null || text === '';
  }

  function createCepHost(cs, options) {
    var o = {};
    Object.keys(DEFAULTS).forEach(function (k) {
      o[k] = options && options[k] !== undefined ? options[k] : DEFAULTS[k];
    });
    var listener = null;
    var lastKey = null;
    var timer = null;
    var busy = false;
    var started = false;
    var visible = true;
    var hasDocument = true;

    /** evalScript that always settles: the answer, or TIMEOUT after `ms` (a later answer is dropped). */
    function evalWithin(script, ms) {
      return new Promise(function (resolve) {
        var done = false;
        var t = setTimeout(function () {
          if (!done) {
            done = true;
            resolve(TIMEOUT);
          }
        }, ms);
        cs.evalScript(script, function (text) {
          if (done) return;
          done = true;
          clearTimeout(t);
          resolve(text);
        });
      });
    }
    function timedOut(what, ms) {
      return { ok: false, timeout: true, error: 'Illustrator did not answer ' + what + ' within ' + Math.round(ms / 1000) + ' s (it may be busy); D-former will try again.' };
    }
    function bridgeFile() {
      var root = cs.getSystemPath ? cs.getSystemPath('extension') : '';
      return root ? root.replace(/[\\/]+$/, '') + '/jsx/dformer-bridge.jsx' : '';
    }
    /** Reload the bridge into the ExtendScript engine with $.evalFile (what ScriptPath did at start-up). */
    function reload(ms) {
      var file = bridgeFile();
      var failed = { ok: false, error: 'Illustrator lost the D-former script bridge' + (file ? ' and reloading ' + file + ' failed' : '') + ': reinstall the extension.' };
      if (!file) return Promise.resolve(failed);
      return evalWithin('$.evalFile(' + scriptLiteral(file) + '); typeof dformer_info', ms).then(function (t) {
        return t === 'function' ? { ok: true } : failed;
      });
    }
    function call(script, what, ms) {
      ms = ms || o.timeoutMs;
      return evalWithin(script, ms).then(function (text) {
        if (text === TIMEOUT) return timedOut(what, ms);
        if (!lostBridge(text)) return parseReply(text, what);
        return reload(ms).then(function (loaded) {
          if (!loaded.ok) return loaded;
          return evalWithin(script, ms).then(function (again) {
            if (again === TIMEOUT) return timedOut(what, ms);
            return lostBridge(again) ? { ok: false, error: 'Illustrator did not answer ' + what + ': the D-former script bridge is not loaded (reinstall the extension).' } : parseReply(again, what);
          });
        });
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
        if (!r.ok) return { ok: false, error: r.error, timeout: !!r.timeout, pieces: [], units: 'pt', skipped: [] };
        if (r.more) {
          // The bridge sends no geometry beyond two paths (a Select All would stall Illustrator).
          return { ok: false, error: 'More than two paths (or more than 500 objects) are selected: select exactly two closed paths (a D-form joins two pieces).', document: r.document, pieces: [], units: DF.units.known(r.units), skipped: [] };
        }
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
    /** Poll only while the panel is shown and a document is open. */
    function schedule() {
      var want = started && visible && hasDocument;
      if (want && timer === null) timer = setInterval(poll, o.pollMs);
      if (!want && timer !== null) {
        clearInterval(timer);
        timer = null;
      }
    }
    /** Cheap poll of the selection fingerprint; the full read only when it changes. */
    function poll() {
      if (busy) return Promise.resolve();
      busy = true;
      return call('dformer_selectionKey()', 'the selection check')
        .then(function (r) {
          if (r.timeout) return null; // keep the last state; the next poll asks again
          if (r.ok && r.hasDocument === false && hasDocument) {
            hasDocument = false; // resumes on documentAfterActivate, when the panel is shown again, or Refresh
            schedule();
          }
          var key = r.ok ? r.key : 'error:' + r.error;
          if (key !== lastKey) {
            lastKey = key;
            return refresh().then(function (sel) {
              if (sel.timeout) lastKey = null; // the read itself timed out: read again on the next poll
            });
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
    /** Something changed outside the panel: read again now and poll again. */
    function wake() {
      hasDocument = true;
      lastKey = null;
      schedule();
      return poll();
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
        started = true;
        cs.addEventListener(DF.CSInterface.THEME_COLOR_CHANGED_EVENT, function () {
          if (listener) listener.theme(theme());
        });
        ['documentAfterActivate', 'documentAfterDeactivate'].forEach(function (type) {
          cs.addEventListener(type, wake);
        });
        cs.addEventListener(PANEL_STATUS_EVENT, function (e) {
          // data "false": the student closed or collapsed the panel; "true": it is shown again.
          visible = String(e && e.data).replace(/^\s+|\s+$/g, '') !== 'false';
          if (visible) wake();
          else schedule();
        });
        schedule();
        return poll();
      },
      stop: function () {
        started = false;
        schedule();
      },
      refresh: function () {
        return wake();
      },
      /** Whether the selection poll is running (tests). */
      polling: function () {
        return timer !== null;
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
        return call('dformer_apply(' + scriptLiteral(payload) + ')', 'Apply', o.applyTimeoutMs).then(function (r) {
          lastKey = null; // our own write changes the selection fingerprint; re-read it
          if (r.timeout) return { ok: false, error: 'Illustrator has not answered Apply for ' + Math.round(o.applyTimeoutMs / 1000) + ' s. It may still be writing: check the document (Edit > Undo) before you apply again.' };
          if (!r.ok) return { ok: false, error: r.error };
          return { ok: true, message: 'Updated ' + r.updated + ' path(s), created ' + r.created + ' item(s) on ' + (r.layers || []).join(', ') + '.' };
        });
      },
    };
  }
  DF.createCepHost = createCepHost;
  DF.cepScript = { ascii: ascii, literal: scriptLiteral };
})(window.DF = window.DF || {});
