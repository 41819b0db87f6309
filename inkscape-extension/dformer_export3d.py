#!/usr/bin/env python3
"""Extensions > D-former > 3D export: the D-form the two selected pieces make when stitched
(the core's `simulate`), saved as OBJ or STL in the chosen unit, with its volume and area
reported. The document is not changed."""

import math
import os

import inkex
from inkex.units import CONVERSIONS

from dformer_bridge import call
from dformer_effect import DformerEffect
from dformer_mesh import write_obj, write_stl
from dformer_pieces import describe, read_pieces


def shortfall_text(stats, resolution):
    """What an unconverged answer misses (`stats.shortfall` of the core's `simulate`), in words."""
    why = stats.get("shortfall")
    if why == "sampling":
        more = min(2 * resolution, 2048)
        return (f"Approximate shape: the outline turns too tightly somewhere for {resolution} seam vertices, which alone "
                f"force edges up to {stats['strainFloor']:.3%} off their flat lengths, more than the 0.1% a true D-form "
                f"allows. Raise Seam vertices (try {more}) or round that curve a little more.")
    if why == "fold":
        bend = round(math.degrees(stats["maxBend"]))
        return (f"Approximate shape: the pieces keep their flat lengths, but one is creased by {bend}° inside it, "
                "where real material creases; the real D-form will look different there. Making a deep "
                "inward bay (an L's notch, a heart's dip) shallower usually avoids it; rounding its corners does not.")
    if why == "crossing":
        return "Approximate shape: the pieces pass through each other in it; the real D-form will look different."
    if why == "unsettled":
        return f"The solver stopped before the shape settled ({stats['iterations']} steps): treat it as approximate."
    return (f"The solver did not converge in {stats['iterations']} steps (the pieces would have to stretch, "
            f"up to {stats['maxStrain']:.2%}): treat the shape as approximate.")


class Export3D(DformerEffect):
    piece_count = (2, 2)

    def add_arguments(self, pars):
        super().add_arguments(pars)
        pars.add_argument("--file", default="", help="OBJ or STL file to write")
        pars.add_argument("--offset", type=float, default=0.0, help="Shift of B's start along its edge (like Connectors' start on B)")
        pars.add_argument("--resolution", type=int, default=256, help="Seam vertices")

    def target_file(self):
        name = os.path.expanduser(self.options.file.strip())
        if not name:
            raise inkex.AbortExtension("Choose the file to write (.obj or .stl).")
        if not os.path.isabs(name):
            doc = self.document_path()
            name = os.path.join(os.path.dirname(doc) if doc else os.getcwd(), name)
        ext = os.path.splitext(name)[1].lower()
        if ext not in (".obj", ".stl"):
            raise inkex.AbortExtension(f"The 3D file must end in .obj or .stl, got {name!r}.")
        return name, ext

    def compute(self):
        name, ext = self.target_file()
        shapes = self.pieces()
        pieces = read_pieces(shapes)
        options = {"offset": self.to_user(self.options.offset), "resolution": self.options.resolution}
        result = call("simulate", pieces=pieces, options=options)
        k = self.from_user(1.0)  # user units -> the chosen unit, for the file and the figures
        unit = self.unit()
        vertices = [[c * k for c in v] for v in result["vertices"]]
        stats = result["stats"]
        volume, area = stats["volume"] * k**3, stats["area"] * k**2
        litres = (self.px_per_user() / CONVERSIONS["cm"]) ** 3 * stats["volume"] / 1000.0
        comment = f"D-former D-form of {describe(shapes[0])} and {describe(shapes[1])}, unit {unit}"
        lines = [
            f"Wrote {name}: {len(vertices)} vertices, {len(result['triangles'])} triangles, unit {unit}.",
            f"Volume {volume:.6g} {unit}³ ({litres:.6g} L), surface area {area:.6g} {unit}².",
            f"Max edge strain {stats['maxStrain']:.3%}, seam gap {stats['seamGap'] * k:.3g} {unit}.",
        ]
        if not stats["converged"]:
            lines.append(shortfall_text(stats, self.options.resolution))

        def write():
            try:
                if ext == ".obj":
                    write_obj(name, vertices, result["triangles"], result["piece"], comment)
                else:
                    write_stl(name, vertices, result["triangles"], comment)
            except OSError as err:
                raise inkex.AbortExtension(f"Could not write {name}: {err}") from err
            self.msg("\n".join(lines))

        return write


if __name__ == "__main__":
    Export3D().run()
