/* D-former panel: the shape picker — which two of the file's closed shapes are pieces A and B.
 * Shown when the host offers candidates (the browser app: every closed shape of the opened files).
 * Every candidate is drawn where it is in the file, in a small map, and listed with its name (id,
 * Inkscape label) and perimeter; what cannot be a piece is listed as skipped, with why.
 * Choosing: click a shape in the map (it becomes the piece named by the hint, "Next click: piece A",
 * which then alternates; clicking A or B itself makes that the piece the next click replaces), or
 * the A / B radio buttons of the list. Keyboard: Tab to a shape in the map and press Enter or Space,
 * or Tab into the A or B column and move with the arrow keys. Host-agnostic: it only calls
 * `choose(slot, index)` and formats with the functions it is given. */
(function (DF) {
  'use strict';
  var NS = 'http://www.w3.org/2000/svg';
  var SLOTS = ['A', 'B'];
  var next = 0; // the slot the next click on an unchosen shape fills
  var shown = ''; // the candidate set drawn (a new file resets `next`)

  function el(name, attrs, parent, text) {
    var e = name === 'svg' || name === 'g' || name === 'path' || name === 'text' ? document.createElementNS(NS, name) : document.createElement(name);
    Object.keys(attrs || {}).forEach(function (k) { e.setAttribute(k, attrs[k]); });
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  /** How a shape is named: its id, and its Inkscape label when it has another one. */
  function title(c) {
    return c.label && c.label !== c.name ? c.name + ' “' + c.label + '”' : c.name;
  }
  function focusKey(node) {
    return node && node.getAttribute ? node.getAttribute('data-focus') : null;
  }

  /** The map: every candidate at its place in the file, A and B marked; click or Enter to choose. */
  function drawMap(root, candidates, opts) {
    var X = DF.svgExport;
    var svg = el('svg', { id: 'shape-map', class: 'shape-map', role: 'group', 'aria-label': 'The closed shapes of the file: choose a shape to make it piece ' + SLOTS[next] }, root);
    var b = X.boundsOf(candidates.map(function (c) { return c.path; }));
    var size = Math.max(b[2] - b[0], b[3] - b[1]) || 1;
    var pad = 0.04 * size;
    svg.setAttribute('viewBox', [b[0] - pad, b[1] - pad, b[2] - b[0] + 2 * pad, b[3] - b[1] + 2 * pad].join(' '));
    candidates.forEach(function (c) {
      var g = el('g', {
        class: 'cand' + (c.piece ? ' piece-' + c.piece.toLowerCase() : ''),
        'data-index': c.index,
        'data-focus': 'map:' + c.index,
        tabindex: '0',
        role: 'button',
        'aria-label': title(c) + ', ' + opts.fmt(c.perimeter) + (c.piece ? ', piece ' + c.piece : ''),
      }, svg);
      el('title', {}, g, title(c) + (c.piece ? ' — piece ' + c.piece : ''));
      el('path', { d: X.pathD(c.path), 'vector-effect': 'non-scaling-stroke' }, g);
      if (c.piece) {
        var cb = X.boundsOf([c.path]);
        el('text', { x: X.n((cb[0] + cb[2]) / 2), y: X.n((cb[1] + cb[3]) / 2), 'font-size': X.n(0.09 * size), 'text-anchor': 'middle', 'dominant-baseline': 'central' }, g, c.piece);
      }
      function pick() {
        if (c.piece) {
          next = SLOTS.indexOf(c.piece); // the next click replaces this piece
          opts.rerender();
          return;
        }
        var slot = next;
        next = 1 - slot;
        opts.choose(slot, c.index);
      }
      g.addEventListener('click', pick);
      g.addEventListener('keydown', function (e) {
        if (e.key === 'Enter' || e.key === ' ') {
          e.preventDefault();
          pick();
        }
      });
    });
  }

  /** The list: one row per candidate with an A and a B radio button (arrow keys move the choice). */
  function drawList(root, candidates, opts) {
    var table = el('table', { id: 'shape-list', class: 'shape-list' }, root);
    var head = el('tr', {}, el('thead', {}, table));
    el('th', { scope: 'col', title: 'Piece A' }, head, 'A');
    el('th', { scope: 'col', title: 'Piece B' }, head, 'B');
    el('th', { scope: 'col' }, head, 'Shape');
    el('th', { scope: 'col', class: 'perimeter' }, head, 'Perimeter');
    var body = el('tbody', {}, table);
    candidates.forEach(function (c) {
      var tr = el('tr', { 'data-index': c.index, class: c.piece ? 'piece-' + c.piece.toLowerCase() : '' }, body);
      SLOTS.forEach(function (slot, s) {
        var input = el('input', { type: 'radio', name: 'pick-' + slot, value: String(c.index), 'aria-label': title(c) + ' as piece ' + slot, 'data-focus': slot + ':' + c.index }, el('td', {}, tr));
        input.checked = c.piece === slot;
        input.addEventListener('change', function () {
          if (input.checked) opts.choose(s, c.index);
        });
      });
      var name = el('td', { class: 'name', title: title(c) + (c.file ? ' (' + c.file + ')' : '') }, tr, c.name);
      if (c.label && c.label !== c.name) el('span', { class: 'label' }, name, ' “' + c.label + '”');
      el('td', { class: 'perimeter' }, tr, opts.fmt(c.perimeter));
    });
  }

  function drawSkipped(root, skipped, opts) {
    if (!skipped.length) return;
    var box = el('details', { class: 'skipped', id: 'skipped', open: '' }, root);
    el('summary', {}, box, 'Skipped (' + skipped.length + '): not usable as pieces');
    var ul = el('ul', { id: 'skipped-list' }, box);
    skipped.forEach(function (s) {
      var li = el('li', {}, ul);
      el('span', { class: 'name' }, li, s.name);
      el('span', { class: 'reason' }, li, ': ' + opts.advise(s.reason));
    });
  }

  /**
   * Draws the picker for `selection` ({ candidates, skipped, document }) into `root`, or hides it
   * when the host has no candidates. opts: { fmt(points), advise(text), choose(slot, index) }.
   */
  function render(root, selection, opts) {
    var candidates = selection.candidates;
    if (!root) return;
    if (!candidates) {
      root.hidden = true;
      return;
    }
    var key = selection.document + '|' + candidates.map(function (c) { return c.name; }).join('|');
    if (key !== shown) {
      shown = key;
      next = 0;
    }
    var focused = focusKey(document.activeElement);
    var withRerender = Object.assign({}, opts, { rerender: function () { render(root, selection, opts); } });
    while (root.firstChild) root.removeChild(root.firstChild);
    root.hidden = false;
    if (candidates.length) {
      el('p', { class: 'pick-hint', id: 'pick-hint', 'aria-live': 'polite' }, root,
        candidates.length < 2 ? 'Only one closed shape: a D-form needs two.'
          : 'Click a shape or use the list to choose the pieces. Next click: piece ' + SLOTS[next] + '.');
      drawMap(root, candidates, withRerender);
      drawList(root, candidates, withRerender);
    }
    drawSkipped(root, selection.skipped || [], opts);
    if (focused) {
      var again = root.querySelector('[data-focus="' + focused + '"]');
      if (again) again.focus();
    }
  }
  DF.picker = { render: render };
})(window.DF = window.DF || {});
