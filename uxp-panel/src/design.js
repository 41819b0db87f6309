/* D-former panel: the design pipeline — measure → normalize → connect — as one pure computation
 * over the host's selection and the panel's parameters (lengths in points). Nothing here writes:
 * Apply only ever sends a design that computed without error. Host-agnostic. */
(function (DF) {
  'use strict';
  var KEYS = ['A', 'B'];

  function named(piece, e) {
    return new Error('Path “' + piece.name + '”: ' + (e && e.message ? e.message : String(e)));
  }

  /** Measures every selected path; a path the core refuses carries its message instead. */
  function measureAll(pieces) {
    return pieces.map(function (p) {
      try {
        return { name: p.name, ok: true, m: DF.core.measure(p.path) };
      } catch (e) {
        return { name: p.name, ok: false, error: e.message };
      }
    });
  }

  /**
   * Arc length where a piece's connector 0 sits, in the core's convention: measured from the
   * path's first anchor along the piece's WALK (A counter-clockwise, B clockwise, y up; the core
   * reverses a path drawn the other way, still starting at anchor 0). So anchor k of a path drawn
   * against its walk lies at P − (length to k along the drawing). `offset` runs along the walk.
   */
  function startArc(piece, path, perimeter, spec, index, orientation) {
    var key = KEYS[index];
    var k = 0;
    if (spec.mode === 'selected') {
      if (piece.allSelected || !piece.selectedAnchors || !piece.selectedAnchors.length) {
        throw new Error('Piece ' + key + ' (“' + piece.name + '”): no single anchor is selected. Select one anchor with the Direct Selection tool (A), or choose another start.');
      }
      k = piece.selectedAnchors[0];
    } else if (spec.mode === 'anchor') {
      k = Math.round(spec.anchor) - 1;
      if (!(k >= 0 && k < path.points.length)) {
        throw new Error('Piece ' + key + ' has ' + path.points.length + ' anchors; start anchor ' + spec.anchor + ' does not exist.');
      }
    }
    var along = DF.core.lengthToAnchor(path, k);
    var walkCcw = index === 0;
    var base = (orientation === 'ccw') === walkCcw ? along : along === 0 ? 0 : perimeter - along;
    var s = (base + (spec.offset || 0)) % perimeter;
    return { anchor: k, base: base, arc: s < 0 ? s + perimeter : s };
  }

  /**
   * The core's connect options from the panel's parameters. Only what the user set is sent: sizes
   * left automatic (0), the count and angle left to the core (null), and — when both pieces start
   * at their first anchor with no offset and no slide — the start and slide, so the core places the
   * connectors clear of the corners (see `connect` in core/src/connect/phase.rs).
   */
  function connectOptions(params, start, auto) {
    var o = { kind: params.kind, invert: !!params.invert, kerf: params.kerf };
    if (!auto) {
      o.slide = params.slide;
      o.start = start;
    }
    if (params.spacing === 'pitch') o.pitch = params.pitch;
    else if (params.count != null) o.count = Math.round(params.count);
    if (params.kind === 'stitch' || params.kind === 'hybrid') {
      if (params.inset > 0) o.inset = params.inset;
      if (params.diameter > 0) o.diameter = params.diameter;
    }
    if (params.kind !== 'stitch' && params.length > 0) o.length = params.length;
    if ((params.kind === 'teeth' || params.kind === 'hybrid') && params.angle != null) o.angle = params.angle;
    if (params.kind === 'leaves') o.leaf = params.leaf || 'tab';
    if ((params.kind === 'stitch' || params.kind === 'leaves') && params.allowance > 0) o.allowance = params.allowance;
    if (params.labels === false) o.labels = false;
    return o;
  }

  /** One path with an exact target: Normalize alone scales it (Apply updates it in place). */
  function computeSingle(pieces, params, out) {
    var p = pieces[0];
    var n = DF.core.normalize([p.path], { target: params.exact, pivot: params.pivot });
    out.normalized = n;
    out.single = true;
    out.perimeter = n.perimeter;
    out.count = 0;
    out.pitch = 0;
    out.pieces = [{ key: 'A', id: p.id, name: p.name, path: n.paths[0], scale: n.scales[0], outline: n.paths[0], holes: [], slots: [], labels: [], marks: [] }];
    out.ok = true;
    return out;
  }

  /**
   * selection: { pieces: [{ id, name, path, selectedAnchors, allSelected }] }; params: see app.js.
   * Returns { ok, error?, measures, normalized?, perimeter?, pieces?, count?, pitch?, warnings }.
   */
  function compute(selection, params) {
    var pieces = selection.pieces || [];
    var out = { ok: false, measures: measureAll(pieces), warnings: [] };
    if (pieces.length === 1 && params.normalize && params.target === 'exact' && params.exact > 0 && out.measures[0].ok) {
      try {
        return computeSingle(pieces, params, out);
      } catch (e) {
        out.error = e && e.message ? e.message : String(e);
        return out;
      }
    }
    if (pieces.length !== 2) {
      // Illustrator's wording; `pieceCount` lets a host with no selection say it its own way.
      out.pieceCount = pieces.length;
      out.error = !pieces.length ? 'Select two closed paths.' : pieces.length === 1 ? 'Select a second closed path: a D-form joins two pieces.' : pieces.length + ' paths are selected; select exactly two.';
      out.idle = pieces.length <= 1;
      return out;
    }
    try {
      var bad = out.measures.filter(function (m) { return !m.ok; })[0];
      if (bad) throw new Error('Path “' + bad.name + '”: ' + bad.error);
      var paths = pieces.map(function (p) { return p.path; });
      var perims = out.measures.map(function (m) { return m.m.perimeter; });
      if (params.normalize) {
        var target = params.target === 'exact' ? params.exact : params.target;
        if (params.target === 'exact' && !(target > 0)) throw new Error('Enter the exact perimeter to normalize to.');
        var n = DF.core.normalize(paths, { target: target, pivot: params.pivot });
        out.normalized = n;
        paths = n.paths;
        perims = [n.perimeter, n.perimeter];
      }
      out.perimeter = perims[0];
      var starts = pieces.map(function (p, i) {
        return startArc(p, paths[i], perims[i], params.start[i], i, out.measures[i].m.orientation);
      });
      var auto = !params.slide && params.start.every(function (s) { return s.mode === 'first' && !s.offset; });
      var result = DF.core.connect(paths, connectOptions(params, [starts[0].arc, starts[1].arc], auto));
      out.starts = starts;
      // simulate() pairs A(t) with B(offset + t): the seam offset matching these connectors.
      var off = (starts[1].arc - starts[0].arc) % out.perimeter;
      out.offset = off < 0 ? off + out.perimeter : off;
      out.count = result.count;
      out.pitch = result.pitch;
      out.warnings = result.warnings || [];
      out.pieces = pieces.map(function (p, i) {
        var r = result.pieces[i];
        return {
          key: KEYS[i],
          id: p.id,
          name: p.name,
          path: paths[i],
          scale: out.normalized ? out.normalized.scales[i] : 1,
          startAnchor: starts[i].anchor,
          outline: r.outline,
          seam: r.seam,
          slots: r.slots || [],
          holes: r.holes || [],
          labels: r.labels || [],
          marks: r.marks || [],
        };
      });
      out.ok = true;
    } catch (e) {
      out.error = e && e.message ? e.message : String(e);
    }
    return out;
  }

  /** What Apply writes: updated outlines, then per piece its connectors, marks and labels. */
  function plan(design, params, settings, documentName) {
    return {
      document: documentName,
      updates: design.normalized
        ? design.pieces.map(function (p) { return { id: p.id, path: p.path }; })
        : [],
      pieces: design.single ? [] : design.pieces.map(function (p) {
        // Numbers at the panel's size, or smaller where the core found less room.
        var labels = params.labels === false ? [] : p.labels.map(function (l) {
          return { text: l.text, at: l.at, angle: l.angle, size: l.size > 0 ? Math.max(0.1, Math.min(l.size, settings.labelSize)) : settings.labelSize };
        });
        var piece = { id: p.id, name: 'piece ' + p.key, holes: p.holes, slots: p.slots, labels: labels, marks: p.marks };
        // With a seam allowance the outline is the cut line and the seam line goes to the score layer.
        if (params.kind !== 'stitch' || p.seam) piece.outline = p.outline;
        if (p.seam) piece.seam = p.seam;
        return piece;
      }),
      layers: settings.layers,
      labelSize: settings.labelSize,
      design: design,
    };
  }

  DF.design = { compute: compute, plan: plan, measureAll: measureAll, connectOptions: connectOptions, named: named };
})(window.DF = window.DF || {});
