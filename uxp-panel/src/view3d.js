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

  function create(canvas) {
    var mesh = null;
    var center = [0, 0, 0];
    var radius = 1;
    var yaw = -0.6;
    var pitch = 1.0; // radians from looking straight down the z axis
    var zoom = 1;
    var drag = null;

    function setMesh(result) {
      mesh = result;
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

    function draw() {
      var dpr = window.devicePixelRatio || 1;
      var w = canvas.clientWidth;
      var h = canvas.clientHeight;
      if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
        canvas.width = Math.round(w * dpr);
        canvas.height = Math.round(h * dpr);
      }
      var ctx = canvas.getContext('2d');
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      ctx.clearRect(0, 0, w, h);
      if (!mesh || !mesh.vertices.length) return;
      var s = (0.45 * Math.min(w, h) * zoom) / radius;
      var P = mesh.vertices.map(function (v) {
        var t = transform(v);
        return [w / 2 + s * t[0], h / 2 - s * t[1], t[2]];
      });
      var V = mesh.vertices.map(transform);
      var order = mesh.triangles.map(function (t, i) {
        return { i: i, depth: V[t[0]][2] + V[t[1]][2] + V[t[2]][2] };
      });
      order.sort(function (a, b) { return a.depth - b.depth; });
      ctx.lineJoin = 'round';
      order.forEach(function (o) {
        var t = mesh.triangles[o.i];
        var a = V[t[0]];
        var b = V[t[1]];
        var c = V[t[2]];
        var u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        var v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        var n = normalize3([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]);
        var lambert = Math.abs(n[0] * LIGHT[0] + n[1] * LIGHT[1] + n[2] * LIGHT[2]);
        var k = 0.35 + 0.65 * lambert;
        var col = COLORS[mesh.piece[o.i] ? 1 : 0];
        var fill = 'rgb(' + Math.round(col[0] * k) + ',' + Math.round(col[1] * k) + ',' + Math.round(col[2] * k) + ')';
        ctx.beginPath();
        ctx.moveTo(P[t[0]][0], P[t[0]][1]);
        ctx.lineTo(P[t[1]][0], P[t[1]][1]);
        ctx.lineTo(P[t[2]][0], P[t[2]][1]);
        ctx.closePath();
        ctx.fillStyle = fill;
        ctx.strokeStyle = fill; // hides hairline gaps between neighbours
        ctx.lineWidth = 0.6;
        ctx.fill();
        ctx.stroke();
      });
      if (mesh.seam && mesh.seam.length > 1) {
        ctx.beginPath();
        mesh.seam.forEach(function (idx, i) {
          if (i === 0) ctx.moveTo(P[idx][0], P[idx][1]);
          else ctx.lineTo(P[idx][0], P[idx][1]);
        });
        ctx.closePath();
        ctx.strokeStyle = '#c0182a';
        ctx.lineWidth = 1.6;
        ctx.stroke();
      }
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

  /** ASCII STL of the mesh (facet normals from the vertex order), scaled by `scale`. */
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
