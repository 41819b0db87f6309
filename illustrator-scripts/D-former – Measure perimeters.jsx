/*
 * D-former - Measure perimeters (Illustrator File > Scripts; ExtendScript, strict ES3).
 * Shows the perimeter of every selected path in the document's ruler units, using Illustrator's
 * own PathItem.length, and how far apart they are. Groups are searched; a compound path with one
 * sub-path counts as that path; everything else is listed as skipped. Changes nothing.
 * Self-contained on purpose (no #include): Illustrator lists every .jsx of its Scripts folder as a
 * menu item, and each script must keep working when copied alone.
 */
(function () {
  var TITLE = "D-former \u2013 Measure perimeters";

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

  inDocumentCoordinates(function () {
    if (app.documents.length === 0) {
      alert("No document is open. Open a document and select the paths to measure.", TITLE);
      return;
    }
    var doc = app.activeDocument;
    var units = unitsOf(doc);
    var found = selectedPaths(doc);
    if (found.paths.length === 0) {
      alert("Select one or more paths first." + (found.skipped.length ? "\nNot paths: " + found.skipped.join(", ") + "." : ""), TITLE);
      return;
    }
    /** @param {number} points @returns {string} */
    function show(points) {
      return (points * units.perPoint).toFixed(units.digits) + " " + units.name;
    }
    var lines = [];
    var min = Infinity, max = -Infinity, closedCount = 0;
    for (var i = 0; i < found.paths.length; i++) {
      var p = found.paths[i];
      var len = p.length;
      lines.push((p.name ? p.name : "Path " + (i + 1)) + ": " + show(len) + (p.closed ? "" : " (open path)"));
      if (p.closed) {
        closedCount++;
        if (len < min) min = len;
        if (len > max) max = len;
      }
    }
    if (closedCount >= 2) {
      var diff = max - min;
      if (diff <= 1e-6 * max) lines.push("The closed outlines have equal perimeters (difference " + show(diff) + ").");
      else lines.push("Difference: " + show(diff) + " (" + (100 * diff / max).toFixed(3) + " %). Run \"D-former \u2013 Normalize perimeters\" to make them equal.");
    }
    if (found.skipped.length) lines.push("Skipped (not paths): " + found.skipped.join(", ") + ".");
    alert(lines.join("\n"), TITLE);
  });
})();
