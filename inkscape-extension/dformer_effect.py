"""What every D-former effect shares: lengths in the user's unit, selection reading, and the
rule that the document is only written after everything has been computed.

Each effect implements ``compute()`` (reads the document, calls the core, returns a function
that writes the result). Any ``CoreError`` — a message from the core or from the selection
checks — becomes ``inkex.AbortExtension``: Inkscape shows it as an error and, because the
writer never ran, the document is unchanged.
"""

import math
import re

import inkex
from inkex.units import CONVERSIONS

from dformer_bridge import CoreError, advise
from dformer_pieces import describe, name_pieces, selected_shapes
from dformer_viewport import page_px_per_user

UNITS = ("mm", "cm", "in", "pt", "pc", "px")

_NUMBER = r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)"
_MISMATCH = re.compile(r"different perimeters \(" + _NUMBER + " and " + _NUMBER + ";")


class DformerEffect(inkex.EffectExtension):
    """Base class: subclasses define ``compute(self)`` returning a no-argument writer."""

    #: (minimum, maximum) number of pieces the effect works on; None = no maximum.
    piece_count = (1, None)

    def add_arguments(self, pars):
        pars.add_argument(
            "--unit",
            default="document",
            help="Unit of every length option and of reported lengths: document, mm, cm, in, pt, pc, px",
        )

    # -- units -------------------------------------------------------------------------------

    def unit(self):
        """The unit the user works in: the option, or the document's display unit."""
        unit = self.options.unit
        if unit == "document":
            unit = self.svg.document_unit or "px"
        if unit not in UNITS:
            raise CoreError(f"Unit {unit!r} is not one of {', '.join(UNITS)}.")
        return unit

    def px_per_user(self):
        """CSS px per document user unit, as Inkscape draws the page (``dformer_viewport``)."""
        if not hasattr(self, "_px_per_user"):
            self._px_per_user = page_px_per_user(self.svg)
        return self._px_per_user

    def to_user(self, value):
        """A length in the user's unit -> document user units (through the page's scale)."""
        return value * CONVERSIONS[self.unit()] / self.px_per_user()

    def from_user(self, value):
        """Document user units -> the user's unit."""
        return value * self.px_per_user() / CONVERSIONS[self.unit()]

    def fmt(self, value):
        """A length in user units written for a report, e.g. ``314.1593 mm``."""
        return f"{self.from_user(value):.4f} {self.unit()}"

    #: True while the core works in the user's unit (``in_unit``): the lengths in its messages
    #: are then in that unit already.
    core_in_unit = False

    def in_unit(self, paths):
        """Core paths in document user units -> the same paths in the user's unit (the display
        unit unless ``--unit`` says otherwise). A core called with these, and with the lengths
        the user typed as they are, speaks the user's unit in every message and warning, rounded
        by its own rule (4 significant digits). ``from_unit`` maps its results back."""
        self.core_in_unit = True
        return [self._scaled(p, self.from_user(1.0)) for p in paths]

    def from_unit(self, path):
        """A core path in the user's unit -> document user units."""
        return self._scaled(path, self.to_user(1.0))

    @staticmethod
    def _scaled(path, k):
        if k == 1.0:
            return path
        return {
            **path,
            "points": [
                {key: [v * k for v in pt[key]] for key in ("anchor", "left", "right") if pt.get(key) is not None}
                for pt in path["points"]
            ],
        }

    def message_len(self, value):
        """A length from a core message in the user's unit, 4 significant digits (the core's
        rule), e.g. ``55.64 mm``."""
        v = float(f"{value if self.core_in_unit else self.from_user(value):.4g}")
        text = f"{v:.{max(0, 3 - math.floor(math.log10(abs(v))))}f}" if v else "0"
        if "." in text:
            text = text.rstrip("0").rstrip(".")
        return f"{text} {self.unit()}"

    # -- selection ---------------------------------------------------------------------------

    def pieces(self):
        """The selected shapes (selection order), checked against ``piece_count``."""
        self.px_per_user()  # a page that stretches unequally is refused before anything else
        shapes, refused = selected_shapes(self.svg)
        if refused:
            names = ", ".join(describe(e) for e in refused)
            raise CoreError(f"D-former works on paths and shapes; it cannot use {names}.")
        low, high = self.piece_count
        want = f"exactly {low}" if low == high else f"at least {low}" if high is None else f"{low} to {high}"
        if len(shapes) < low or (high is not None and len(shapes) > high):
            raise CoreError(
                f"Select {want} closed path{'s' if (high or low) != 1 else ''} "
                f"(or groups of them); {len(shapes)} selected."
            )
        self.shapes = shapes
        return shapes

    # -- the effect --------------------------------------------------------------------------

    def compute(self):
        raise NotImplementedError

    def user_message(self, message):
        """A core message for the student: pieces named by object, and the two perimeters of
        a mismatch (raw numbers from the core) rounded, in the user's unit."""
        shapes = getattr(self, "shapes", [])
        # What to do, in Inkscape's menus (the core and this extension say it in plain words).
        message = name_pieces(advise(message), shapes)

        def perimeters(match):
            a, b = (float(v) for v in match.groups())
            names = [describe(e) for e in shapes[:2]] if len(shapes) >= 2 else ["", ""]
            return "different perimeters (" + " and ".join(
                f"{name + ' ' if name else ''}{self.message_len(v)}" for name, v in zip(names, (a, b))
            ) + ";"

        try:
            return _MISMATCH.sub(perimeters, message)
        except CoreError:  # an unknown display unit: keep the core's numbers
            return message

    def effect(self):
        try:
            write = self.compute()
        except CoreError as err:
            raise inkex.AbortExtension(self.user_message(str(err))) from err
        if write is not None:
            write()
