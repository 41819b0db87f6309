/* D-former panel: the 3D view of the glued D-form (the core's `simulate` result), drawn on a 2D
 * canvas: orthographic projection, painter's algorithm (triangles sorted far to near), two-sided
 * Lambert shading, the seam drawn on top. Canvas 2D rather than WebGL so it renders the same in
 * every CEP Chromium and in headless test browsers. Drag to orbit, wheel to zoom. Host-agnostic. */
(function (DF) {
  'use strict';
  var COLORS = [[222, 170, 110], [128, 166, 214]]; // piece A warm, piece B cool
  var LIGHT = normalize3([0.35, -0.45, 0.82]);

  function normalize3(v) {
    var l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) || 1;
    return [v[0] / l, v[1] / l, v[2] / l];
  }

  /** Fills a screen-space triangle (x, y, depth; larger depth = nearer) with a depth test. */
  function fillTriangle(px, depth, W, H, p0, p1, p2, r, g, b) {
    var area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]);
    if (!area) return;
    var minX = Math.max(0, Math.floor(Math.min(p0[0], p1[0], p2[0])));
    var maxX = Math.min(W - 1, Math.ceil(Math.max(p0[0], p1[0], p2[0])));
    var minY = Math.max(0, Math.floor(Math.min(p0[1], p1[1], p2[1])));
    var maxY = Math.min(H - 1, Math.ceil(Math.max(p0[1], p1[1], p2[1])));
    var inv = 1 / area;
    for (var y = minY; y <= maxY; y++) {
      var cy = y + 0.5;
      for (var x = minX; x <= maxX; x++) {
        var cx = x + 0.5;
        var w0 = ((p1[0] - cx) * (p2[1] - cy) - (p1[1] - cy) * (p2[0] - cx)) * inv;
        var w1 = ((p2[0] - cx) * (p0[1] - cy) - (p2[1] - cy) * (p0[0] - cx)) * inv;
        var w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        var z = w0 * p0[2] + w1 * p1[2] + w2 * p2[2];
        var idx = y * W + x;
        if (z <= depth[idx]) continue;
        depth[idx] = z;
        var o = idx * 4;
        px[o] = r;
        px[o + 1] = g;
        px[o + 2] = b;
        px[o + 3] = 255;
      }
    }
  }

  var SEAM_RGB = [192, 24, 42];
  var CREASE_RGB = [112, 32, 168]; // where a non-convex pair's answer creases (result.creases)
  /**
   * A depth-tested line (seam) of the given pixel width, drawn over the surface it lies on; with
   * `dash` (pixels), dashed. A `bias` of Infinity draws it through the surface.
   */
  function line(px, depth, W, H, a, b, bias, width, rgb, dash) {
    var col = rgb || SEAM_RGB;
    var n = Math.ceil(Math.max(Math.abs(b[0] - a[0]), Math.abs(b[1] - a[1]))) + 1;
    var half = width / 2;
    for (var i = 0; i <= n; i++) {
      if (dash && Math.floor(i / dash) % 2) continue;
      var t = i / n;
      var x = a[0] + t * (b[0] - a[0]);
      var y = a[1] + t * (b[1] - a[1]);
      var z = a[2] + t * (b[2] - a[2]) + bias;
      for (var dy = -half; dy <= half; dy++) {
        for (var dx = -half; dx <= half; dx++) {
          var xi = Math.round(x + dx);
          var yi = Math.round(y + dy);
          if (xi < 0 || yi < 0 || xi >= W || yi >= H) continue;
          var idx = yi * W + xi;
          if (z < depth[idx]) continue;
          var o = idx * 4;
          px[o] = col[0];
          px[o + 1] = col[1];
          px[o + 2] = col[2];
          px[o + 3] = 255;
        }
      }
    }
  }

  function create(canvas) {
    var mesh = null;
    var center = [0, 0, 0];
    var radius = 1;
    var yaw = -0.6;
    var pitch = 1.0; // radians from looking straight down the z axis
    var zoom = 1;
    var drag = null;
    var buffer = null;
    var marks = null; // connectors on the form: { holes: [[x, y, z]…], labels: [{ at, text }…], lines: [[[x, y, z]…]…] }

    /** Connectors on the surface (points from the core's placeOnForm), drawn with the next frame. */
    function setMarks(m) {
      marks = m;
      draw();
    }

    function setMesh(result) {
      mesh = result;
      marks = null; // they belonged to the previous mesh
      if (!mesh || !mesh.vertices.length) return draw();
      var lo = [Infinity, Infinity, Infinity];
      var hi = [-Infinity, -Infinity, -Infinity];
      mesh.vertices.forEach(function (v) {
        for (var k = 0; k < 3; k++) {
          lo[k] = Math.min(lo[k], v[k]);
          hi[k] = Math.max(hi[k], v[k]);
        }
      });
      center = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2];
      radius = 0;
      mesh.vertices.forEach(function (v) {
        radius = Math.max(radius, Math.hypot(v[0] - center[0], v[1] - center[1], v[2] - center[2]));
      });
      radius = radius || 1;
      draw();
    }

    /** Model → view: rotate by yaw about z, then tilt by pitch about x. */
    function transform(v) {
      var x = v[0] - center[0];
      var y = v[1] - center[1];
      var z = v[2] - center[2];
      var cy = Math.cos(yaw);
      var sy = Math.sin(yaw);
      var x1 = cy * x - sy * y;
      var y1 = sy * x + cy * y;
      var cp = Math.cos(pitch);
      var sp = Math.sin(pitch);
      return [x1, cp * y1 - sp * z, sp * y1 + cp * z];
    }

    /**
     * Software z-buffer rendering into an ImageData (2× supersampled, then scaled down): correct
     * occlusion for any triangle shape (the solver's long seam-to-seam triangles defeat the
     * painter's algorithm), no dependence on WebGL being available. Flat two-sided Lambert
     * shading; the seam is drawn with a depth test (small bias) so its hidden half stays hidden.
     */
    function draw() {
      var dpr = window.devicePixelRatio || 1;
      var w = canvas.clientWidth;
      var h = canvas.clientHeight;
      if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
        canvas.width = Math.round(w * dpr);
        canvas.height = Math.round(h * dpr);
      }
      var ctx = canvas.getContext('2d');
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      if (!mesh || !mesh.vertices.length || !canvas.width || !canvas.height) return;
      var ss = 2;
      var W = canvas.width * ss;
      var H = canvas.height * ss;
      if (!buffer || buffer.width !== W || buffer.height !== H) {
        buffer = document.createElement('canvas');
        buffer.width = W;
        buffer.height = H;
      }
      var bctx = buffer.getContext('2d');
      var image = bctx.createImageData(W, H);
      var px = image.data;
      var depth = new Float32Array(W * H).fill(-Infinity);
      var s = (0.45 * Math.min(W, H) * zoom) / radius;
      var V = mesh.vertices.map(transform);
      var P = V.map(function (t) { return [W / 2 + s * t[0], H / 2 - s * t[1], t[2]]; });
      mesh.triangles.forEach(function (t, i) {
        var a = V[t[0]];
        var b = V[t[1]];
        var c = V[t[2]];
        var u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        var v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        var n = normalize3([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]);
        var k = 0.35 + 0.65 * Math.abs(n[0] * LIGHT[0] + n[1] * LIGHT[1] + n[2] * LIGHT[2]);
        var col = COLORS[mesh.piece[i] ? 1 : 0];
        fillTriangle(px, depth, W, H, P[t[0]], P[t[1]], P[t[2]], Math.round(col[0] * k), Math.round(col[1] * k), Math.round(col[2] * k));
      });
      if (mesh.seam && mesh.seam.length > 1) {
        var bias = 0.01 * radius;
        for (var j = 0; j < mesh.seam.length; j++) {
          line(px, depth, W, H, P[mesh.seam[j]], P[mesh.seam[(j + 1) % mesh.seam.length]], bias, 2 * ss);
        }
      }
      // Creases: dashed through the surface (a crease is often on the far piece), solid where seen.
      (mesh.creases || []).forEach(function (c) {
        var a = P[c.vertices[0]];
        var b = P[c.vertices[1]];
        line(px, depth, W, H, a, b, Infinity, 2 * ss, CREASE_RGB, 3 * ss);
        line(px, depth, W, H, a, b, 0.01 * radius, 3 * ss, CREASE_RGB);
      });
      var labels = marks ? drawMarks(px, depth, W, H, P, s, ss) : [];
      bctx.putImageData(image, 0, 0);
      ctx.imageSmoothingEnabled = true;
      ctx.drawImage(buffer, 0, 0, canvas.width, canvas.height);
      ctx.fillStyle = 'rgb(20,20,20)';
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      ctx.font = Math.round(10 * dpr) + 'px sans-serif';
      labels.forEach(function (l) { ctx.fillText(l.text, l.x / ss, l.y / ss); });
    }

    /** Screen position (x, y, depth) of a model point, as for the mesh's vertices. */
    function toScreen(v, W, H, s) {
      var t = transform(v);
      return [W / 2 + s * t[0], H / 2 - s * t[1], t[2]];
    }
    /** Holes (dark dots) and start marks (lines) depth-tested into the image; returns the labels
     * whose anchor is visible (not behind the surface), in buffer pixels, to write as text. */
    function drawMarks(px, depth, W, H, P, s, ss) {
      var bias = 0.02 * radius;
      var visible = function (p) {
        var xi = Math.round(p[0]);
        var yi = Math.round(p[1]);
        return xi >= 0 && yi >= 0 && xi < W && yi < H && p[2] + bias >= depth[yi * W + xi];
      };
      (marks.lines || []).forEach(function (pts) {
        for (var i = 0; i + 1 < pts.length; i++) line(px, depth, W, H, toScreen(pts[i], W, H, s), toScreen(pts[i + 1], W, H, s), bias, 1.5 * ss, [30, 60, 200]);
      });
      (marks.holes || []).forEach(function (v) {
        var p = toScreen(v, W, H, s);
        line(px, depth, W, H, p, p, bias, 3 * ss, [25, 25, 25]);
      });
      return (marks.labels || []).map(function (l) {
        var p = toScreen(l.at, W, H, s);
        return visible(p) ? { text: l.text, x: p[0], y: p[1] } : null;
      }).filter(Boolean);
    }

    canvas.addEventListener('pointerdown', function (e) {
      drag = { x: e.clientX, y: e.clientY, yaw: yaw, pitch: pitch };
      if (canvas.setPointerCapture) canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener('pointermove', function (e) {
      if (!drag) return;
      yaw = drag.yaw + (e.clientX - drag.x) * 0.01;
      pitch = Math.max(-Math.PI, Math.min(Math.PI, drag.pitch + (e.clientY - drag.y) * 0.01));
      draw();
    });
    function end() {
      drag = null;
    }
    canvas.addEventListener('pointerup', end);
    canvas.addEventListener('pointercancel', end);
    canvas.addEventListener('wheel', function (e) {
      zoom = Math.max(0.2, Math.min(8, zoom * Math.exp(-e.deltaY * 0.001)));
      draw();
      e.preventDefault();
    });
    return {
      setMesh: setMesh,
      setMarks: setMarks,
      marks: function () { return marks; },
      draw: draw,
      view: function () { return { yaw: yaw, pitch: pitch, zoom: zoom }; },
    };
  }

  /** Wavefront OBJ of the mesh (vertices scaled by `scale`, e.g. points → mm), one group per piece. */
  function toObj(mesh, scale, unit) {
    var out = ['# D-former D-form mesh, units: ' + unit, 'o d-form'];
    mesh.vertices.forEach(function (v) {
      out.push('v ' + (v[0] * scale).toFixed(6) + ' ' + (v[1] * scale).toFixed(6) + ' ' + (v[2] * scale).toFixed(6));
    });
    [0, 1].forEach(function (p) {
      out.push('g piece_' + (p ? 'B' : 'A'));
      mesh.triangles.forEach(function (t, i) {
        if ((mesh.piece[i] ? 1 : 0) === p) out.push('f ' + (t[0] + 1) + ' ' + (t[1] + 1) + ' ' + (t[2] + 1));
      });
    });
    return out.join('\n') + '\n';
  }

  /** ASCII STL of the mesh (facet normals from the vertex order), scaled by `scale` (the panel writes mm). */
  function toStl(mesh, scale) {
    var out = ['solid d-form'];
    mesh.triangles.forEach(function (t) {
      var a = mesh.vertices[t[0]];
      var b = mesh.vertices[t[1]];
      var c = mesh.vertices[t[2]];
      var u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
      var v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
      var n = normalize3([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]);
      out.push(' facet normal ' + n.map(function (x) { return x.toExponential(6); }).join(' '));
      out.push('  outer loop');
      [a, b, c].forEach(function (p) {
        out.push('   vertex ' + p.map(function (x) { return (x * scale).toExponential(6); }).join(' '));
      });
      out.push('  endloop', ' endfacet');
    });
    out.push('endsolid d-form');
    return out.join('\n') + '\n';
  }

  DF.view3d = { create: create, toObj: toObj, toStl: toStl };
})(window.DF = window.DF || {});
