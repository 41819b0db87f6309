/* D-former panel: runs the core's `simulate` off the UI thread, so dragging the seam-offset slider
 * never freezes the panel. A classic worker script (CEP 8 has no module workers); it loads the same
 * bundled core as the page. Messages: { id, pieces, options } → { id, ok, result | error }; with
 * `op: 'figures'` (the seam-offset sweep, sweep.js) the result is only the form's figures
 * (DF.sweepPoint: volume, height, … of `simulate` + `formFigures`), not the whole mesh. With
 * `progress: true` a solve also posts { id, progress: { done, total, maxStrain } } after each
 * stage of a non-convex pair's solve (the core's `simulateWithProgress`). */
/* global dformerWasm, importScripts */
'use strict';
// The one-file browser app (uxp-panel/tools/single-html.mjs) starts this worker from a Blob of its
// own text with the core's glue and sweep-point.js before it, and posts the WASM bytes
// ({ op: 'wasm', base64 }) as its first message: a page opened from file:// may start such a
// worker but not one from a file, and the bytes are in the page already.
if (typeof self.dformerWasm === 'undefined') {
  importScripts('../wasm/dformer.js', 'sweep-point.js');
  try {
    importScripts('../wasm/dformer-wasm-inline.js');
  } catch (missing) {
    void missing; // not built with inline bytes: fetch the .wasm instead
  }
}

function base64Bytes(b64) {
  var bin = atob(b64);
  var bytes = new Uint8Array(bin.length);
  for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  return bytes;
}

var bytesFromPage = null;
var ready = self.DFORMER_WASM_FROM_PAGE
  ? new Promise(function (resolve) { bytesFromPage = resolve; }).then(function (b64) {
    return dformerWasm.default({ module_or_path: base64Bytes(b64) });
  })
  : dformerWasm.default({
    module_or_path: self.DFORMER_WASM_BASE64 ? base64Bytes(self.DFORMER_WASM_BASE64) : '../wasm/dformer_bg.wasm',
  });

self.onmessage = function (e) {
  var job = e.data;
  if (job.op === 'wasm') {
    if (bytesFromPage) bytesFromPage(job.base64);
    return;
  }
  ready.then(
    function () {
      var result;
      try {
        if (job.op === 'figures') result = self.DF.sweepPoint(dformerWasm, job.pieces, job.options, job.figures);
        else if (job.progress) {
          result = dformerWasm.simulateWithProgress(job.pieces, job.options, function (p) {
            self.postMessage({ id: job.id, progress: p });
          });
        } else result = dformerWasm.simulate(job.pieces, job.options);
      } catch (err) {
        self.postMessage({ id: job.id, ok: false, error: err && err.message ? err.message : String(err) });
        return;
      }
      self.postMessage({ id: job.id, ok: true, result: result });
    },
    function (err) {
      self.postMessage({ id: job.id, ok: false, error: 'The geometry core did not load in the solver thread: ' + err.message });
    }
  );
};
