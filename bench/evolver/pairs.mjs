// The bench's pairs: the convex calibration case the issue quotes and two non-convex pairs of
// its table, each normalized to the first piece's perimeter (the circle is scaled to it).
import { polarPath, ellipsePath, arcTable, scaled } from './outline.mjs';

/** A circle (96 Hermite arcs) whose perimeter equals `perimeter`. */
function circleOf(perimeter) {
  const unit = polarPath(() => 1, () => 0);
  return scaled(unit, perimeter / arcTable(unit).perimeter);
}

/** `{ name, pieces: [A, B], offset }` for every pair of the bench. */
export function pairs() {
  const ellipse = ellipsePath(60, 30);
  const pe = arcTable(ellipse).perimeter;
  const kidney = polarPath(
    (t) => 60 * (1 + 0.35 * Math.cos(2 * t) - 0.25 * Math.cos(t) + 0.2 * Math.sin(3 * t)),
    (t) => 60 * (-0.7 * Math.sin(2 * t) + 0.25 * Math.sin(t) + 0.6 * Math.cos(3 * t)),
  );
  const lobed = polarPath((t) => 55 * (1 + 0.12 * Math.sin(5 * t)), (t) => 55 * 0.6 * Math.cos(5 * t));
  return [
    { name: 'two 2:1 ellipses, quarter-perimeter offset (convex calibration)', convex: true, pieces: [ellipse, ellipse], offset: pe / 4 },
    { name: 'kidney r = 60(1 + 0.35cos2θ − 0.25cosθ + 0.2sin3θ) + circle', pieces: [kidney, circleOf(arcTable(kidney).perimeter)], offset: 0 },
    { name: 'five-lobed r = 55(1 + 0.12 sin5θ) + circle', pieces: [lobed, circleOf(arcTable(lobed).perimeter)], offset: 0 },
  ];
}
