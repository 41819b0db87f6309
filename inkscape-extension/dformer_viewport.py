"""SVG viewports, read the way Inkscape 1.2 draws them (checked with ``inkscape --query-*``).

- The page: one user unit (root viewBox unit) measures ``width / viewBox width`` CSS px
  across and ``height / viewBox height`` down. ``preserveAspectRatio`` decides which one the
  drawing uses: ``meet`` (the default) the smaller, ``slice`` the larger. With ``none`` and
  unequal scales a length depends on its direction, so no single unit fits a perimeter: that
  file is refused. A missing or percentage ``width``/``height`` is a share of the viewBox
  size (Inkscape's rule); without a viewBox one user unit is one px.

inkex 1.2 takes the larger of the two page scales whatever ``preserveAspectRatio`` says
(``SvgDocumentElement._base_scale``), hence this module.
"""

from inkex.units import CONVERSIONS, convert_unit, parse_unit

from dformer_bridge import CoreError

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
