#!/usr/bin/env python3
"""Extensions > D-former > Connectors: paired stitch holes, teeth, leaves or both on the two
selected outlines (equal perimeters: run Normalize first), with numbered labels and a start
mark, on laser layers. Live preview is Inkscape's (the effect is re-run on a copy)."""

import inkex

from dformer_bridge import call
from dformer_effect import DformerEffect
from dformer_layers import add_labels, add_paths, piece_group
from dformer_pieces import describe, path_data, read_pieces, replace_outline


class Connect(DformerEffect):
    """The two selected pieces: A is the first selected, B the second."""

    piece_count = (2, 2)

    def add_arguments(self, pars):
        super().add_arguments(pars)
        add = pars.add_argument
        add("--tab", default="connectors", help="Notebook page shown in the dialog (ignored)")
        add("--kind", default="stitch", help="stitch, teeth, leaves or hybrid")
        add("--spacing", default="count", help="count (a number of connectors) or pitch (a distance)")
        add("--count", type=int, default=24, help="Number of connectors on each piece")
        add("--pitch", type=float, default=10.0, help="Distance between connectors along the edge (rounded to divide the perimeter)")
        add("--slide", type=float, default=0.0, help="Shift of every connector, as a fraction of the pitch (0-1)")
        add("--start_a", type=float, default=0.0, help="Connector 1 on piece A: distance along A from its first node")
        add("--start_b", type=float, default=0.0, help="Connector 1 on piece B: distance along B from its first node")
        add("--diameter", type=float, default=0.0, help="Hole diameter (0: a quarter of the pitch)")
        add("--inset", type=float, default=0.0, help="Edge to hole centre (0: automatic)")
        add("--length", type=float, default=0.0, help="Tooth or leaf length (0: automatic)")
        add("--angle", type=float, default=90.0, help="Tooth flank angle in degrees (90: square)")
        add("--invert", type=inkex.Boolean, default=False, help="Connectors on the other side of the edge")
        add("--kerf", type=float, default=0.0, help="Laser kerf to compensate (cut width)")
        add("--labels", type=inkex.Boolean, default=True, help="Engrave connector numbers")
        add("--label_size", type=float, default=0.0, help="Number height (0: 40% of the pitch)")

    def core_options(self):
        """The core's connect options, lengths converted to user units; 0 = the core's default."""
        o = self.options
        opts = {"kind": o.kind, "slide": o.slide, "invert": o.invert, "angle": o.angle,
                "kerf": self.to_user(o.kerf), "start": [self.to_user(o.start_a), self.to_user(o.start_b)]}
        if o.spacing == "pitch":
            opts["pitch"] = self.to_user(o.pitch)
        else:
            opts["count"] = o.count
        for name in ("diameter", "inset", "length"):
            value = getattr(o, name)
            if value != 0:
                opts[name] = self.to_user(value)
        return opts

    def compute(self):
        shapes = self.pieces()
        pieces = read_pieces(shapes)
        result = call("connect", pieces=pieces, options=self.core_options())
        outlines_change = self.options.kind != "stitch"
        outline_d = path_data([r["outline"] for r in result["pieces"]], shapes) if outlines_change else None
        holes = [path_data([h["path"] for h in r["holes"]], [None] * len(r["holes"])) for r in result["pieces"]]
        marks = [path_data(r["marks"], [None] * len(r["marks"])) for r in result["pieces"]]
        size = self.to_user(self.options.label_size) if self.options.label_size > 0 else 0.4 * result["pitch"]
        names = ("A", "B")

        def write():
            for i, elem in enumerate(shapes):
                pid = elem.get_id()
                title = f"Piece {names[i]} {describe(elem)}"
                if outlines_change:
                    elem = replace_outline(elem, outline_d[i])
                if holes[i]:
                    add_paths(self.svg, piece_group(self.svg, "cut", pid, f"{title}: holes"), "cut", holes[i], f"dformer-hole-{pid}")
                if marks[i]:
                    add_paths(self.svg, piece_group(self.svg, "score", pid, f"{title}: start"), "score", marks[i], f"dformer-mark-{pid}")
                if self.options.labels:
                    group = piece_group(self.svg, "engrave", pid, f"{title}: numbers")
                    add_labels(group, result["pieces"][i]["labels"], size, f"dformer-label-{pid}")
            if result["warnings"]:
                self.msg("D-former warnings:\n" + "\n".join(result["warnings"]))

        return write


if __name__ == "__main__":
    Connect().run()
