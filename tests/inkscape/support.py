"""Shared set-up for the Inkscape extension tests: import paths, the ``dformer`` binary, and
an independent geometry toolkit (arc length by Gauss-Legendre quadrature, point at arc
length, point-in-polygon) written here from the textbook formulas, so the tests never check
the core against itself.

Environment:
- ``INKEX_PATH``: folder holding Inkscape's ``inkex`` (default /usr/share/inkscape/extensions,
  Inkscape 1.2's bundled copy: the one Inkscape itself runs extensions with);
- ``DFORMER_BIN``: the ``dformer`` binary (default: target/{debug,release}/dformer under
  ``CARGO_TARGET_DIR`` or the repository);
- ``EXPORT_COMPARE=1`` writes missing golden files, ``=3`` overwrites them (inkex convention).
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
EXTENSION = os.path.join(REPO, "inkscape-extension")
INKEX = os.environ.get("INKEX_PATH", "/usr/share/inkscape/extensions")

for p in (EXTENSION, INKEX):
    if p not in sys.path:
        sys.path.insert(0, p)


def find_dformer():
    """The built ``dformer`` binary; raises with the build command when missing."""
    if os.environ.get("DFORMER_BIN"):
        return os.environ["DFORMER_BIN"]
    roots = [os.environ.get("CARGO_TARGET_DIR"), os.path.join(REPO, "target")]
    for root in filter(None, roots):
        for profile in ("release", "debug"):
            cand = os.path.join(root, profile, "dformer")
            if os.path.isfile(cand):
                return cand
    raise RuntimeError("dformer binary not found: run `cargo build -p dformer-cli` or set DFORMER_BIN")


os.environ["DFORMER_BIN"] = find_dformer()

import inkex  # noqa: E402  (after the path set-up above)

# -- independent geometry ----------------------------------------------------------------------

# 16-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun, table 25.4).
_GL = [
    (0.0950125098376374, 0.1894506104550685),
    (0.2816035507792589, 0.1826034150449236),
    (0.4580167776572274, 0.1691565193950025),
    (0.6178762444026438, 0.1495959888165767),
    (0.7554044083550030, 0.1246289712555339),
    (0.8656312023878318, 0.0951585116824928),
    (0.9445750230732326, 0.0622535239386479),
    (0.9894009349916499, 0.0271524594117541),
]


def _speed(seg, t):
    (x0, y0), (x1, y1), (x2, y2), (x3, y3) = seg
    u = 1 - t
    dx = 3 * (u * u * (x1 - x0) + 2 * u * t * (x2 - x1) + t * t * (x3 - x2))
    dy = 3 * (u * u * (y1 - y0) + 2 * u * t * (y2 - y1) + t * t * (y3 - y2))
    return math.hypot(dx, dy)


def _gl(seg, a, b):
    half, mid = (b - a) / 2, (a + b) / 2
    return half * sum(w * (_speed(seg, mid - half * x) + _speed(seg, mid + half * x)) for x, w in _GL)


def cubic_length(seg, a=0.0, b=1.0, tol=1e-13, depth=0):
    """Arc length of a cubic Bezier between parameters a and b: adaptive 16-point
    Gauss-Legendre, halving until the two halves agree with the whole to ``tol`` relative."""
    whole = _gl(seg, a, b)
    m = (a + b) / 2
    left, right = _gl(seg, a, m), _gl(seg, m, b)
    if depth > 30 or abs(left + right - whole) <= tol * max(abs(whole), 1e-300):
        return left + right
    return cubic_length(seg, a, m, tol, depth + 1) + cubic_length(seg, m, b, tol, depth + 1)


def cubic_point(seg, t):
    (x0, y0), (x1, y1), (x2, y2), (x3, y3) = seg
    u = 1 - t
    return (
        u**3 * x0 + 3 * u * u * t * x1 + 3 * u * t * t * x2 + t**3 * x3,
        u**3 * y0 + 3 * u * u * t * y1 + 3 * u * t * t * y2 + t**3 * y3,
    )


def raw_transform(elem):
    """Composed transform from the raw attribute strings (inkex 1.2's composed_transform()
    rewrites each transform it reads, rounded to 6 digits, which would skew later reads)."""
    result = inkex.Transform()
    for node in reversed([elem] + [a for a in elem.ancestors() if isinstance(a, inkex.BaseElement)]):
        result = result @ inkex.Transform(node.attrib.get("transform"))
    return result


def segments(elem):
    """The element's outline in document user units as cubic segments (first subpath),
    starting at its first node, closing back to it. Uses inkex for transforms and parsing."""
    path = elem.path.to_absolute().transform(raw_transform(elem))
    sub = path.to_superpath()[0]
    segs = []
    for (_, a, ar), (bl, b, _) in zip(sub, sub[1:]):
        segs.append((tuple(a), tuple(ar), tuple(bl), tuple(b)))
    first, last = sub[0][1], sub[-1][1]
    if math.dist(first, last) > 0:
        segs.append((tuple(last), tuple(last), tuple(first), tuple(first)))
    return [s for s in segs if cubic_length(s) > 0]


def perimeter(elem):
    return sum(cubic_length(s) for s in segments(elem))


def signed_area_y_up(segs, n=64):
    """Shoelace on a fine sampling: positive = counter-clockwise for y up (the core's convention)."""
    pts = [cubic_point(s, k / n) for s in segs for k in range(n)]
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1])) / 2


def point_at(segs, s):
    """Point at arc length ``s`` (mod the perimeter) from the first node, walking the
    segments in order: bisection on the quadrature length within the segment."""
    total = sum(cubic_length(g) for g in segs)
    s %= total
    for g in segs:
        length = cubic_length(g)
        if s <= length:
            lo, hi = 0.0, 1.0
            for _ in range(60):
                mid = (lo + hi) / 2
                if cubic_length(g, 0.0, mid) < s:
                    lo = mid
                else:
                    hi = mid
            return cubic_point(g, (lo + hi) / 2)
        s -= length
    return cubic_point(segs[-1], 1.0)


def reverse(segs):
    """The same outline walked the other way, still starting at the first node."""
    return [(d, c, b, a) for (a, b, c, d) in reversed(segs)]


def inside(segs, p, n=256):
    """Even-odd point-in-polygon on a fine sampling of the outline."""
    pts = [cubic_point(s, k / n) for s in segs for k in range(n)]
    x, y = p
    result = False
    for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            result = not result
    return result


def distance(segs, p, n=64):
    """Distance from ``p`` to the outline, over ``n`` chords per segment (exact for straight
    segments, whose chords lie on them)."""
    pts = [cubic_point(s, k / n) for s in segs for k in range(n)]
    best = math.inf
    for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]):
        dx, dy = x1 - x0, y1 - y0
        l2 = dx * dx + dy * dy
        t = 0.0 if l2 == 0 else max(0.0, min(1.0, ((p[0] - x0) * dx + (p[1] - y0) * dy) / l2))
        best = min(best, math.hypot(p[0] - x0 - t * dx, p[1] - y0 - t * dy))
    return best


def rel(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)
