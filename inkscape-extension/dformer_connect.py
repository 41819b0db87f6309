#!/usr/bin/env python3
"""Extensions > D-former > Connectors: paired stitch holes, teeth, leaves or both on the two
selected outlines (equal perimeters: run Normalize first), with numbered labels and a start
mark, on laser layers. Live preview is Inkscape's (the effect is re-run on a copy)."""

import inkex

from dformer_bridge import call
from dformer_effect import DformerEffect
from dformer_layers import add_labels, add_paths, piece_group
from dformer_pieces import describe, path_data, read_pieces, replace_outline


def default_count():
    """The core's default number of connectors, from `defaults()`."""
    return int(next(d["value"] for d in call("defaults")["options"] if d["name"] == "count"))


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
        add("--pitch", type=float, default=0.0, help="Distance between connectors along the edge (rounded to divide the perimeter; 0: the perimeter over the core's default count)")
        add("--slide", type=float, default=0.0, help="Shift of every connector, as a fraction of the pitch (0-1; with both starts 0 too: automatic, clear of corners)")
        add("--start_a", type=float, default=0.0, help="Connector 1 on piece A: distance along A from its first node")
        add("--start_b", type=float, default=0.0, help="Connector 1 on piece B: distance along B from its first node")
        add("--diameter", type=float, default=0.0, help="Hole diameter (0: a quarter of the pitch)")
        add("--inset", type=float, default=0.0, help="Edge to hole centre (0: automatic)")
        add("--length", type=float, default=0.0, help="Tooth or leaf length (0: automatic)")
        add("--angle", type=float, default=90.0, help="Tooth flank angle in degrees (90: square; more: dovetails that lock)")
        add("--leaf", default="tab", help="Leaves: tab (glued) or lock (a head on a neck, held in a slot in the other piece)")
        add("--allowance", type=float, default=0.0, help="Seam allowance: the cut line moves out by this much (stitch, leaves)")
        add("--invert", type=inkex.Boolean, default=False, help="Stitch: holes outside; teeth: swap teeth and gaps; leaves: swap which piece carries each leaf")
        add("--kerf", type=float, default=0.0, help="Laser kerf to compensate (cut width)")
        add("--labels", type=inkex.Boolean, default=True, help="Engrave connector numbers")
        add("--label_size", type=float, default=0.0, help="Number height (0: as large as fits clear of holes, slots and edge)")

    def core_options(self):
        """The core's connect options; lengths as typed, in the user's unit (the core gets the
        pieces in that unit too, ``in_unit``, and names it after every length in its messages);
        0 = the core's default."""
        o = self.options
        opts = {"kind": o.kind, "invert": o.invert, "angle": o.angle, "leaf": o.leaf, "kerf": o.kerf, "unit": self.unit()}
        # Slide and start both 0: the core places the connectors clear of the corners.
        if o.slide != 0 or o.start_a != 0 or o.start_b != 0:
            opts["slide"] = o.slide
            opts["start"] = [o.start_a, o.start_b]
        if not o.labels:
            opts["labels"] = False
        if o.allowance != 0:
            opts["allowance"] = o.allowance
        if o.spacing == "pitch":
            # 0: the pitch the core's default count gives, perimeter / defaults().count (no
            # number of the extension's own: the count is the core's).
            if o.pitch != 0:
                opts["pitch"] = o.pitch
            else:
                opts["count"] = default_count()
        else:
            opts["count"] = o.count
        for name in ("diameter", "inset", "length"):
            value = getattr(o, name)
            if value != 0:
                opts[name] = value
        return opts

    def compute(self):
        shapes = self.pieces()
        pieces = self.in_unit(read_pieces(shapes))
        result = call("connect", pieces=pieces, options=self.core_options())
        back = self.from_unit
        k = self.to_user(1.0)
        for r in result["pieces"]:
            r["outline"] = back(r["outline"])
            for h in r["holes"]:
                h["path"] = back(h["path"])
            r["slots"] = [back(s) for s in r.get("slots", [])]
            r["marks"] = [back(m) for m in r["marks"]]
            if "seam" in r:
                r["seam"] = back(r["seam"])
            for label in r["labels"]:
                label["at"] = [v * k for v in label["at"]]
                label["size"] *= k
        # With a seam allowance the outline is the cut line and the seam line is scored.
        outlines_change = self.options.kind != "stitch" or any("seam" in r for r in result["pieces"])
        outline_d = path_data([r["outline"] for r in result["pieces"]], shapes) if outlines_change else None

        def data(paths):
            return path_data(paths, [None] * len(paths))

        holes = [data([h["path"] for h in r["holes"]]) for r in result["pieces"]]
        slots = [data(r.get("slots", [])) for r in result["pieces"]]
        marks = [data(r["marks"]) for r in result["pieces"]]
        seams = [data([r["seam"]] if "seam" in r else []) for r in result["pieces"]]
        size = self.to_user(self.options.label_size) if self.options.label_size > 0 else None
        names = ("A", "B")

        def write():
            for i, elem in enumerate(shapes):
                pid = elem.get_id()
                title = f"Piece {names[i]} {describe(elem)}"
                if outlines_change:
                    elem = replace_outline(elem, outline_d[i])
                if holes[i] or slots[i]:
                    group = piece_group(self.svg, "cut", pid, f"{title}: {'slots' if slots[i] else 'holes'}")
                    add_paths(self.svg, group, "cut", holes[i], f"dformer-hole-{pid}")
                    add_paths(self.svg, group, "cut", slots[i], f"dformer-slot-{pid}")
                if marks[i] or seams[i]:
                    group = piece_group(self.svg, "score", pid, f"{title}: start{' and seam line' if seams[i] else ''}")
                    add_paths(self.svg, group, "score", marks[i], f"dformer-mark-{pid}")
                    add_paths(self.svg, group, "score", seams[i], f"dformer-seam-{pid}")
                if self.options.labels:
                    group = piece_group(self.svg, "engrave", pid, f"{title}: numbers")
                    add_labels(group, result["pieces"][i]["labels"], size, f"dformer-label-{pid}")
            if result["warnings"]:
                self.msg("D-former warnings:\n" + "\n".join(result["warnings"]))

        return write


if __name__ == "__main__":
    Connect().run()
