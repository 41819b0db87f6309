/* D-former panel: runs the core's `simulate` off the UI thread, so dragging the seam-offset slider
 * never freezes the panel. A classic worker script (CEP 8 has no module workers); it loads the same
 * bundled core as the page. Messages: { id, pieces, options } → { id, ok, result | error }; with
 * `op: 'figures'` (the seam-offset sweep, sweep.js) the result is only the form's figures
 * (DF.sweepPoint: volume, height, … of `simulate` + `formFigures`), not the whole mesh. With
 * `progress: true` a solve also posts { id, progress: { done, total, maxStrain } } after each
 * stage of a non-convex pair's solve (the core's `simulateWithProgress`). */
/* global dformerWasm, importScripts */
'use strict';
importScripts('../wasm/dformer.js', 'sweep-point.js');
try {
  importScripts('../wasm/dformer-wasm-inline.js');
} catch (missing) {
  void missing; // not built with inline bytes: fetch the .wasm instead
}

function base64Bytes(b64) {
  var bin = atob(b64);
  var bytes = new Uint8Array(bin.length);
  for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  return bytes;
}

var ready = dformerWasm.default({
  module_or_path: self.DFORMER_WASM_BASE64 ? base64Bytes(self.DFORMER_WASM_BASE64) : '../wasm/dformer_bg.wasm',
});

self.onmessage = function (e) {
  var job = e.data;
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
