"""SVG viewports, read the way Inkscape 1.2 draws them (checked with ``inkscape --query-*``).

- The page: one user unit (root viewBox unit) measures ``width / viewBox width`` CSS px
  across and ``height / viewBox height`` down. ``preserveAspectRatio`` decides which one the
  drawing uses: ``meet`` (the default) the smaller, ``slice`` the larger. With ``none`` and
  unequal scales a length depends on its direction, so no single unit fits a perimeter: that
  file is refused. A missing or percentage ``width``/``height`` is a share of the viewBox
  size (Inkscape's rule); without a viewBox one user unit is one px.
- A nested ``<svg>`` maps its content into the rectangle ``x, y, width, height`` of its
  parent's user space (percentages of the parent viewport, missing size = 100%) through its
  own viewBox and ``preserveAspectRatio``, ``none`` included: that is an affine map like a
  group's transform. Inkscape 1.2 ignores ``transform`` on ``<svg>`` elements, so do we.

inkex 1.2 takes the larger of the two page scales whatever ``preserveAspectRatio`` says
(``SvgDocumentElement._base_scale``) and ignores nested viewports, hence this module.
"""

import inkex
from inkex.units import CONVERSIONS, convert_unit, parse_unit

from dformer_bridge import CoreError

#: Inkscape's page size when the root has neither a viewBox nor an absolute width/height.
DEFAULT_SIZE = (300.0, 150.0)

_ALIGN = {"min": 0.0, "mid": 0.5, "max": 1.0}


def _name(elem):
    return "the page" if elem.getparent() is None else f"the nested <svg> #{elem.get_id()}"


def length(elem, name):
    """``(value, unit)`` of a length attribute: unit ``"px"`` (absolute, converted to user
    units), ``"%"``, or ``None`` when the attribute is missing. Anything else is refused."""
    raw = elem.get(name)
    if raw is None or not raw.strip():
        return None, None
    parsed = parse_unit(raw.strip())
    if parsed is None or (parsed[1] not in CONVERSIONS and parsed[1] != "%"):
        raise CoreError(f"{_name(elem)}: {name}=\"{raw}\" cannot be read; use a number, an absolute unit or %.")
    value, unit = parsed
    return (value, "%") if unit == "%" else (convert_unit(raw.strip(), "px"), "px")


def view_box(elem):
    """``(x, y, w, h)`` of a usable viewBox (width and height > 0), else None."""
    parts = (elem.get("viewBox") or "").replace(",", " ").split()
    try:
        box = tuple(float(p) for p in parts)
    except ValueError:
        return None
    return box if len(box) == 4 and box[2] > 0 and box[3] > 0 else None


def aspect(elem):
    """``preserveAspectRatio`` as ``(align, slice)``: align None for ``none``, else the
    (x, y) fractions of the free space put before the content."""
    words = (elem.get("preserveAspectRatio") or "").split()
    if words[:1] == ["defer"]:
        words = words[1:]
    align = words[0] if words else "xMidYMid"
    mode = words[1] if len(words) > 1 else "meet"
    if len(words) > 2 or mode not in ("meet", "slice"):
        align = "xMidYMid"  # unreadable: SVG's default
        mode = "meet"
    if align == "none":
        return None, False
    x, y = align[1:4].lower(), align[5:8].lower()
    if len(align) != 8 or align[0] != "x" or align[4] != "Y" or x not in _ALIGN or y not in _ALIGN:
        return (0.5, 0.5), False
    return (_ALIGN[x], _ALIGN[y]), mode == "slice"


def _scales(box, width, height, elem):
    """(sx, sy): viewport size per viewBox unit, after preserveAspectRatio."""
    sx, sy = width / box[2], height / box[3]
    align, slice_ = aspect(elem)
    if align is None:
        return sx, sy
    s = max(sx, sy) if slice_ else min(sx, sy)
    return s, s


def page_px_per_user(svg):
    """CSS px per root user unit along every direction, as Inkscape draws the page."""
    box = view_box(svg)
    if box is None:
        return 1.0
    size = []
    for name, full in (("width", box[2]), ("height", box[3])):
        value, unit = length(svg, name)
        value = full if unit is None else full * value / 100 if unit == "%" else value
        if not value > 0:
            raise CoreError(f"The page's {name}=\"{svg.get(name)}\" is not a positive length.")
        size.append(value)
    sx, sy = size[0] / box[2], size[1] / box[3]
    align, _ = aspect(svg)
    if align is None and abs(sx - sy) > 1e-9 * max(sx, sy):
        raise CoreError(
            f"The page stretches the drawing unequally (preserveAspectRatio=\"none\", "
            f"{sx:.6g} px per user unit across, {sy:.6g} down), so a length depends on its "
            "direction and a perimeter has no single value. In Document Properties, make the "
            "page size and the viewBox (scale) proportional, or remove preserveAspectRatio."
        )
    return _scales(box, size[0], size[1], svg)[0]


def _page_size(svg):
    """The root viewport's size in root user units (what nested percentages refer to)."""
    box = view_box(svg)
    if box is not None:
        return box[2], box[3]
    size = []
    for name, default in zip(("width", "height"), DEFAULT_SIZE):
        try:
            value, unit = length(svg, name)
        except CoreError:
            value, unit = None, None
        size.append(value if unit == "px" and value > 0 else default)
    return tuple(size)


def _nested(elem, parent):
    """(transform into the parent's user space, size of the viewport it makes)."""
    def resolve(name, ref, default):
        value, unit = length(elem, name)
        return default if unit is None else ref * value / 100 if unit == "%" else value

    x, y = resolve("x", parent[0], 0.0), resolve("y", parent[1], 0.0)
    w, h = resolve("width", parent[0], parent[0]), resolve("height", parent[1], parent[1])
    if not (w > 0 and h > 0):
        raise CoreError(f"{_name(elem)}, which has zero or negative width or height (SVG draws nothing in it).")
    box = view_box(elem)
    if box is None:
        return inkex.Transform(translate=(x, y)), (w, h)
    sx, sy = _scales(box, w, h, elem)
    align, _ = aspect(elem)
    ax, ay = align if align is not None else (0.0, 0.0)
    tx = x + (w - box[2] * sx) * ax - box[0] * sx
    ty = y + (h - box[3] * sy) * ay - box[1] * sy
    return inkex.Transform((sx, 0.0, 0.0, sy, tx, ty)), (box[2], box[3])


def to_root(elem):
    """Local coordinates -> root user units: the ``transform`` attributes of the element and
    its ancestors and the viewports of nested ``<svg>`` ancestors, composed outermost first.
    Transforms are read from the raw attributes (inkex 1.2's ``composed_transform()`` rounds
    them to 6 digits)."""
    chain = [elem] + [a for a in elem.ancestors() if isinstance(a, inkex.BaseElement)]
    chain.reverse()
    result = inkex.Transform()
    size = _page_size(chain[0]) if isinstance(chain[0], inkex.SvgDocumentElement) else DEFAULT_SIZE
    for node in chain[1:]:
        if isinstance(node, inkex.SvgDocumentElement):
            viewport, size = _nested(node, size)
            result = result @ viewport
        else:
            result = result @ inkex.Transform(node.attrib.get("transform"))
    return result
