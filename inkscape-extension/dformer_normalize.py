#!/usr/bin/env python3
"""Extensions > D-former > Normalize: scales the selected outlines about their pivots so that
all have the same perimeter, updating each object in place (id, style, transform kept). One
selected outline is scaled to the exact length."""

import inkex

from dformer_bridge import call
from dformer_effect import DformerEffect
from dformer_pieces import path_data, read_pieces, replace_outline


class Normalize(DformerEffect):
    """Options: target (largest/smallest/mean/first/exact length) and pivot."""

    piece_count = (1, None)

    def add_arguments(self, pars):
        super().add_arguments(pars)
        pars.add_argument("--target", default="largest", help="largest, smallest, mean, first or length")
        pars.add_argument("--length", type=float, default=100.0, help="Perimeter when target=length, in --unit")
        pars.add_argument("--pivot", default="center", help="center (bounding box), centroid or start (first node stays)")

    def compute(self):
        shapes = self.pieces()
        pieces = read_pieces(shapes)
        target = self.options.target
        if len(shapes) == 1 and target != "length":
            raise inkex.AbortExtension(
                "Only one outline is selected: choose Exact length to scale it to a perimeter, or select two or more outlines to give them one perimeter."
            )
        if target == "length":
            if not self.options.length > 0:
                raise inkex.AbortExtension(f"The perimeter to reach must be positive, got {self.options.length}.")
            target = self.to_user(self.options.length)
        result = call("normalize", paths=pieces, options={"target": target, "pivot": self.options.pivot})
        new_d = path_data(result["paths"], shapes)

        def write():
            for elem, d in zip(shapes, new_d):
                replace_outline(elem, d)

        return write


if __name__ == "__main__":
    Normalize().run()
