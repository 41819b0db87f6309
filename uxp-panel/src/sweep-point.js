/* D-former panel: one point of the seam-offset sweep — the form at one offset reduced to the
 * figures the plot shows. Shared by the page (no worker) and the solver worker (importScripts), so
 * both compute it the same way: `simulate` with exactly the options given (the plot's values are
 * those of a separate `simulate` call), then the core's `formFigures`. */
(function (root) {
  'use strict';
  var DF = (root.DF = root.DF || {});
  /** core: the wasm exports; figuresOptions: { mmPerUnit, density }. */
  DF.sweepPoint = function (core, pieces, options, figuresOptions) {
    var form = core.simulate(pieces, options);
    var f = core.formFigures(form, figuresOptions);
    return {
      offset: options.offset,
      converged: form.stats.converged,
      maxStrain: form.stats.maxStrain,
      volume: f.volume,
      litres: f.litres,
      height: f.height,
      width: f.width,
      depth: f.depth,
      // One piece is a circle: every offset gives this form (the core's simulate/round.rs).
      offsetFree: !!form.stats.offsetFree,
    };
  };
})(typeof self !== 'undefined' ? self : window);
