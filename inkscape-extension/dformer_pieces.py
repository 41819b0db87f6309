"""Selected Inkscape objects <-> the core's path JSON, in document user units.

A <path> sends its own ``d``; <rect>, <circle> and <ellipse> become SVG's equivalent paths
(``local_path_data``), polygons go through inkex's ``get_path()``, all at full precision;
nested group transforms and nested ``<svg>`` viewports are composed (``dformer_viewport``). The
path data itself is parsed by the core (``pathFromSvg``) and written by it (``pathToSvg``), so
the extension and the ``dformer`` batch command read SVG curves identically.

Every piece lives in *document user units* (the root viewBox coordinates): the element's
local coordinates mapped through its composed transform. Bezier curves are affine-invariant,
so mapping anchors and handles maps the curve exactly; results are mapped back through the
inverse transform when an element is updated in place.
"""

import re

import inkex

from dformer_bridge import CoreError, call_all, run_batch
from dformer_viewport import to_root

#: inkex classes that can be D-form pieces (closed outlines). Polyline and Line are accepted
#: so that the core can say the outline is open, rather than the extension ignoring them.
SHAPES = (
    inkex.PathElement,
    inkex.Rectangle,
    inkex.Circle,
    inkex.Ellipse,
    inkex.Polygon,
    inkex.Polyline,
    inkex.Line,
)

#: Geometry attributes a shape loses when it is rewritten as a <path>.
GEOMETRY_ATTRS = ("x", "y", "width", "height", "rx", "ry", "cx", "cy", "r", "points", "x1", "y1", "x2", "y2")

#: sodipodi attributes that do not describe the shape: the object's lock stays on.
KEEP_SODIPODI = ("{%s}insensitive" % inkex.NSS["sodipodi"],)

#: Id prefix of everything D-former writes (layers and groups); never read back as a piece.
OWN_PREFIX = "dformer-"


def describe(elem):
    """How messages name an element: its id and, when set, its label."""
    label = elem.label
    return f"#{elem.get_id()}" + (f" ({label})" if label and label != elem.get_id() else "")


_ORDINALS = {"first": 0, "second": 1, "third": 2}
_PIECE_REF = re.compile(r"\b[Tt]he (first|second|third|(\d+)(?:st|nd|rd|th)) path\b")


def name_pieces(message, shapes):
    """The core names pieces by position ("The second path is open."); a student needs the
    object: "#path12 (Left) is open." ``shapes`` are the pieces in the order the core got them."""

    def repl(match):
        index = _ORDINALS.get(match.group(1))
        if index is None:
            index = int(match.group(2)) - 1
        return describe(shapes[index]) if 0 <= index < len(shapes) else match.group(0)

    return _PIECE_REF.sub(repl, message)


def is_own_output(elem):
    """True for anything inside a layer or group that D-former wrote."""
    node = elem
    while node is not None and isinstance(node, inkex.BaseElement):
        if (node.get("id") or "").startswith(OWN_PREFIX):
            return True
        node = node.getparent()
    return False


def selected_shapes(svg):
    """The selected shapes in selection order, groups opened (their shapes in document order).
    Text, images, clones and D-former's own output are left out; the caller checks the count."""
    shapes, refused = [], []
    for elem in svg.selection.values():
        opened = isinstance(elem, (inkex.Group, inkex.SvgDocumentElement))  # a nested <svg> too
        candidates = list(elem.descendants()) if opened else [elem]
        for cand in candidates:
            if is_own_output(cand) or isinstance(cand, (inkex.Group, inkex.SvgDocumentElement)):
                continue
            if isinstance(cand, SHAPES):
                if cand not in shapes:
                    shapes.append(cand)
            elif isinstance(cand, inkex.ShapeElement) and cand is elem:
                refused.append(cand)
    return shapes, refused


def check_editable(elem):
    """Refuses objects whose outline Inkscape regenerates from other data."""
    if elem.get("inkscape:path-effect") or elem.get("inkscape:original-d"):
        raise CoreError(
            f"{describe(elem)} has a live path effect, so its outline cannot be changed directly: "
            "convert it to a path first."
        )


def doc_transform(elem):
    """Local coordinates -> document user units: ``transform`` attributes and nested
    ``<svg>`` viewports, as Inkscape draws them (``dformer_viewport.to_root``)."""
    try:
        return to_root(elem)
    except CoreError as err:
        raise CoreError(f"{describe(elem)} is inside {err}") from err


def to_doc(path, transform):
    """Maps a core path through an inkex Transform (anchors and handles: exact for Beziers)."""
    def tr(p):
        if p is None:
            return None
        q = transform.apply_to_point(p)
        return [q.x, q.y]

    return {
        "closed": path.get("closed", False),
        "points": [
            {k: tr(pt.get(k)) for k in ("anchor", "left", "right") if pt.get(k) is not None}
            for pt in path["points"]
        ],
    }


def _number(value):
    """A path-data number at full precision (shortest round trip). inkex's ``str(Path)``
    writes 6 significant digits, which moves a normalized outline by ~1e-6 relative and
    makes its perimeter differ from its partner's when it is read back."""
    value = float(value)
    if value.is_integer() and abs(value) < 1e15:
        return str(int(value))
    return repr(value)


def full_precision_d(path):
    """SVG path data for an inkex Path, every number at full precision."""
    return " ".join(
        " ".join([seg.letter] + [_number(a) for a in seg.args]) for seg in path
    )


def _length_attr(elem, name, default=None):
    """A geometry attribute in user units; percentages (relative to the viewport) are refused."""
    raw = elem.get(name)
    if raw is None:
        return default
    if "%" in raw:
        raise CoreError(
            f"{describe(elem)}: attribute {name}=\"{raw}\" is a percentage, which D-former does "
            "not follow: convert it to a path first."
        )
    return raw


def rect_d(elem):
    """A <rect>'s outline by SVG's rules (inkex 1.2 ignores them): a missing, ``auto`` or
    negative rx/ry takes the other one's value, and each is clamped to half the width or
    height. Same result as the ``dformer`` batch command."""

    def radius(name):
        raw = _length_attr(elem, name)
        if raw is None or raw.strip() == "auto":
            return None
        value = elem.to_dimensionless(raw)
        return value if value >= 0 else None

    x = elem.to_dimensionless(_length_attr(elem, "x", "0"))
    y = elem.to_dimensionless(_length_attr(elem, "y", "0"))
    w = elem.to_dimensionless(_length_attr(elem, "width", "0"))
    h = elem.to_dimensionless(_length_attr(elem, "height", "0"))
    rx, ry = radius("rx"), radius("ry")
    if rx is None and ry is None:
        rx = ry = 0.0
    elif rx is None:
        rx = ry
    elif ry is None:
        ry = rx
    if not (w > 0 and h > 0):
        raise CoreError(f"{describe(elem)} has zero or negative width or height.")
    rx, ry = min(rx, w / 2), min(ry, h / 2)
    n = _number
    if rx <= 0 or ry <= 0:
        return f"M {n(x)} {n(y)} H {n(x + w)} V {n(y + h)} H {n(x)} Z"
    arc = f"A {n(rx)} {n(ry)} 0 0 1"
    return (
        f"M {n(x + rx)} {n(y)} H {n(x + w - rx)} {arc} {n(x + w)} {n(y + ry)} "
        f"V {n(y + h - ry)} {arc} {n(x + w - rx)} {n(y + h)} "
        f"H {n(x + rx)} {arc} {n(x)} {n(y + h - ry)} "
        f"V {n(y + ry)} {arc} {n(x + rx)} {n(y)} Z"
    )


def ellipse_d(elem):
    """A <circle>'s or <ellipse>'s outline as SVG defines it: four arcs from (cx + rx, cy),
    clockwise on screen (inkex 1.2 starts at the top and turns the other way). The first node
    is where Connectors' "start" is measured from, so this matches the ``dformer`` command and
    Inkscape's Object to Path."""
    cx = elem.to_dimensionless(_length_attr(elem, "cx", "0"))
    cy = elem.to_dimensionless(_length_attr(elem, "cy", "0"))
    if isinstance(elem, inkex.Circle):
        rx = ry = elem.to_dimensionless(_length_attr(elem, "r", "0"))
    else:
        raw_rx, raw_ry = _length_attr(elem, "rx"), _length_attr(elem, "ry")
        raw_rx = raw_ry if raw_rx in (None, "auto") else raw_rx
        raw_ry = raw_rx if raw_ry in (None, "auto") else raw_ry
        rx, ry = (elem.to_dimensionless(v) if v not in (None, "auto") else 0.0 for v in (raw_rx, raw_ry))
    if not (rx > 0 and ry > 0):
        raise CoreError(f"{describe(elem)} has a zero or negative radius.")
    n = _number
    arc = f"A {n(rx)} {n(ry)} 0 0 1"
    return (
        f"M {n(cx + rx)} {n(cy)} {arc} {n(cx)} {n(cy + ry)} {arc} {n(cx - rx)} {n(cy)} "
        f"{arc} {n(cx)} {n(cy - ry)} {arc} {n(cx + rx)} {n(cy)} Z"
    )


def local_path_data(elem):
    """The element's outline as path data in its own coordinates, at full precision: a
    <path>'s own ``d`` as written (the core parses it, as the ``dformer`` command does),
    <rect>, <circle> and <ellipse> by SVG's rules, polygons through inkex's ``get_path()``."""
    if isinstance(elem, inkex.PathElement):
        return elem.get("d") or ""
    if isinstance(elem, inkex.Rectangle):
        return rect_d(elem)
    if isinstance(elem, (inkex.Circle, inkex.Ellipse)):
        return ellipse_d(elem)
    for name in GEOMETRY_ATTRS:
        _length_attr(elem, name)
    return full_precision_d(elem.path.to_absolute())


def read_pieces(shapes):
    """One core path per shape, in document user units. A shape must be one outline: several
    subpaths (a compound path) is an error naming the shape."""
    local_d = []
    for elem in shapes:
        check_editable(elem)
        local_d.append(local_path_data(elem))
    answers = run_batch([{"op": "pathFromSvg", "d": d} for d in local_d])
    pieces = []
    for elem, subpaths in zip(shapes, answers):
        if isinstance(subpaths, dict) and "error" in subpaths:
            raise CoreError(f"{describe(elem)}: {subpaths['error']}")
        if len(subpaths) != 1:
            raise CoreError(
                f"{describe(elem)} has {len(subpaths)} subpaths; a D-form piece must be one outline. "
                "Use Path > Break Apart and select the outlines themselves."
            )
        pieces.append(to_doc(subpaths[0], doc_transform(elem)))
    return pieces


def path_data(paths_in_doc, elems):
    """SVG path data for each path, in the local coordinates of the matching element
    (``None`` element: document coordinates)."""
    local = [
        to_doc(p, -doc_transform(e)) if e is not None else p
        for p, e in zip(paths_in_doc, elems)
    ]
    return call_all([{"op": "pathToSvg", "path": p} for p in local])


def replace_outline(elem, d):
    """Gives ``elem`` the outline ``d`` (local coordinates), keeping its id, style, transform
    and label. A rect/circle/ellipse/polygon becomes a <path>; Inkscape's own shape data
    (sodipodi:type arcs and stars) is dropped so Inkscape does not regenerate the old shape."""
    if isinstance(elem, inkex.PathElement):
        for key in list(elem.attrib):
            if key.startswith("{%s}" % inkex.NSS["sodipodi"]) and key not in KEEP_SODIPODI:
                del elem.attrib[key]
        elem.set("d", d)
        return elem
    new = inkex.PathElement()
    for key, value in elem.attrib.items():
        if key not in GEOMETRY_ATTRS:
            new.attrib[key] = value  # raw: inkex.set() would round a transform to 6 digits
    new.set("d", d)
    for child in list(elem):  # <title>, <desc> (Object Properties), animations
        new.append(child)
    elem.replace_with(new)
    return new
