"""Which paper a layout goes on when the user names none.

    sheet_set, choice = layout_on_smallest_paper(scaffold, margin=10.0)

The core knows four paper presets (popupcore.paper_size): A4 and A3 (ISO 216), Letter and Tabloid
(US). A piece fits a paper when its cut outline's bounding box fits the printable area (the paper
less the margin on every side), upright or turned a quarter (the nester turns pieces by quarter
turns). The chosen paper is the smallest preset by area that holds every piece, looking first at
the presets of the machine's paper family (libpaper's setting: $PAPERSIZE, else /etc/papersize;
ISO when neither says otherwise), so a small design on an A4 machine lands on A4, not on the
slightly smaller Letter that its printer has no tray for. No FreeCAD needed.
"""

import os
from dataclasses import dataclass

from .sheet_set import points

FAMILIES = {"iso": ("A4", "A3"), "us": ("Letter", "Tabloid")}
# libpaper's names of US paper sizes (papersize(5)); every other name is ISO or metric.
US_PAPER_NAMES = {"letter", "legal", "executive", "tabloid", "ledger", "11x17", "halfletter"}
PAPERSIZE_FILE = "/etc/papersize"
# The core's largest custom paper (kLargestCustomSide in core/src/sheets/nest/paper.cpp): every piece a
# preset could hold lies flat on it, so one layout on it measures the pieces.
MEASURING_PAPER = "1000x1000"


@dataclass(frozen=True)
class Paper:
    name: str
    width: float  # mm
    height: float  # mm

    def area(self):
        return self.width * self.height

    def holds(self, size, margin):
        """True when a piece of `size` (width, height in mm) fits inside the margins, upright or
        turned a quarter."""
        room = (self.width - 2.0 * margin, self.height - 2.0 * margin)
        w, h = size
        return (w <= room[0] and h <= room[1]) or (h <= room[0] and w <= room[1])


@dataclass(frozen=True)
class PieceSize:
    id: str
    width: float  # mm, bounding box of the cut outline as the sheet set places it
    height: float

    def text(self):
        return f"piece {self.id} ({self.width:.1f} x {self.height:.1f} mm)"


@dataclass(frozen=True)
class PaperChoice:
    paper: Paper
    family: str  # the family looked at first: "iso" or "us"
    largest_piece: PieceSize  # the piece of largest bounding-box area
    margin: float

    def text(self):
        return (
            f"paper {self.paper.name} ({self.paper.width:g} x {self.paper.height:g} mm) chosen "
            f"automatically: the smallest preset holding every piece with {self.margin:g} mm "
            f"margins (largest: {self.largest_piece.text()}; {self.family.upper()} sizes first)"
        )


class NoPaperFits(ValueError):
    """No preset holds some piece; the message names the piece, its size and the largest preset."""


def system_paper_family(environ=None, papersize_file=PAPERSIZE_FILE):
    """'us' when libpaper's setting names a US size, else 'iso'."""
    environ = os.environ if environ is None else environ
    name = environ.get("PAPERSIZE", "").strip()
    if not name:
        try:
            with open(papersize_file, encoding="utf-8") as f:
                lines = [line.strip() for line in f if line.strip()]
            name = next((line for line in lines if not line.startswith("#")), "")
        except OSError:
            name = ""
    return "us" if name.lower() in US_PAPER_NAMES else "iso"


def presets(family):
    """Every preset, those of `family` first, each family smallest area first."""
    from popupwb.core import popupcore

    def papers(names):
        return sorted((Paper(*popupcore.paper_size(name)) for name in names), key=Paper.area)

    others = [name for key, names in FAMILIES.items() if key != family for name in names]
    return papers(FAMILIES[family]) + papers(others)


def _loop_area(loop):
    return abs(
        sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(loop, loop[1:] + loop[:1])) / 2.0
    )


def piece_sizes(sheet_set):
    """Bounding box of each piece's largest cut region (of the popupcore.SheetSet `sheet_set`),
    the outline the core checks against the paper (core/src/sheets/sheet_layout.cpp)."""
    sizes = []
    for piece in sheet_set.pieces:
        outer = max((points(region.outer) for region in piece.cut), key=_loop_area)
        xs = [x for x, _ in outer]
        ys = [y for _, y in outer]
        sizes.append(PieceSize(piece.id, max(xs) - min(xs), max(ys) - min(ys)))
    return sizes


def choose_paper(sizes, margin, family):
    """The PaperChoice for pieces of `sizes`; NoPaperFits when no preset holds one of them."""
    candidates = presets(family)
    for piece in sorted(sizes, key=lambda p: p.width * p.height, reverse=True):
        if not any(paper.holds((piece.width, piece.height), margin) for paper in candidates):
            largest = max(candidates, key=Paper.area)
            raise NoPaperFits(
                f"{piece.text()} fits on no paper preset with {margin:g} mm margins (largest "
                f"preset: {largest.name}, {largest.width:g} x {largest.height:g} mm); name a "
                f"larger paper as WxH mm (at most 1000 mm a side)"
            )
    largest_piece = max(sizes, key=lambda p: p.width * p.height)
    for paper in candidates:
        if all(paper.holds((p.width, p.height), margin) for p in sizes):
            return PaperChoice(paper, family, largest_piece, margin)
    # Each piece fits some preset but no preset holds them all (a long piece and a wide one).
    raise NoPaperFits(
        f"no paper preset holds every piece with {margin:g} mm margins (largest: "
        f"{largest_piece.text()}); name a paper as WxH mm"
    )


def layout_on_smallest_paper(scaffold, family=None, **options):
    """(sheet set, PaperChoice): the scaffold laid out on the smallest preset holding every piece.
    Raises NoPaperFits, or popupcore.DesignError (a ValueError) for a bad option."""
    from .export import layout

    if "paper" in options:
        raise ValueError("layout_on_smallest_paper chooses the paper: do not pass paper")
    measured = layout(scaffold, paper=MEASURING_PAPER, **options)
    margin = measured.options.margin
    choice = choose_paper(piece_sizes(measured), margin, family or system_paper_family())
    return layout(scaffold, paper=choice.paper.name, **options), choice
