/* D-former panel: `simulate` on a worker thread (http, CEP, and the one-file app opened from
 * file://), else on the UI thread (the app's folder opened from file://, where Chrome starts no
 * worker from a file). Host-agnostic.
 * solve(pieces, options, onProgress?) → Promise<result>; one job at a time, the caller coalesces
 * requests; cancel() stops the solve under way (on a worker only). channel(here) → run(job,
 * onProgress?): a worker of its own for another kind of job (the seam-offset sweep, sweep.js),
 * `here(job)` → Promise the fallback on this thread. */
(function (DF) {
  'use strict';

  var bundledUrl = null;

  /** A solver worker: from the page's own text of it where the one-file app carries one (a page
   *  opened from file:// may start a worker from a Blob, not from a file; the WASM bytes are
   *  posted from the page), else from src/solver-worker.js. */
  function newWorker() {
    var bundled = document.getElementById('dformer-worker-source');
    if (!bundled || !window.DFORMER_WASM_BASE64) return new Worker('src/solver-worker.js');
    if (!bundledUrl) bundledUrl = URL.createObjectURL(new Blob([bundled.textContent], { type: 'text/javascript' }));
    var w = new Worker(bundledUrl);
    w.postMessage({ op: 'wasm', base64: window.DFORMER_WASM_BASE64 });
    return w;
  }

  function channel(here) {
    var worker = null;
    var failed = false;
    var nextId = 1;
    var waiting = {};

    function start() {
      if (worker || failed || typeof Worker !== 'function') return worker;
      try {
        worker = newWorker();
      } catch (e) {
        void e;
        failed = true;
        return null;
      }
      worker.onmessage = function (e) {
        var job = waiting[e.data.id];
        if (job && e.data.progress) {
          if (job.onProgress) job.onProgress(e.data.progress);
          return;
        }
        delete waiting[e.data.id];
        if (!job) return;
        if (e.data.ok) job.resolve(e.data.result);
        else job.reject(new Error(e.data.error));
      };
      worker.onerror = function (e) {
        // The worker could not load (e.g. file:// security): finish pending jobs on this thread.
        e.preventDefault();
        failed = true;
        worker = null;
        Object.keys(waiting).forEach(function (id) {
          var job = waiting[id];
          delete waiting[id];
          here(job.message).then(job.resolve, job.reject);
        });
      };
      return worker;
    }

    function run(message, onProgress) {
      var w = start();
      if (!w) return here(message);
      return new Promise(function (resolve, reject) {
        var id = nextId++;
        waiting[id] = { resolve: resolve, reject: reject, message: message, onProgress: onProgress };
        w.postMessage(Object.assign({ id: id, progress: !!onProgress }, message));
      });
    }
    run.threaded = function () {
      return !!worker && !failed;
    };
    /* Stops the jobs under way: the worker is terminated (a solve in WebAssembly cannot be
     * interrupted any other way; the next job starts a fresh worker) and each job's promise is
     * rejected with an Error whose `superseded` is true. False when there is nothing to stop: no
     * job under way, or jobs running on this thread, which cannot be interrupted. */
    run.cancel = function () {
      var ids = Object.keys(waiting);
      if (!worker || !ids.length) return false;
      worker.terminate();
      worker = null;
      ids.forEach(function (id) {
        var job = waiting[id];
        delete waiting[id];
        var e = new Error('This solve was stopped: a newer one replaces it.');
        e.superseded = true;
        job.reject(e);
      });
      return true;
    };
    return run;
  }

  var simulateJob = channel(function (job) {
    return new Promise(function (resolve) {
      resolve(DF.core.simulate(job.pieces, job.options));
    });
  });

  DF.solver = {
    /** `onProgress({ done, total, maxStrain })`, optional, hears of each stage of a long solve
     *  (on the worker only: on this thread the page could not repaint anyway). */
    solve: function (pieces, options, onProgress) {
      return simulateJob({ pieces: pieces, options: options }, onProgress);
    },
    channel: channel,
    threaded: function () {
      return simulateJob.threaded();
    },
    /** Stops the solve under way on the worker, if any (its promise rejects with `superseded`);
     *  true when one was stopped. */
    cancel: function () {
      return simulateJob.cancel();
    },
  };
})(window.DF = window.DF || {});
