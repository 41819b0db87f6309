#!/usr/bin/env python3
"""Extensions > D-former > Measure: perimeter, area and drawing direction of the selected
outlines, in the document's unit, as measured by the core (relative error <= 1e-12). Selected
shapes that cannot be measured (open strokes, self-crossing outlines) are listed as skipped,
with why in Inkscape's words; the run fails only when none can be measured."""

import inkex

from dformer_bridge import CoreError, run_batch
from dformer_effect import DformerEffect
from dformer_pieces import describe, name_pieces, read_pieces


class Measure(DformerEffect):
    """Reports; never changes the document."""

    def compute(self):
        shapes = self.pieces()
        pieces = read_pieces(shapes)
        answers = run_batch([{"op": "measure", "path": p} for p in pieces])
        # A stray open stroke in the selection does not block the others: it is listed as
        # skipped, with why (each request has one path: the core calls every one "the first").
        refused = [name_pieces(m["error"], [elem]) for elem, m in zip(shapes, answers) if "error" in m]
        measured = [(elem, m) for elem, m in zip(shapes, answers) if "error" not in m]
        if not measured:
            raise CoreError(" ".join(refused))  # shown through user_message, like every error
        results = [m for _, m in measured]
        unit = self.unit()
        lines = []
        for elem, m in measured:
            # The core reports orientation for y-up; SVG user space is y-down.
            turn = "clockwise" if m["orientation"] == "ccw" else "counter-clockwise"
            area = m["area"] * self.from_user(1.0) ** 2
            lines.append(
                f"{describe(elem)}: perimeter {self.fmt(m['perimeter'])}, "
                f"area {area:.4f} {unit}², drawn {turn} on screen"
            )
        if len(results) >= 2:
            perims = [m["perimeter"] for m in results]
            spread = (max(perims) - min(perims)) / max(perims)
            verdict = "equal (ready to connect)" if spread <= 1e-6 else "different: run D-former > Normalize"
            lines.append(f"Perimeters differ by {spread:.3e} relative: {verdict}.")
        lines.extend(f"Skipped: {self.user_message(why)}" for why in refused)
        message = "\n".join(lines)
        return lambda: self.msg(message)


if __name__ == "__main__":
    Measure().run()
