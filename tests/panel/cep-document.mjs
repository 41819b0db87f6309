// The simulated Illustrator document as the CEP panel tests read it: every item of a snapshot
// flattened with its layer and group, Apply pressed and answered, and a path's reference length.
import assert from 'node:assert/strict';
import { referenceLength } from '../illustrator/reference-length.mjs';

/** Every item of a snapshot layer tree, flattened, with its group path. */
export function items(snapshotDoc) {
  const out = [];
  const walk = (list, layer, group) => {
    for (const it of list) {
      out.push({ ...it, layer, group });
      if (it.items) walk(it.items, layer, it.name);
    }
  };
  for (const l of snapshotDoc.layers) walk(l.items, l.name, null);
  return out;
}

/** Presses Apply and waits for the bridge's answer, which must be 'ok' (else the panel's status is the message). */
export async function applyOk(page) {
  await page.click('#apply-btn');
  await page.waitForFunction(() => document.body.dataset.applied);
  assert.equal(await page.evaluate(() => document.body.dataset.applied), 'ok', `apply failed: ${await page.textContent('#status')}`);
}

/** Length of a snapshot path item by the independent reference quadrature. */
export const lengthOf = (it) => referenceLength({ closed: it.closed, points: it.points.map((p) => ({ anchor: p.a, left: p.l, right: p.r })) });

/** The two pieces most panel tests start from: a 200 × 110 mm ellipse and a 150 mm circle. */
export const TWO_SHAPES = {
  units: 'mm',
  shapes: [
    { name: 'Ellipse', ellipse: { top: 400, left: 0, width: 200, height: 110 } },
    { name: 'Circle', ellipse: { top: 400, left: 260, width: 150, height: 150 } },
  ],
};
