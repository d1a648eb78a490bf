"""What `popup verify` reads back from a cutting file (dxf_reader.py), as plain Python in mm: the
fields of popupcore.SheetDrawing, and the error of a file that cannot be read as one."""

from dataclasses import dataclass, field
from typing import List, Tuple

Point = Tuple[float, float]
Loop = List[Point]


class DxfReadError(ValueError):
    """A DXF that cannot be read as a cutting file; the message is one line naming the file,
    the layer and the entity."""


@dataclass
class DrawnFoldLine:
    start: Point
    end: Point
    direction: str  # "mountain" or "valley": its layer


@dataclass
class DrawnLabel:
    text: str
    position: Point  # the centre of the text's cap height


@dataclass
class Drawing:
    """What one cutting file holds, in mm: the fields of popupcore.SheetDrawing."""

    name: str
    kerf: float
    cut: List[Loop] = field(default_factory=list)
    folds: List[DrawnFoldLine] = field(default_factory=list)
    glue: List[Loop] = field(default_factory=list)
    labels: List[DrawnLabel] = field(default_factory=list)

    def to_sheet_drawing(self, popupcore):
        drawing = popupcore.SheetDrawing()
        drawing.name = self.name
        drawing.kerf = self.kerf
        drawing.cut = self.cut
        drawing.folds = [popupcore.DrawnFold(f.start, f.end, f.direction) for f in self.folds]
        drawing.glue = self.glue
        drawing.labels = [popupcore.DrawnText(t.text, t.position) for t in self.labels]
        return drawing
