"""Laser layers: where D-former's additions land in the document.

Three top-level Inkscape layers, one per laser operation, with the usual colour convention
(the same as the Illustrator panel and the ``dformer`` command):

- ``D-former cut``     — red (#ff0000) hairline strokes: stitch holes;
- ``D-former score``   — blue (#0000ff) hairline strokes: the start marks of connector 0;
- ``D-former engrave`` — black (#000000) filled text: connector numbers.

A hairline is 0.001 in (0.0254 mm), converted to user units, which is what laser drivers
treat as "vector cut". Each piece's additions are one group per layer, named after the piece;
running Connectors again on the same piece replaces its earlier group.
"""

import inkex

from dformer_pieces import OWN_PREFIX
from dformer_viewport import page_px_per_user

LAYERS = {
    "cut": ("D-former cut", "#ff0000"),
    "score": ("D-former score", "#0000ff"),
    "engrave": ("D-former engrave", "#000000"),
}

HAIRLINE = "0.001in"


def layer(svg, kind):
    """The top-level layer for ``kind`` ("cut", "score", "engrave"), created when missing."""
    label, _ = LAYERS[kind]
    lid = f"{OWN_PREFIX}{kind}"
    found = svg.getElementById(lid)
    if found is not None:
        return found
    new = inkex.Layer.new(label)
    new.set("id", lid)
    svg.add(new)
    return new


def stroke_style(svg, kind):
    """Hairline stroke in the layer's colour, no fill."""
    _, colour = LAYERS[kind]
    width = inkex.units.convert_unit(HAIRLINE, "px") / page_px_per_user(svg)
    return inkex.Style({"fill": "none", "stroke": colour, "stroke-width": f"{width:.6g}"})


def piece_group(svg, kind, piece_id, title):
    """An empty group for one piece in one layer, replacing one from an earlier run."""
    gid = f"{OWN_PREFIX}{kind}-{piece_id}"
    old = svg.getElementById(gid)
    if old is not None:
        old.delete()
    group = inkex.Group()
    group.set("id", gid)
    group.label = title
    layer(svg, kind).add(group)
    return group


def add_paths(svg, group, kind, path_data, id_prefix):
    """One <path> per path data string, hairline-styled for the layer."""
    style = stroke_style(svg, kind)
    for k, d in enumerate(path_data):
        elem = inkex.PathElement()
        elem.set("id", f"{id_prefix}-{k + 1}")
        elem.set("d", d)
        elem.style = style
        group.add(elem)


def add_labels(group, labels, font_size, id_prefix):
    """Engraved numbers: ``{text, at: [x, y], angle, size}`` from the core, ``angle`` in degrees
    along the edge (already turned so the text reads upright). ``font_size`` None: each
    label's own ``size`` (the core's, clear of holes, slots and the cut line)."""
    _, colour = LAYERS["engrave"]
    for k, label in enumerate(labels):
        x, y = label["at"]
        text = inkex.TextElement()
        text.set("id", f"{id_prefix}-{k + 1}")
        text.set("x", f"{x:.6f}")
        text.set("y", f"{y:.6f}")
        text.set("transform", f"rotate({label['angle']:.6f} {x:.6f} {y:.6f})")
        text.style = inkex.Style(
            {
                "font-size": f"{(font_size if font_size else label['size']):.6g}",
                "font-family": "sans-serif",
                "text-anchor": "middle",
                "dominant-baseline": "central",
                "fill": colour,
                "stroke": "none",
            }
        )
        text.text = str(label["text"])
        group.add(text)
