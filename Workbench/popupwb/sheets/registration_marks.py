"""Registration marks for print-then-cut, shared by the PDF and the SVG print layer: filled black
squares of MARK_SIZE mm in the top-left, top-right and bottom-left corners, each centred in the
margin band (so it stays clear of the pieces); the bottom-right corner is left empty so the
cutter's camera can tell the sheet's orientation. Sheet coordinates: mm, origin lower left.
"""

MARK_SIZE = 5.0  # mm
CLEARANCE = 0.5  # mm, least distance between a mark and the printable pieces


def check_room_for_marks(margin):
    """ValueError when the margin band is too narrow to hold the marks clear of the pieces."""
    needed = MARK_SIZE + 2 * CLEARANCE
    if margin < needed:
        raise ValueError(
            f"registration marks need a margin of at least {needed:g} mm; the sheet set has "
            f"{margin:g} mm"
        )


def mark_squares(width, height, margin):
    """The lower-left corners (x, y) of the three MARK_SIZE squares on a width x height sheet."""
    inset = (margin - MARK_SIZE) / 2.0
    far_x = width - inset - MARK_SIZE
    far_y = height - inset - MARK_SIZE
    return ((inset, far_y), (far_x, far_y), (inset, inset))
