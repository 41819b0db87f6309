"""Golden-file tests in inkex's own style (inkex.tester.ComparisonMixin): each effect runs on
the SVG fixtures in data/svg with the listed arguments and its output is compared with
data/refs/*.out after CompareNumericFuzzy (numbers rounded to 3 decimals) and order-independent
styles. Regenerate (inkex's switch) with EXPORT_COMPARE=2 (write missing goldens) or
EXPORT_COMPARE=3 (overwrite them) — run it until it passes, inkex re-checks one file per run —
and look at the new files before committing them; EXPORT_COMPARE=1 writes the output beside
a failing golden for inspection.

Fixtures: paths inside transformed (rotated, scaled, mirrored, nested) groups; a millimetre
document (viewBox in mm) and pixel documents (with and without viewBox); shapes drawn
clockwise and counter-clockwise; rect, circle-as-arcs, ellipse, polygon and curved paths."""

import support  # noqa: F401  (import paths and DFORMER_BIN)

from inkex.tester import ComparisonMixin, TestCase
from inkex.tester.filters import CompareNumericFuzzy, CompareOrderIndependentStyle

from dformer_connect import Connect
from dformer_measure import Measure
from dformer_normalize import Normalize

FILTERS = [CompareNumericFuzzy(), CompareOrderIndependentStyle()]


class NormalizeGoldenMm(ComparisonMixin, TestCase):
    effect_class = Normalize
    compare_filters = FILTERS
    compare_file = ["svg/pieces_mm.svg"]  # a list: the file name goes into the golden's name
    comparisons = [
        ("--id=A", "--id=B", "--id=C"),
        ("--id=B", "--id=A", "--target=first", "--pivot=centroid"),
        ("--id=A", "--id=B", "--id=C", "--target=length", "--length=10", "--unit=cm"),
    ]

    def test_default_settings(self):
        """Without a selection the effect must refuse (it needs two pieces): tested in
        test_properties; inkex's default no-argument run does not apply here."""


class NormalizeGoldenPx(ComparisonMixin, TestCase):
    effect_class = Normalize
    compare_filters = FILTERS
    compare_file = ["svg/pieces_px.svg"]  # a list: the file name goes into the golden's name
    comparisons = [
        ("--id=D", "--id=E", "--target=smallest"),
        ("--id=E", "--id=D", "--target=mean", "--unit=mm"),
    ]

    def test_default_settings(self):
        """See NormalizeGoldenMm."""


class ConnectGoldenMm(ComparisonMixin, TestCase):
    effect_class = Connect
    compare_filters = FILTERS
    compare_file = ["svg/connect_mm.svg"]  # a list: the file name goes into the golden's name
    comparisons = [
        ("--id=A", "--id=B", "--kind=stitch", "--count=12", "--slide=0.25"),
        ("--id=A", "--id=B", "--kind=teeth", "--count=16", "--slide=0.5", "--length=2"),
        ("--id=A", "--id=B", "--kind=leaves", "--count=8", "--slide=0.5"),
    ]

    def test_default_settings(self):
        """See NormalizeGoldenMm."""


class ConnectGoldenPx(ComparisonMixin, TestCase):
    effect_class = Connect
    compare_filters = FILTERS
    compare_file = ["svg/connect_px.svg"]  # a list: the file name goes into the golden's name
    comparisons = [
        ("--id=A", "--id=B", "--kind=leaves", "--count=12", "--slide=0.25", "--labels=false"),
        # Labels off: the 40 × 30 triangle has no room for numbers clear of its teeth and leaves
        # at its sharp corners (the core says so in a warning, which would fail the comparison).
        ("--id=A", "--id=B", "--kind=teeth", "--count=12", "--slide=0.25", "--length=2", "--labels=false"),
        ("--id=B", "--id=A", "--kind=leaves", "--spacing=pitch", "--pitch=50", "--invert=true", "--labels=false"),
    ]

    def test_default_settings(self):
        """See NormalizeGoldenMm."""


class MeasureGolden(ComparisonMixin, TestCase):
    """Measure reports on stderr (Inkscape shows it in a message box): the golden is the text."""

    effect_class = Measure
    stderr_output = True
    compare_file = ["svg/pieces_mm.svg"]  # a list: the file name goes into the golden's name
    comparisons = [("--id=A", "--id=B", "--id=C"), ("--id=C", "--unit=in")]

    def test_default_settings(self):
        """See NormalizeGoldenMm."""
