// A message must describe what is on screen now. "Downloaded d-former-laser.svg" is about the
// previous design once another sample is chosen; an Anchor # the panel does not use (0) is marked
// on the field and explained, instead of leaving the error about the previous number.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openApp, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();

test('the "Downloaded …" line goes away when another sample is chosen', async () => {
  const page = await openApp(panel);
  await page.selectOption('#sample-select', 'pebble-circle');
  await waitReady(page);
  await Promise.all([page.waitForEvent('download'), page.click('#apply-btn')]);
  await page.waitForFunction(() => /Downloaded/.test(document.querySelector('#status').textContent));
  await page.selectOption('#sample-select', 'two-ellipses');
  await page.waitForFunction(() => /Two ellipses/.test(document.querySelector('#selection-summary').textContent));
  assert.equal(await page.textContent('#status'), '');
  await page.close();
});

test('Anchor # 0 after 99: the field is marked, the message gives the valid range, the error about 99 is gone', async () => {
  const page = await openApp(panel);
  await page.selectOption('#sample-select', 'ellipse-circle');
  await waitReady(page);
  const anchorA = '.start[data-piece="0"] .start-anchor';
  await page.selectOption('.start[data-piece="0"] .start-mode', 'anchor');
  await page.fill(anchorA, '99');
  await page.waitForFunction(() => /start anchor 99 does not exist/.test(document.querySelector('#message').textContent));
  const n = Number(/Piece A has (\d+) anchors/.exec(await page.textContent('#message'))[1]);
  // Independent: the anchors of piece A are the points of its path as loaded.
  assert.equal(n, await page.evaluate(() => window.DF.svgImport.parse(window.DF.samples.find((s) => s.id === 'ellipse-circle').files[0].text, 'x').shapes[0].path.points.length));

  await page.fill(anchorA, '0');
  await page.waitForFunction(() => !/99/.test(document.querySelector('#message').textContent));
  assert.equal(await page.evaluate((s) => document.querySelector(s).classList.contains('invalid'), anchorA), true, 'the field is marked invalid');
  const text = await page.textContent('#message');
  assert.match(text, new RegExp(`Anchor # .*A.*1 to ${n}`), text);
  assert.equal(await page.isDisabled('#apply-btn'), true, 'nothing is downloaded with a number the panel does not use');

  await page.fill(anchorA, '2');
  // The error about 0 is still on screen until the panel has read the new number, and
  // waitReady takes an error with a message as settled: wait for that message to go first.
  await page.waitForFunction(() => !/Anchor|anchor/.test(document.querySelector('#message').textContent));
  await waitReady(page);
  assert.equal(await page.evaluate((s) => document.querySelector(s).classList.contains('invalid'), anchorA), false);
  assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready', await page.textContent('#message'));
  assert.doesNotMatch(await page.textContent('#message'), /Anchor|anchor/);
  await page.close();
});

test('a rejected Anchor # is dropped when the start mode changes: no leftover field message', async () => {
  const page = await openApp(panel);
  await page.selectOption('#sample-select', 'ellipse-circle');
  await waitReady(page);
  await page.selectOption('.start[data-piece="1"] .start-mode', 'anchor');
  await page.fill('.start[data-piece="1"] .start-anchor', '0');
  await page.waitForFunction(() => /Anchor # for piece B/.test(document.querySelector('#message').textContent));
  await page.selectOption('.start[data-piece="1"] .start-mode', 'first');
  await waitReady(page);
  assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready');
  assert.doesNotMatch(await page.textContent('#message'), /Anchor #/);
  assert.equal(await page.isDisabled('#apply-btn'), false);
  await page.close();
});
