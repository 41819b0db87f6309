/*
 * D-former - Normalize perimeters (Illustrator File > Scripts; ExtendScript, strict ES3).
 * Scales each selected closed path uniformly about a pivot so that all get the same perimeter:
 * the largest, the smallest, the mean, the first's, or an exact length in ruler units. A single
 * path is scaled to an exact length. The pivot is a point of the bounding box or each path's first
 * anchor, which then stays where it is (as the 2016 Modify Perimeter script did). Arc length
 * scales linearly under a uniform scale, so the factor for a path of length L is target / L
 * (Illustrator's PathItem.length). All factors are computed and checked before the first resize.
 * Self-contained on purpose (see the Measure script for why).
 */
(function () {
  var TITLE = "D-former \u2013 Normalize perimeters";

  /**
   * Ruler unit of a document and how many of it one DOM point is. A Large Canvas document reports
   * every length divided by Document.scaleFactor (10; creold/illustrator-scripts reads it the same
   * way; feature-detected, 1 when absent), so its DOM point is scaleFactor real points.
   * @param {Document} doc @returns {{name: string, perPoint: number, digits: number}}
   */
  function unitsOf(doc) {
    var u = doc.rulerUnits;
    /** @type {*} */
    var sf;
    try { sf = /** @type {*} */ (doc).scaleFactor; } catch (e) { sf = 1; }
    if (typeof sf !== "number" || !isFinite(sf) || !(sf > 0)) sf = 1;
    if (u == RulerUnits.Millimeters || u == RulerUnits.Qs) return { name: "mm", perPoint: sf * 25.4 / 72, digits: 3 };
    if (u == RulerUnits.Centimeters) return { name: "cm", perPoint: sf * 2.54 / 72, digits: 4 };
    if (u == RulerUnits.Inches) return { name: "in", perPoint: sf / 72, digits: 4 };
    if (u == RulerUnits.Picas) return { name: "pc", perPoint: sf / 12, digits: 3 };
    if (u == RulerUnits.Pixels) return { name: "px", perPoint: sf, digits: 2 };
    return { name: "pt", perPoint: sf, digits: 2 };
  }

  /**
   * Selected paths (groups searched, one-sub-path compounds unwrapped) and skipped item names.
   * @param {Document} doc @returns {{paths: Array<PathItem>, skipped: Array<string>}}
   */
  function selectedPaths(doc) {
    /** @type {Array<PathItem>} */
    var paths = [];
    /** @type {Array<string>} */
    var skipped = [];
    /** @param {*} it */
    function visit(it) {
      var label = it.name ? it.name : "<" + it.typename + ">";
      // Hidden or locked art inside a selected group (construction lines, a reference copy) is
      // not an outline to measure or scale, and Illustrator cannot change it.
      if (it.hidden || it.locked) skipped.push(label + (it.hidden ? " (hidden)" : " (locked)"));
      else if (it.typename === "PathItem") {
        if (it.clipping || it.guides || it.pathPoints.length < 2) skipped.push(label);
        else paths.push(it);
      } else if (it.typename === "GroupItem") {
        for (var j = 0; j < it.pageItems.length; j++) visit(it.pageItems[j]);
      } else if (it.typename === "CompoundPathItem" && it.pathItems.length === 1) {
        visit(it.pathItems[0]);
      } else skipped.push(label);
    }
    var sel = doc.selection;
    if (sel && typeof sel.length === "number" && !sel.typename) {
      for (var i = 0; i < sel.length; i++) visit(sel[i]);
    }
    return { paths: paths, skipped: skipped };
  }

  var TARGETS = ["Largest perimeter", "Smallest perimeter", "Mean perimeter", "First path's perimeter", "Exact length"];
  var EXACT = 4;
  var PIVOTS = ["Center", "Top left", "Top", "Top right", "Left", "Right", "Bottom left", "Bottom", "Bottom right",
    "First anchor (stays put)"];
  /** The last pivot, the first anchor, is no Transformation: fit() scales about the centre and moves it back. */
  var START = "start";
  var PIVOT_VALUES = [Transformation.CENTER, Transformation.TOPLEFT, Transformation.TOP, Transformation.TOPRIGHT,
    Transformation.LEFT, Transformation.RIGHT, Transformation.BOTTOMLEFT, Transformation.BOTTOM, Transformation.BOTTOMRIGHT,
    START];

  /**
   * Ask for target and pivot. Returns null when cancelled.
   * @param {string} unitName @param {string} suggested @param {number} first the target shown first
   * @returns {{target: number, exact: string, pivot: number} | null}
   */
  function ask(unitName, suggested, first) {
    var w = new Window("dialog", TITLE);
    w.alignChildren = "fill";
    var g1 = w.add("group");
    g1.add("statictext", undefined, "Make every perimeter equal to:");
    var target = g1.add("dropdownlist", undefined, TARGETS, { name: "target" });
    target.selection = target.items[first];
    var g2 = w.add("group");
    g2.add("statictext", undefined, "Exact length (" + unitName + "):");
    var exact = g2.add("edittext", undefined, suggested, { name: "length" });
    exact.characters = 10;
    var g3 = w.add("group");
    g3.add("statictext", undefined, "Scale about:");
    var pivot = g3.add("dropdownlist", undefined, PIVOTS, { name: "pivot" });
    pivot.selection = pivot.items[0];
    var buttons = w.add("group");
    buttons.alignment = "right";
    buttons.add("button", undefined, "Cancel", { name: "cancel" });
    buttons.add("button", undefined, "OK", { name: "ok" });
    if (w.show() !== 1) return null;
    var t = target.selection;
    var p = pivot.selection;
    return { target: t ? t.index : 0, exact: exact.text, pivot: p ? p.index : 0 };
  }

  /**
   * Run fn in DOCUMENTCOORDINATESYSTEM and put the student's app.coordinateSystem back afterwards,
   * also when fn throws. The setting is global and other scripts often leave it on
   * ARTBOARDCOORDINATESYSTEM (positions relative to the active artboard).
   * @param {function(): void} fn
   */
  function inDocumentCoordinates(fn) {
    /** @type {*} */
    var saved = null;
    if (app.documents.length > 0 && app.coordinateSystem != CoordinateSystem.DOCUMENTCOORDINATESYSTEM) {
      saved = app.coordinateSystem;
      app.coordinateSystem = CoordinateSystem.DOCUMENTCOORDINATESYSTEM;
    }
    try {
      fn();
    } finally {
      if (saved !== null) app.coordinateSystem = saved;
    }
  }

  /** Relative perimeter error above which a path counts as missing the target (Illustrator stores 32-bit floats). */
  var MISS = 1e-6;
  var CORNERS = "policyForPreservingCorners";

  /**
   * Run fn with Illustrator's "Scale Corners" on, and put the student's setting back afterwards.
   * Without it a Live Shape rounded rectangle keeps its corner radius under resize() and misses the
   * target perimeter. The preference is 1 = scale corners, 2 = keep them (creold/illustrator-scripts
   * Rescale and ResizeToSize set it the same way). Feature-detected: older versions have no such
   * preference, and fit() corrects what remains.
   * @param {function(): void} fn
   */
  function withScaledCorners(fn) {
    /** @type {*} */
    var prefs = null;
    var saved = 0;
    try {
      prefs = app.preferences;
      saved = prefs.getIntegerPreference(CORNERS);
      if (saved !== 1) prefs.setIntegerPreference(CORNERS, 1);
    } catch (e) {
      prefs = null;
    }
    try {
      fn();
    } finally {
      if (prefs && saved !== 1) {
        try { prefs.setIntegerPreference(CORNERS, saved); } catch (e2) { /* the student's setting could not be put back */ }
      }
    }
  }

  /**
   * Scale p by pct about pivot, then measure it again (PathItem.length) and correct until it is within
   * 1e-9 of target (at most 6 corrections). Secant steps on the total scale s: a shape that keeps part
   * of itself, such as a Live Shape's corners (length a s - b), is exact after one correction.
   * Returns the final length.
   * @param {PathItem} p @param {number} target @param {number} pct @param {*} pivot @returns {number}
   */
  function fit(p, target, pct, pivot) {
    var s0 = 1, l0 = p.length, s = pct / 100;
    var start = pivot === START ? p.pathPoints[0].anchor : null;
    var about = start ? Transformation.CENTER : pivot;
    /** @param {number} c */
    function scale(c) {
      p.resize(c, c, true, true, true, true, 100, about);
      if (!start) return;
      var moved = p.pathPoints[0].anchor;
      p.translate(start[0] - moved[0], start[1] - moved[1]);
    }
    scale(pct);
    var len = p.length;
    for (var k = 0; k < 6 && Math.abs(len - target) > 1e-9 * target && len > 0; k++) {
      var next = len !== l0 ? s + (target - len) * (s - s0) / (len - l0) : s * target / len;
      if (!(next > 0) || !isFinite(next)) next = s * target / len;
      scale(100 * next / s);
      s0 = s; l0 = len; s = next;
      len = p.length;
    }
    return len;
  }

  inDocumentCoordinates(function () {
    if (app.documents.length === 0) {
      alert("No document is open. Open a document and select the outlines to normalize.", TITLE);
      return;
    }
    var doc = app.activeDocument;
    var units = unitsOf(doc);
    var found = selectedPaths(doc);
    var paths = found.paths;
    if (paths.length < 1) {
      alert("Select two or more closed paths to give them one perimeter, or one to scale it to an exact length (found none)." +
        (found.skipped.length ? "\nNot usable: " + found.skipped.join(", ") + "." : ""), TITLE);
      return;
    }
    var lengths = [];
    for (var i = 0; i < paths.length; i++) {
      var label = paths[i].name ? "\"" + paths[i].name + "\"" : "Path " + (i + 1);
      if (!paths[i].closed) {
        alert(label + " is an open path. A D-form needs closed outlines: close it (Object > Path > Join) or deselect it.", TITLE);
        return;
      }
      var len = paths[i].length;
      if (!(len > 0) || !isFinite(len)) {
        alert(label + " has no length to scale (" + len + " pt).", TITLE);
        return;
      }
      lengths.push(len);
    }
    var sum = 0, min = Infinity, max = -Infinity;
    for (i = 0; i < lengths.length; i++) {
      sum += lengths[i];
      if (lengths[i] < min) min = lengths[i];
      if (lengths[i] > max) max = lengths[i];
    }
    var choice = ask(units.name, (max * units.perPoint).toFixed(units.digits), paths.length === 1 ? EXACT : 0);
    if (choice === null) return;
    if (paths.length === 1 && choice.target !== EXACT) {
      alert("Only one closed path is selected: choose Exact length to scale it to a perimeter, or select two or more " +
        "paths to give them one perimeter. Nothing was changed.", TITLE);
      return;
    }
    var target;
    if (choice.target === 0) target = max;
    else if (choice.target === 1) target = min;
    else if (choice.target === 2) target = sum / lengths.length;
    else if (choice.target === 3) target = lengths[0];
    else {
      var typed = Number(String(choice.exact).replace(/^\s+|\s+$/g, "").replace(",", "."));
      if (!(typed > 0) || !isFinite(typed)) {
        alert("Enter an exact length greater than 0 in " + units.name + " (got \"" + choice.exact + "\"). Nothing was changed.", TITLE);
        return;
      }
      target = typed / units.perPoint;
    }
    var factors = [];
    for (i = 0; i < paths.length; i++) {
      var f = target / lengths[i];
      if (!(f > 0) || !isFinite(f) || f > 1e4 || f < 1e-4) {
        alert("Scaling " + (paths[i].name ? "\"" + paths[i].name + "\"" : "Path " + (i + 1)) + " by " + f.toPrecision(4) +
          " is out of range; choose another target. Nothing was changed.", TITLE);
        return;
      }
      factors.push(f);
    }
    var pivot = PIVOT_VALUES[choice.pivot];
    /** @param {number} points @returns {string} */
    function show(points) {
      return (points * units.perPoint).toFixed(units.digits) + " " + units.name;
    }
    var lines = ["Target perimeter: " + show(target)];
    var missed = [];
    withScaledCorners(function () {
      for (i = 0; i < paths.length; i++) {
        var pct = 100 * factors[i];
        var got = fit(paths[i], target, pct, pivot);
        var name = paths[i].name ? paths[i].name : "Path " + (i + 1);
        lines.push(name + ": " + show(lengths[i]) + " \u2192 " + show(got) + " (scaled " + (100 * got / lengths[i]).toFixed(4) + " %)");
        if (Math.abs(got - target) > MISS * target) missed.push(name + " (" + show(got) + ")");
      }
    });
    if (missed.length) {
      lines.push("Not at the target: " + missed.join(", ") + ". A Live Shape keeps its corner radius when scaled; " +
        "expand it (Object > Shape > Expand Shape) and run the script again, or use Edit > Undo.");
    }
    alert(lines.join("\n"), TITLE);
  });
})();
