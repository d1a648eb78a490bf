"""The TechDraw template of a cutting-sheet page: exactly the paper (so the page is drawn at 1:1
whatever the paper), with a line legend and a title block in the bottom margin band, where the
exported sheets leave the paper blank.

Legend (left): a sample of the cut, mountain and valley lines and of a glue area, in the colours
and dashes of layer_style.SheetStyle, each with its name. Title block (right): the card, the
paper, "sheet n of m" and the scale, each value a TechDraw editable text (TITLE_FIELDS), so the
maker can change it on the page like in TechDraw's own templates. Text is the labels' font; it is
as large as the band allows (up to TITLE_CAP_HEIGHT) and shrinks, down to SMALLEST_CAP_HEIGHT, to
fit across the paper. No FreeCAD needed.
"""

import re
from dataclasses import dataclass
from xml.sax.saxutils import escape, quoteattr

from .layer_style import SheetStyle
from .not_valid_stamp import CAP_HEIGHT_PER_EM, SMALLEST_CAP_HEIGHT, STAMP_FONT
from .svg_writer import FONT_FAMILY

FREECAD_NAMESPACE = "http://www.freecadweb.org/wiki/index.php?title=Svg_Namespace"
TITLE_CAP_HEIGHT = 2.5  # mm: ISO 3098's smallest lettering for drawings
# Editable text names, in the order the title block shows them, with the caption before each.
TITLE_FIELDS = (("CardName", "Card"), ("Paper", "Paper"), ("Sheet", "Sheet"), ("Scale", "Scale"))
_SAMPLE = 4.0  # line sample length, in cap heights
_GAP = 1.2  # between a sample and its name, and between captions and values, in cap heights
_SPACE = 3.0  # between legend entries and title fields, in cap heights
_BOLD = STAMP_FONT + "-Bold"  # the values; captions and legend are regular


@dataclass(frozen=True)
class TitleBlock:
    card: str
    paper: str  # "A4 210 x 297 mm"
    sheet: int  # 1-based
    sheets: int
    scale: str = "1:1"

    def fields(self):
        """{editable text name: value}, as the page template's EditableTexts."""
        values = (self.card, self.paper, f"{self.sheet} of {self.sheets}", self.scale)
        return {name: value for (name, _), value in zip(TITLE_FIELDS, values)}


def paper_text(name, width, height):
    """A sheet set's paper (its name, width and height in mm) as the title block shows it:
    "A4 210 x 297 mm"."""
    size = f"{width:g} x {height:g} mm"
    name = name or ""
    custom = re.fullmatch(r"[0-9.]+x[0-9.]+", name)  # the core names a custom paper "WxH"
    return size if not name or custom else f"{name} {size}"


def _text_width(text, cap, font=STAMP_FONT):
    from reportlab.pdfbase.pdfmetrics import stringWidth

    return stringWidth(text, font, cap / CAP_HEIGHT_PER_EM)


def _legend_entries(style):
    return (
        (style.cut, "cut"),
        (style.mountain, "mountain fold"),
        (style.valley, "valley fold"),
        (style.glue, "glue"),
    )


def _widths(title, style, cap):
    legend = (
        sum(
            _SAMPLE * cap + _GAP * cap + _text_width(name, cap)
            for _, name in _legend_entries(style)
        )
        + _SPACE * cap * 3
    )
    fields = title.fields()
    block = sum(
        _text_width(f"{caption}:", cap) + _GAP * cap + _text_width(fields[name], cap, _BOLD)
        for name, caption in TITLE_FIELDS
    ) + _SPACE * cap * (len(TITLE_FIELDS) - 1)
    return legend, block


def cap_height(width, margin, title, style=None):
    """The legend's and title block's cap height on a paper `width` mm wide with `margin`."""
    style = style or SheetStyle()
    band = max(margin, 2.0 * SMALLEST_CAP_HEIGHT)
    cap = min(TITLE_CAP_HEIGHT, 0.5 * band)
    room = width - 2.0 * max(margin, SMALLEST_CAP_HEIGHT)
    legend, block = _widths(title, style, cap)
    needed = legend + _SPACE * cap + block
    if needed > room:
        cap = max(SMALLEST_CAP_HEIGHT, cap * room / needed)
    return cap


def template_svg(width, height, margin, title, style=None):
    """The template's SVG text for a `width` x `height` mm paper with `margin` mm borders."""
    style = style or SheetStyle()
    cap = cap_height(width, margin, title, style)
    font = cap / CAP_HEIGHT_PER_EM
    band = max(margin, 2.0 * SMALLEST_CAP_HEIGHT)
    left = max(margin, SMALLEST_CAP_HEIGHT)
    baseline = height - band / 2.0 + cap / 2.0  # SVG y points down: cap centred in the band
    middle = height - band / 2.0
    colour = style.label.hex_colour()
    text_style = f'font-family={quoteattr(FONT_FAMILY)} font-size="{font:.4f}" fill="{colour}"'
    parts = []

    x = left
    for layer, name in _legend_entries(style):
        end = x + _SAMPLE * cap
        stroke = f'stroke="{layer.hex_colour()}" stroke-width="{layer.line_width:g}"'
        if layer is style.glue:
            fill = "#{:02x}{:02x}{:02x}".format(*style.glue_fill)
            parts.append(
                f'<rect x="{x:.4f}" y="{middle - cap / 2:.4f}" width="{end - x:.4f}" '
                f'height="{cap:.4f}" fill="{fill}" {stroke}/>'
            )
        else:
            dashes = " ".join(f"{d:g}" for d in layer.dashes)
            dash = f' stroke-dasharray="{dashes}"' if dashes else ""
            parts.append(
                f'<line x1="{x:.4f}" y1="{middle:.4f}" x2="{end:.4f}" y2="{middle:.4f}" '
                f"{stroke}{dash}/>"
            )
        x = end + _GAP * cap
        parts.append(f'<text x="{x:.4f}" y="{baseline:.4f}" {text_style}>{escape(name)}</text>')
        x += _text_width(name, cap) + _SPACE * cap

    # The title block, right-aligned on the right margin: caption, then its editable value.
    fields = title.fields()
    _, block = _widths(title, style, cap)
    x = width - left - block
    for name, caption in TITLE_FIELDS:
        parts.append(f'<text x="{x:.4f}" y="{baseline:.4f}" {text_style}>{escape(caption)}:</text>')
        x += _text_width(f"{caption}:", cap) + _GAP * cap
        parts.append(
            f'<text freecad:editable="{name}" x="{x:.4f}" y="{baseline:.4f}" {text_style} '
            f'font-weight="bold"><tspan>{escape(fields[name])}</tspan></text>'
        )
        x += _text_width(fields[name], cap, _BOLD) + _SPACE * cap

    body = "\n  ".join(parts)
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        f'<svg xmlns="http://www.w3.org/2000/svg" xmlns:freecad="{FREECAD_NAMESPACE}" '
        f'version="1.1" width="{width:g}mm" height="{height:g}mm" '
        f'viewBox="0 0 {width:g} {height:g}">\n  {body}\n</svg>\n'
    )
