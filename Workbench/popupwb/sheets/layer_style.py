"""Layer names, colours and line patterns: one table shared by the DXF, SVG, PDF and PNG writers,
so a cutter or a person sees the same convention in every file (docs/SHEET_FORMAT.md, "Layers and
styles"). Change it with dataclasses.replace, e.g.
`replace(SheetStyle(), cut=replace(SheetStyle().cut, name="Schnitt"))`; the maker's preferences
(popupwb/preferences.py) give the style `popup sheet` and Export cutting sheets write with.
"""

from dataclasses import dataclass
from typing import Tuple


@dataclass(frozen=True)
class LayerStyle:
    name: str  # DXF layer, SVG Inkscape layer label and id
    aci: int  # AutoCAD colour index, DXF only
    rgb: Tuple[int, int, int]  # 0-255, SVG/PDF/PNG; the defaults are the ACI colours
    linetype: str = "CONTINUOUS"  # DXF linetype name
    dashes: Tuple[float, ...] = ()  # mm: dash, gap, dash, gap...; empty for a solid line
    line_width: float = 0.2  # mm, SVG/PDF/PNG (DXF lines stay hairlines, as cutters expect)

    def __post_init__(self):
        if not self.name:
            raise ValueError("layer style: empty layer name")
        if not 1 <= self.aci <= 255:
            raise ValueError(f"layer style {self.name}: ACI colour {self.aci} outside 1..255")
        if len(self.rgb) != 3 or any(not 0 <= channel <= 255 for channel in self.rgb):
            raise ValueError(f"layer style {self.name}: rgb {self.rgb} is not three 0..255 values")
        if len(self.dashes) % 2 or any(length <= 0 for length in self.dashes):
            raise ValueError(
                f"layer style {self.name}: dashes {self.dashes} must be positive dash/gap pairs"
            )
        if self.line_width <= 0:
            raise ValueError(f"layer style {self.name}: line width must be positive")

    def hex_colour(self):
        return "#{:02x}{:02x}{:02x}".format(*self.rgb)

    def unit_colour(self):
        """The colour as 0..1 floats (reportlab, matplotlib)."""
        return tuple(channel / 255.0 for channel in self.rgb)


@dataclass(frozen=True)
class SheetStyle:
    cut: LayerStyle = LayerStyle("CUT", 1, (255, 0, 0))
    mountain: LayerStyle = LayerStyle(
        "MOUNTAIN", 5, (0, 0, 255), "DASHDOT", dashes=(3.0, 1.0, 0.5, 1.0)
    )
    valley: LayerStyle = LayerStyle("VALLEY", 3, (0, 255, 0), "DASHED", dashes=(3.0, 1.5))
    glue: LayerStyle = LayerStyle("GLUE", 8, (128, 128, 128), line_width=0.1)
    label: LayerStyle = LayerStyle("LABEL", 7, (0, 0, 0))
    # Glue areas are filled in SVG/PDF/PNG so they stand out on the printed sheet.
    glue_fill: Tuple[int, int, int] = (217, 217, 217)

    def __post_init__(self):
        names = [layer.name.upper() for layer in self.layers()]
        if len(set(names)) != len(names):
            raise ValueError(f"sheet style: layer names repeat: {names}")

    def layers(self):
        return (self.cut, self.mountain, self.valley, self.glue, self.label)

    def fold(self, direction):
        """The layer of a fold by its direction, "mountain" or "valley"."""
        return {"mountain": self.mountain, "valley": self.valley}[direction]

    def glue_fill_unit(self):
        return tuple(channel / 255.0 for channel in self.glue_fill)


def nearest_aci(rgb):
    """The AutoCAD colour index (1..255) closest to (r, g, b), for a DXF layer of a colour the user
    chose (cutters read the index; ACI 7 draws black on white). Needs ezdxf."""
    from ezdxf.colors import DXF_DEFAULT_COLORS

    if tuple(rgb) == (0, 0, 0):
        return 7

    def distance(aci):
        value = DXF_DEFAULT_COLORS[aci]
        other = ((value >> 16) & 0xFF, (value >> 8) & 0xFF, value & 0xFF)
        return sum((a - b) ** 2 for a, b in zip(rgb, other))

    return min(range(1, 256), key=distance)
