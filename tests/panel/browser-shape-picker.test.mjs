// The shape picker of the browser app on drawings written the way real editors write them
// (tests/fixtures/drawings, shared with the CLI's tests): every closed shape is drawn and listed
// with its name and perimeter (checked against closed forms computed here), what cannot be a piece
// is listed as skipped with why, the two longest are preselected, and the user picks A and B by
// clicking a shape or with the keyboard; the choice survives option changes, not a new file.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { measureRows, openApp, openSvgFiles, repo, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const fixture = (name) => [name, readFileSync(join(repo, 'tests', 'fixtures', 'drawings', name), 'utf8')];
const mm = (x) => `${x.toFixed(2)} mm`;
const PT = 25.4 / 72; // Illustrator's SVG px is a point
const polygon = (pts) => pts.reduce((s, p, i) => s + Math.hypot(pts[(i + 1) % pts.length][0] - p[0], pts[(i + 1) % pts.length][1] - p[1]), 0);
// The Inkscape 0.92 star from its sodipodi parameters: 28 edges between radius 30 and 14, π/14 apart.
const STAR = 28 * Math.sqrt(30 * 30 + 14 * 14 - 2 * 30 * 14 * Math.cos(Math.PI / 14));

/** The picker's list: [{ name, perimeter, a, b }] (a/b: the radio of that piece is checked). */
function listRows(page) {
  return page.$$eval('#shape-list tbody tr', (trs) => trs.map((tr) => ({
    name: tr.querySelector('.name').textContent,
    perimeter: tr.querySelector('.perimeter').textContent,
    a: tr.querySelector('input[name="pick-A"]').checked,
    b: tr.querySelector('input[name="pick-B"]').checked,
  })));
}
const skippedItems = (page) => page.$$eval('#skipped-list li', (lis) => lis.map((li) => li.textContent));
const pieces = async (page) => (await measureRows(page)).map((r) => `${r.key} ${r.name}`);
/** Waits until the measure table shows these pieces (["A name", "B name"]). */
function piecesBecome(page, want) {
  return page.waitForFunction((w) => JSON.stringify([...document.querySelectorAll('#measure-table tr:not(.diff)')]
    .map((tr) => tr.children[0].textContent + ' ' + tr.children[1].textContent)) === JSON.stringify(w), want);
}

async function open(page, name) {
  await openSvgFiles(page, [fixture(name)]);
  await waitReady(page);
}

test('Inkscape 0.92 drawing with stray strokes: three closed shapes offered, the open ones and the text skipped with why', async () => {
  const page = await openApp(panel);
  await open(page, 'inkscape-092.svg');
  assert.equal(await page.textContent('#status'), '', 'no error for the file');
  assert.deepEqual(await listRows(page), [
    { name: 'rect10', perimeter: mm(200), a: true, b: false },
    { name: 'path12 “Disc”', perimeter: mm(2 * Math.PI * 25), a: false, b: false },
    { name: 'path14', perimeter: mm(STAR), a: false, b: true },
  ]);
  assert.equal(await page.$$eval('#shape-map .cand', (c) => c.length), 3, 'every closed shape is drawn');
  const stroke = 'an open path (a stroke): a piece must be a closed outline, so close the path to use it';
  assert.deepEqual(await skippedItems(page), [`path16: ${stroke}`, `path9: ${stroke}`, `path1: ${stroke}`,
    'text20: text, not an outline: convert it to a path to use it as a piece']);
  // The two longest are preselected, in file order.
  assert.deepEqual(await pieces(page), ['A rect10', 'B path14']);
  assert.match(await page.textContent('#selection-summary'), /^3 closed shapes · inkscape-092\.svg/);
  await page.close();
});

test('click a shape: it becomes the piece the hint names; the choice survives option changes and a new file resets it', async () => {
  const page = await openApp(panel);
  await open(page, 'inkscape-092.svg');
  assert.match(await page.textContent('#pick-hint'), /Next click: piece A/);
  await page.click('#shape-map .cand[data-index="1"]'); // the disc
  await piecesBecome(page, ['A path12', 'B path14']);
  assert.match(await page.textContent('#pick-hint'), /Next click: piece B/);
  await page.click('#shape-map .cand[data-index="0"]'); // the rectangle, as B
  await piecesBecome(page, ['A path12', 'B rect10']);
  // Perimeters shown for the chosen pair, against the closed forms.
  assert.deepEqual((await measureRows(page)).map((r) => r.perimeter), [mm(2 * Math.PI * 25), mm(200)]);
  // Clicking piece A makes A the one the next click replaces.
  await page.click('#shape-map .cand[data-index="1"]');
  assert.match(await page.textContent('#pick-hint'), /Next click: piece A/);
  await page.click('#shape-map .cand[data-index="2"]');
  await piecesBecome(page, ['A path14', 'B rect10']);

  // Options change: the pieces stay.
  await page.fill('#count', '10');
  await page.waitForFunction(() => /^10 connectors/.test(document.querySelector('#stats').textContent));
  await page.selectOption('#unit-select', 'cm');
  await page.waitForFunction(() => /cm/.test(document.querySelector('#units-badge').textContent));
  assert.deepEqual(await pieces(page), ['A path14', 'B rect10']);

  // Another file: its own two longest.
  await open(page, 'compound.svg');
  assert.deepEqual(await pieces(page), ['A frame', 'B plate']);
  assert.match(await page.textContent('#pick-hint'), /Next click: piece A/);
  await page.close();
});

test('keyboard: arrow keys move piece A through the list, Enter on a shape in the map chooses it', async () => {
  const page = await openApp(panel);
  await open(page, 'inkscape-092.svg');
  await page.focus('#shape-list input[name="pick-A"]:checked');
  await page.keyboard.press('ArrowDown'); // A: rect10 → path12
  await piecesBecome(page, ['A path12', 'B path14']);
  // Focus stays on the radio just chosen, so the arrows keep working.
  assert.equal(await page.evaluate(() => document.activeElement.getAttribute('data-focus')), 'A:1');
  await page.keyboard.press('ArrowDown'); // A: path12 → path14, which was B: they swap
  await piecesBecome(page, ['A path14', 'B path12']);

  // The map is in the tab order: Tab to a shape, Enter.
  await page.focus('#shape-map .cand[data-index="0"]');
  await page.keyboard.press('Enter'); // rect10 → piece A (the hint's slot)
  await piecesBecome(page, ['A rect10', 'B path12']);
  assert.equal(await page.evaluate(() => document.activeElement.getAttribute('data-focus')), 'map:0');
  assert.equal(await page.getAttribute('#shape-map .cand[data-index="0"]', 'aria-label'), `rect10, ${mm(200)}, piece A`);
  await page.close();
});

test('Inkscape 1.x drawing: a hidden layer is not offered; rounded rect, circle, ellipse, relative path, rotated group', async () => {
  const page = await openApp(panel);
  await open(page, 'inkscape-1x.svg');
  // The ellipse by 400 000 chords of (15 cos t, 10 sin t).
  let ellipse = 0;
  const n = 400000;
  for (let k = 0; k < n; k++) {
    const [t0, t1] = [(2 * Math.PI * k) / n, (2 * Math.PI * (k + 1)) / n];
    ellipse += Math.hypot(15 * (Math.cos(t1) - Math.cos(t0)), 10 * (Math.sin(t1) - Math.sin(t0)));
  }
  const rows = await listRows(page);
  assert.deepEqual(rows.map((r) => [r.name, r.perimeter]), [
    ['rect846 “Body”', mm(2 * (50 + 30) - 8 * 5 + 2 * Math.PI * 5)],
    ['path1010', mm(2 * Math.PI * 20)],
    ['path1012', mm(ellipse)],
    ['path2044 “Petal”', mm(polygon([[30, 80], [70, 80], [80, 100], [50, 125], [20, 110]]))],
    ['path300', mm(140)],
  ]);
  assert.deepEqual((await skippedItems(page)).map((s) => s.split(':')[0]), ['path3000', 'path3001', 'image77']);
  assert.match((await skippedItems(page))[2], /an image, not an outline/);
  await page.close();
});

test('Illustrator export: <style> classes, <polygon>, <rect> with a transform, <circle>, a scaled group; open <polyline> and <line> skipped', async () => {
  const page = await openApp(panel);
  const [name, text] = fixture('illustrator-export.svg');
  await open(page, name);
  const pts = /points="([^"]+)"/.exec(text)[1].split(' ').map(Number);
  const hexagon = polygon(pts.reduce((a, v, i) => (i % 2 ? a : a.concat([[v, pts[i + 1]]])), []));
  assert.deepEqual((await listRows(page)).map((r) => [r.name, r.perimeter]), [
    ['Hexagon', mm(hexagon * PT)],
    ['<rect>', mm(2 * (141.73 + 85.04) * PT)],
    ['<circle>', mm(2 * Math.PI * 56.69 * PT)],
    ['Small_panel', mm(0.8 * 300 * PT)],
  ]);
  assert.deepEqual((await skippedItems(page)).map((s) => s.split(': ')[0]), ['<polyline>', '<line>']);
  assert.deepEqual(await pieces(page), ['A Hexagon', 'B <rect>']);
  await page.close();
});

test('compound paths: an outline with a hole is offered (outer outline), side-by-side outlines and a bow tie are skipped', async () => {
  const page = await openApp(panel);
  await open(page, 'compound.svg');
  assert.deepEqual((await listRows(page)).map((r) => [r.name, r.perimeter]), [
    ['frame “Frame”', mm(320)],
    // Two arcs of radius 40 over a 60 mm chord: each spans 2·asin(30/40).
    ['lens', mm(2 * 40 * 2 * Math.asin(0.75))],
    ['plate', mm(200)],
  ]);
  const skipped = await skippedItems(page);
  assert.equal(skipped[0], 'twins: a compound path of 2 separate outlines: split it into separate shapes');
  assert.match(skipped[1], /^bow: The path crosses itself/);
  assert.equal(skipped.length, 2);
  assert.match(await page.textContent('#selection-summary'), /frame” is a compound path: its outer outline is used, its hole is ignored/);
  await page.close();
});
