// The browser app speaks the browser's and the panel's language: with one shape it says to open a
// file with two shapes (not Illustrator's "select a second path"); the core's "first piece" /
// "second piece" are the A and B the panel shows everywhere; one connector is singular.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openApp, openSvgFiles, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();

test('a file with one shape: open a file with two closed shapes (no "Select")', async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['one.svg', '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><circle id="c" cx="50" cy="50" r="40"/></svg>']]);
  await page.waitForFunction(() => document.querySelector('#message').textContent);
  const text = await page.textContent('#message');
  assert.match(text, /two closed shapes/, text);
  assert.doesNotMatch(text, /[Ss]elect/, text);
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve);
  assert.doesNotMatch(await page.textContent('#stats3d'), /[Ss]elect/);
  await page.close();
});

test('hole warnings name pieces A and B, as the table does', async () => {
  const page = await openApp(panel);
  await page.selectOption('#sample-select', 'two-ellipses');
  await waitReady(page);
  // 60 holes of 3 mm, 15 mm in: they crowd where the ellipses curve most, on both pieces.
  await page.fill('#count', '60');
  await page.fill('#diameter', '3');
  await page.fill('#inset', '15');
  await page.waitForFunction(() => /second piece|piece B/.test(document.querySelector('#message').textContent));
  const text = await page.textContent('#message');
  assert.match(text, /On piece A, /, text);
  assert.match(text, /On piece B, /, text);
  assert.doesNotMatch(text, /first piece|second piece/, text);
  await page.close();
});

test('one connector is singular, in the stats line and in the core’s messages', async () => {
  const page = await openApp(panel);
  await page.selectOption('#sample-select', 'ellipse-circle');
  await waitReady(page);
  await page.fill('#count', '1');
  await page.waitForFunction(() => /^1 connector/.test(document.querySelector('#stats').textContent) || document.body.dataset.state === 'error');
  assert.match(await page.textContent('#stats'), /^1 connector\b/, await page.textContent('#message'));
  assert.doesNotMatch(await page.textContent('#stats'), /1 connectors/);
  const out = await page.evaluate(() => window.DF.messages.humanize(
    'On the second piece, the holes of connectors 3 cross the edge: increase the inset. On the first piece, the holes of connectors 1 and 2 overlap: use fewer connectors or smaller holes.',
    (pt) => `${pt} pt`));
  assert.equal(out, 'On piece B, the holes of connector 3 cross the edge: increase the inset. On piece A, the holes of connectors 1 and 2 overlap: use fewer connectors or smaller holes.');
  await page.close();
});
