// The core measures in points and prints raw numbers; what the user reads must be in the panel's
// unit, matching the numbers the panel shows elsewhere (the perimeter table, the length fields).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();

async function sample(page) {
  await page.goto(panel.url);
  await waitReady(page, 'load');
  await page.selectOption('#sample-select', 'ellipse-circle');
  await waitReady(page);
}
const message = (page) => page.textContent('#message');
const NO_RAW_NUMBER = /\d\.\d{5,}/; // 5.669291338582678 and the like

test('too many connectors for the holes: diameter and pitch in mm, then in inches', async () => {
  const page = await panel.browser.newPage();
  await sample(page);
  const perimeter = Number(/perimeter ([\d.]+) mm/.exec(await page.textContent('#stats'))[1]);
  await page.fill('#diameter', '2');
  await page.fill('#count', '200');
  await page.waitForFunction(() => document.body.dataset.state === 'error');
  const mm = await message(page);
  assert.doesNotMatch(mm, NO_RAW_NUMBER, mm);
  assert.ok(mm.includes('2.00 mm'), `the 2 mm hole of the Hole ⌀ field: ${mm}`);
  assert.ok(mm.includes(`${(perimeter / 200).toFixed(2)} mm apart`), `pitch ${perimeter} / 200: ${mm}`);
  await page.selectOption('#unit-select', 'in');
  await page.waitForFunction(() => / in\b/.test(document.querySelector('#message').textContent));
  const inch = await message(page);
  assert.ok(inch.includes(`${(2 / 25.4).toFixed(4)} in`), `2 mm = 0.0787 in: ${inch}`);
  await page.close();
});

test('Normalize off: the perimeters in the message are the ones in the table', async () => {
  const page = await panel.browser.newPage();
  await sample(page);
  const rows = await page.$$eval('#measure-table tr td.perimeter', (tds) => tds.map((t) => t.textContent));
  await page.uncheck('#normalize-on');
  await page.waitForFunction(() => document.body.dataset.state === 'error');
  const text = await message(page);
  assert.doesNotMatch(text, NO_RAW_NUMBER, text);
  assert.ok(text.includes(`(${rows[0]} and ${rows[1]};`), `wanted ${rows[0]} and ${rows[1]} in: ${text}`);
  await page.close();
});

test('teeth: the flank angle field takes dovetails up to 179°, a flank error shows a rounded angle', async () => {
  const page = await panel.browser.newPage();
  await sample(page);
  await page.click('#kind button[data-kind="teeth"]');
  await waitReady(page);
  // The core's default (defaults()), not a number of the panel's own.
  assert.equal(await page.inputValue('#angle'), '90');
  assert.equal(await page.getAttribute('#angle', 'max'), '179');
  await page.fill('#angle', '180');
  assert.equal(await page.evaluate(() => document.querySelector('#angle').classList.contains('invalid')), true, '180° is marked invalid');
  await page.fill('#angle', '110');
  assert.equal(await page.evaluate(() => document.querySelector('#angle').classList.contains('invalid')), false, '110° (a dovetail) is valid');
  await page.waitForTimeout(100);
  assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready', await message(page));
  await page.fill('#angle', '60');
  await page.fill('#length', '30');
  await page.waitForFunction(() => document.body.dataset.state === 'error');
  const text = await message(page);
  assert.doesNotMatch(text, NO_RAW_NUMBER, text);
  assert.match(text, /Teeth 30\.00 mm long with 60° flanks/, text);
  await page.close();
});

test('a negative inset marks the field instead of reaching the core', async () => {
  const page = await panel.browser.newPage();
  await sample(page);
  await page.fill('#inset', '-5');
  assert.equal(await page.evaluate(() => document.querySelector('#inset').classList.contains('invalid')), true);
  await page.waitForTimeout(100);
  assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready', await message(page));
  await page.close();
});
