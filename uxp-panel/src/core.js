/* D-former panel: the WASM geometry core, loaded as a classic script.
 * `wasm/dformer.js` is wasm-bindgen's glue bundled by build.mjs into one classic script (global
 * `dformerWasm`: `default` is the initialiser, the rest the core's functions);
 * the bytes come from `wasm/dformer-wasm-inline.js` (base64, written by build.mjs) so the panel needs
 * neither fetch() of a file:// URL (refused by CEP's Chromium) nor Node.js. Served over http without
 * the inline file, the .wasm is fetched instead. */
(function (DF) {
  'use strict';
  var api = null;
  function glue() {
    var ns = window.dformerWasm;
    return ns && typeof ns.default === 'function' ? ns : null;
  }

  function base64Bytes(b64) {
    var bin = atob(b64);
    var bytes = new Uint8Array(bin.length);
    for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    return bytes;
  }

  /** Loads the module once; resolves to the core's exported functions. */
  function load() {
    if (api) return Promise.resolve(api);
    var ns = glue();
    if (!ns) {
      return Promise.reject(new Error('The geometry core (wasm/dformer.js) is missing: run `node uxp-panel/build.mjs`.'));
    }
    var source = window.DFORMER_WASM_BASE64 ? base64Bytes(window.DFORMER_WASM_BASE64) : 'wasm/dformer_bg.wasm';
    return ns.default({ module_or_path: source }).then(function () {
      api = ns;
      return api;
    });
  }

  /** Calls a core function by its contract name; a missing export becomes a clear error. */
  function call(name, args) {
    if (!api) throw new Error('The geometry core is not loaded yet.');
    if (typeof api[name] !== 'function') throw new Error('This build of the geometry core has no "' + name + '" function; rebuild it.');
    return api[name].apply(null, args);
  }

  // --- Arc length of Bézier segments (for "start at anchor k"): composite 10-point Gauss–Legendre,
  // halving intervals until two levels agree to 1e-12 relative. Only positions the start mark, so
  // it need not match the core bit for bit.
  var GL_X = [0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845, 0.9739065285171717];
  var GL_W = [0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806, 0.0666713443086881];
  function speed(p0, p1, p2, p3, t) {
    var u = 1 - t;
    var dx = 3 * (u * u * (p1[0] - p0[0]) + 2 * u * t * (p2[0] - p1[0]) + t * t * (p3[0] - p2[0]));
    var dy = 3 * (u * u * (p1[1] - p0[1]) + 2 * u * t * (p2[1] - p1[1]) + t * t * (p3[1] - p2[1]));
    return Math.sqrt(dx * dx + dy * dy);
  }
  function glInterval(p, a, b) {
    var m = 0.5 * (a + b);
    var h = 0.5 * (b - a);
    var s = 0;
    for (var i = 0; i < 5; i++) {
      s += GL_W[i] * (speed(p[0], p[1], p[2], p[3], m - h * GL_X[i]) + speed(p[0], p[1], p[2], p[3], m + h * GL_X[i]));
    }
    return s * h;
  }
  function cubicLength(p) {
    var n = 1;
    var prev = glInterval(p, 0, 1);
    for (var level = 0; level < 12; level++) {
      n *= 2;
      var sum = 0;
      for (var k = 0; k < n; k++) sum += glInterval(p, k / n, (k + 1) / n);
      if (Math.abs(sum - prev) <= 1e-12 * Math.max(sum, 1e-300)) return sum;
      prev = sum;
    }
    return prev;
  }
  /** Segment i of a path as four control points (missing handle = corner). */
  function segment(path, i) {
    var pts = path.points;
    var a = pts[i];
    var b = pts[(i + 1) % pts.length];
    return [a.anchor, a.right || a.anchor, b.left || b.anchor, b.anchor];
  }
  /** Arc length from anchor 0 to anchor k along the path's own direction. */
  function lengthToAnchor(path, k) {
    var s = 0;
    for (var i = 0; i < k; i++) s += cubicLength(segment(path, i));
    return s;
  }

  /** Applies the affine map [a, b, c, d, e, f] (x' = a x + c y + e, y' = b x + d y + f) to a path. */
  function transformPath(path, m) {
    function tp(p) {
      return p ? [m[0] * p[0] + m[2] * p[1] + m[4], m[1] * p[0] + m[3] * p[1] + m[5]] : p;
    }
    return {
      closed: path.closed,
      points: path.points.map(function (q) {
        var out = { anchor: tp(q.anchor) };
        if (q.left) out.left = tp(q.left);
        if (q.right) out.right = tp(q.right);
        return out;
      }),
    };
  }

  DF.core = {
    load: load,
    measure: function (path) {
      return call('measure', [path]);
    },
    normalize: function (paths, options) {
      return call('normalize', [paths, options]);
    },
    connect: function (pieces, options) {
      return call('connect', [pieces, options]);
    },
    simulate: function (pieces, options) {
      return call('simulate', [pieces, options]);
    },
    formFigures: function (form, options) {
      return call('formFigures', [form, options]);
    },
    placeOnForm: function (form, points) {
      return call('placeOnForm', [form, points]);
    },
    /** The default connector options and how each is derived (the core's; no host keeps its own). */
    defaults: function () {
      return call('defaults', []);
    },
    /** The core's version (the workspace Cargo.toml's), or '' from a build without it. */
    version: function () {
      return api && typeof api.version === 'function' ? api.version() : '';
    },
    has: function (name) {
      return !!api && typeof api[name] === 'function';
    },
    pathFromSvg: function (d) {
      return call('pathFromSvg', [d]);
    },
    pathToSvg: function (path) {
      return call('pathToSvg', [path]);
    },
    cubicLength: cubicLength,
    lengthToAnchor: lengthToAnchor,
    transformPath: transformPath,
  };
})(window.DF = window.DF || {});
