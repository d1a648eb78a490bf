"""Reads a DXF cutting file back: only what the maker receives, for `popup verify`.

    drawing = read_dxf("out/sheets/sheets.dxf")          # a Drawing, plain Python
    sheet_drawing = drawing.to_sheet_drawing(popupcore)  # a popupcore.SheetDrawing

What is read (docs/SHEET_FORMAT.md, "What popup verify reads"), from modelspace, with the entities
inside block references (INSERT, nested, MINSERT arrays) visited as well; layer names are those
of layer_style.SheetStyle, matched regardless of case; an entity on layer 0 inside a block takes
the layer of its INSERT, as CAD programs draw it:

- CUT: closed loops, any orientation. A closed LWPOLYLINE or POLYLINE (or one whose last vertex
  returns to its first), a CIRCLE, a closed SPLINE or a full ELLIPSE is a loop by itself; LINEs,
  ARCs and open polylines, splines and elliptic arcs are joined end to end into loops (ends within
  CHAIN_TOLERANCE). Arcs, bulges and curves are flattened to chords at most FLATTEN_TOLERANCE
  from the curve. A line that does not close, three lines meeting at one end, or an entity of
  another type on CUT is an error: the cutter would cut something the reader cannot check.
- MOUNTAIN and VALLEY: straight LINEs, or polylines whose collinear runs each give one fold.
- GLUE: closed polylines, vertex order kept (the first edge is where the tab's crease lands).
- LABEL: TEXT and MTEXT, by the centre of the text's cap height (the writer's MIDDLE_CENTER
  placement point; other alignments measured with ezdxf's font metrics).
- The header's custom property PopUpKerf (mm), the kerf the CUT lines were written with.

Other layers, and hatches, points and dimensions on GLUE and LABEL, are ignored. Coordinates are
converted to mm from the header's $INSUNITS (unset or unitless: mm). Every problem raises
DxfReadError (a ValueError) with one line naming the file, the layer and the entity's handle.
No FreeCAD needed.
"""

import contextlib
import logging
import math
import os
from dataclasses import dataclass
from typing import List

import ezdxf
from ezdxf.math import Vec3

from popupwb.readable_file import unreadable

from .drawn_sheet import Drawing, DrawnFoldLine, DrawnLabel, DxfReadError, Point
from .dxf_writer import KERF_PROPERTY
from .layer_style import SheetStyle

CHAIN_TOLERANCE = 1e-6  # mm: two CUT line ends this close are one point
FLATTEN_TOLERANCE = 1e-3  # mm: largest distance between an arc or curve and its chords
COLLINEAR_TOLERANCE = 1e-6  # mm: a fold polyline's vertex this close to the line is on it
MAX_BLOCK_DEPTH = 16  # nested block references; deeper is taken for a reference cycle
SHEETS_DXF = "sheets.dxf"  # the file `popup sheet --out DIR` writes with every sheet

# $INSUNITS codes and millimetres per drawing unit; 0 (unitless) is taken for mm.
UNITS_TO_MM = {0: 1.0, 1: 25.4, 2: 304.8, 4: 1.0, 5: 10.0, 6: 1000.0, 8: 25.4e-6, 9: 25.4e-3}

_CUT_TYPES = ("LINE", "ARC", "CIRCLE", "ELLIPSE", "SPLINE", "LWPOLYLINE", "POLYLINE")
_IGNORED_TYPES = ("HATCH", "SOLID", "POINT", "DIMENSION", "MPOLYGON", "WIPEOUT", "IMAGE")


def sheets_path(path):
    """The DXF to read for `path`: path itself, or <path>/sheets.dxf for a folder."""
    if os.path.isdir(path):
        dxf = os.path.join(path, SHEETS_DXF)
        if not os.path.isfile(dxf):
            raise DxfReadError(
                f"{path}: folder without {SHEETS_DXF} (popup sheet --out {path} writes it)"
            )
        return dxf
    return path


def read_sheet_drawing(path, popupcore, kerf=None, style=None):
    """read_dxf(...) as a popupcore.SheetDrawing."""
    return read_dxf(path, kerf=kerf, style=style).to_sheet_drawing(popupcore)


def read_dxf(path, kerf=None, style=None):
    """The Drawing of the DXF at `path` (a file, or a folder holding sheets.dxf). `kerf` (mm),
    when given, is used instead of the header's PopUpKerf; without it a file lacking PopUpKerf
    is a DxfReadError."""
    path = sheets_path(path)
    doc = _open(path)
    reader = _Reader(path, doc, style or SheetStyle())
    kerf = _header_kerf(path, doc) if kerf is None else _checked_kerf(path, "--kerf", kerf)
    return reader.read(kerf)


def _open(path):
    why = unreadable(path)
    if why:
        raise DxfReadError(why)
    try:
        return ezdxf.readfile(path)
    except Exception as e:  # ezdxf raises structure, encoding and value errors of every kind
        # A file cut short leaves ezdxf's tag reader with no message (StopIteration).
        reason = " ".join(str(e).split()) or f"it ends early or is damaged: {type(e).__name__}"
        raise DxfReadError(f"{path}: not a readable DXF file ({reason})") from None


def _header_kerf(path, doc):
    custom = doc.header.custom_vars
    for tag, value in custom:
        if tag.lower() == KERF_PROPERTY.lower():
            try:
                number = float(value)
            except (TypeError, ValueError):
                raise DxfReadError(
                    f"{path}: header property {KERF_PROPERTY} = {value!r} is not a number"
                ) from None
            return _checked_kerf(path, f"header property {KERF_PROPERTY}", number)
    raise DxfReadError(
        f"{path}: the header has no custom property {KERF_PROPERTY} (the kerf the CUT lines "
        "were written with): give it with --kerf MM"
    )


def _checked_kerf(path, what, kerf):
    if not math.isfinite(kerf) or kerf < 0:
        raise DxfReadError(f"{path}: {what} = {kerf:g}: the kerf must be a finite length >= 0 mm")
    return float(kerf)


@dataclass
class _Open:
    """An open CUT stroke waiting to be joined: its points and where it came from."""

    points: List[Point]
    where: str


class _Reader:
    def __init__(self, path, doc, style):
        self.path = path
        self.doc = doc
        self.style = style
        units = doc.header.get("$INSUNITS", 0)
        if units not in UNITS_TO_MM:
            raise DxfReadError(
                f"{path}: header $INSUNITS = {units}: only mm, cm, m, inches, feet, micro-inches "
                "and mils are read (0 or 4 for mm)"
            )
        self.scale = UNITS_TO_MM[units]
        self.layers = {
            style.cut.name.upper(): "cut",
            style.mountain.name.upper(): "mountain",
            style.valley.name.upper(): "valley",
            style.glue.name.upper(): "glue",
            style.label.name.upper(): "label",
        }
        self.layer_names = {
            "cut": style.cut.name,
            "mountain": style.mountain.name,
            "valley": style.valley.name,
            "glue": style.glue.name,
            "label": style.label.name,
        }

    def fail(self, role, where, what):
        raise DxfReadError(f"{self.path}: layer {self.layer_names[role]}: {where} {what}")

    def read(self, kerf):
        drawing = Drawing(name=os.path.basename(self.path), kerf=kerf)
        strokes = []
        for entity, layer, where in self._entities(self.doc.modelspace(), None, "", 0):
            role = self.layers.get(layer.upper())
            if role is None:
                continue
            kind = entity.dxftype()
            if role == "cut":
                self._read_cut(entity, kind, where, drawing.cut, strokes)
            elif role in ("mountain", "valley"):
                drawing.folds.extend(self._read_fold(entity, kind, where, role))
            elif role == "glue":
                loop = self._read_glue(entity, kind, where)
                if loop is not None:
                    drawing.glue.append(loop)
            elif kind in ("TEXT", "MTEXT"):
                label = self._read_label(entity, kind, where)
                if label is not None:
                    drawing.labels.append(label)
        drawing.cut.extend(self._join(strokes))
        if not drawing.cut:
            self.fail("cut", "no", "closed loop: the file holds nothing to cut")
        return drawing

    # --- walking modelspace and blocks -----------------------------------------------------

    def _entities(self, entities, insert_layer, inside, depth):
        """(entity, effective layer, description) of every entity, block references expanded."""
        for entity in entities:
            layer = entity.dxf.get("layer", "0")
            if insert_layer is not None and layer == "0":
                layer = insert_layer  # an entity on layer 0 in a block takes the INSERT's layer
            where = self._describe(entity, inside)
            if entity.dxftype() == "INSERT":
                if depth >= MAX_BLOCK_DEPTH:
                    raise DxfReadError(
                        f"{self.path}: {where}: block references nested deeper than "
                        f"{MAX_BLOCK_DEPTH} (a block that contains itself?)"
                    )
                name = entity.dxf.get("name", "?")
                try:
                    parts = [list(single.virtual_entities()) for single in entity.multi_insert()]
                except Exception as e:  # ezdxf refuses a missing block or a bad transformation
                    reason = " ".join(str(e).split()) or type(e).__name__
                    raise DxfReadError(
                        f"{self.path}: {where} (block '{name}') cannot be expanded ({reason})"
                    ) from None
                block_where = f"in block '{name}' ({where})"
                for part in parts:
                    yield from self._entities(part, layer, block_where, depth + 1)
            else:
                yield entity, layer, where

    @staticmethod
    def _describe(entity, inside):
        handle = entity.dxf.get("handle")
        name = f"{entity.dxftype()} #{handle}" if handle else entity.dxftype()
        return f"{name} {inside}" if inside else name

    # --- geometry ----------------------------------------------------------------------------

    def _xy(self, role, where, vector):
        x, y = float(vector[0]) * self.scale, float(vector[1]) * self.scale
        if not (math.isfinite(x) and math.isfinite(y)):
            self.fail(role, where, f"has a coordinate that is not a finite number ({x}, {y})")
        return (x, y)

    def _points(self, role, where, vectors):
        return [self._xy(role, where, v) for v in vectors]

    def _flattened(self, role, entity, kind, where):
        """A CIRCLE, ARC, ELLIPSE or SPLINE as WCS points on the curve, its chords within
        FLATTEN_TOLERANCE of it (ezdxf's own flattening of each curve, not of a Bezier
        approximation, which is off a circle by 2.7e-4 of its radius)."""
        tolerance = FLATTEN_TOLERANCE / self.scale
        try:
            if kind in ("CIRCLE", "ARC"):
                radius = entity.dxf.radius
                if not math.isfinite(radius) or radius <= 0:
                    self.fail(role, where, f"has radius {radius}: must be a positive number")
                vectors = list(entity.flattening(min(tolerance, radius)))
            else:
                vectors = list(entity.flattening(tolerance))
        except DxfReadError:
            raise
        except Exception as e:  # ezdxf's geometry raises on degenerate curves
            reason = " ".join(str(e).split()) or type(e).__name__
            self.fail(role, where, f"cannot be flattened ({reason})")
        return self._points(role, where, vectors)

    def _polyline(self, role, entity, kind, where):
        """(points, closed) of an LWPOLYLINE or 2D POLYLINE in WCS; arcs (bulges) flattened."""
        if kind == "POLYLINE":
            if not entity.is_2d_polyline:
                self.fail(role, where, "is a 3D polyline or mesh: only 2D polylines are read")
            closed = bool(entity.is_closed)
            raw = [
                (v.dxf.location[0], v.dxf.location[1], v.dxf.get("bulge", 0.0))
                for v in entity.vertices
            ]
            elevation = Vec3(entity.dxf.get("elevation", (0, 0, 0))).z
        else:
            closed = bool(entity.closed)
            raw = list(entity.get_points("xyb"))
            elevation = entity.dxf.get("elevation", 0.0)
        ocs_points = []
        for index, (x, y, bulge) in enumerate(raw):
            self._xy(role, where, (x, y))
            if not math.isfinite(bulge):
                self.fail(role, where, f"has a bulge that is not a finite number ({bulge})")
            ocs_points.append((x, y))
            last = index == len(raw) - 1
            if bulge and not (last and not closed):
                following = raw[0] if last else raw[index + 1]
                ocs_points.extend(self._arc_points((x, y), following[:2], bulge))
        ocs = entity.ocs()
        vectors = [ocs.to_wcs(Vec3(x, y, elevation)) for x, y in ocs_points]
        return self._points(role, where, vectors), closed

    def _arc_points(self, start, end, bulge):
        """The points strictly between `start` and `end` on the arc of a polyline segment with
        this bulge (tan of a quarter of its signed angle), chords within FLATTEN_TOLERANCE."""
        chord = math.dist(start, end)
        if chord == 0:
            return []
        angle = 4.0 * math.atan(bulge)  # counter-clockwise when positive
        radius = chord / (2.0 * abs(math.sin(angle / 2.0)))
        # The centre: from the chord's middle, along its left normal for a counter-clockwise
        # arc of under half a turn.
        mx, my = (start[0] + end[0]) / 2.0, (start[1] + end[1]) / 2.0
        nx, ny = -(end[1] - start[1]) / chord, (end[0] - start[0]) / chord
        offset = radius * math.cos(angle / 2.0)  # signed: the centre is on the other side past pi
        cx, cy = mx + nx * offset * math.copysign(1.0, bulge), my + ny * offset * math.copysign(
            1.0, bulge
        )
        tolerance = FLATTEN_TOLERANCE / self.scale
        if tolerance >= radius:
            steps = 2
        else:
            steps = max(2, math.ceil(abs(angle) / (2.0 * math.acos(1.0 - tolerance / radius))))
        first = math.atan2(start[1] - cy, start[0] - cx)
        return [
            (
                cx + radius * math.cos(first + angle * k / steps),
                cy + radius * math.sin(first + angle * k / steps),
            )
            for k in range(1, steps)
        ]

    # --- CUT ---------------------------------------------------------------------------------

    def _read_cut(self, entity, kind, where, loops, strokes):
        if kind not in _CUT_TYPES:
            self.fail(
                "cut",
                where,
                f"is not a cut line: CUT takes {', '.join(_CUT_TYPES)} (the cutter would cut it "
                "and popup verify cannot check it)",
            )
        if kind in ("LWPOLYLINE", "POLYLINE"):
            points, closed = self._polyline("cut", entity, kind, where)
        elif kind == "LINE":
            points, closed = self._points("cut", where, (entity.dxf.start, entity.dxf.end)), False
        else:
            points, closed = self._flattened("cut", entity, kind, where), kind == "CIRCLE"
        points = _without_repeats(points)
        if len(points) > 2 and _close(points[0], points[-1]):
            points.pop()  # returns to its first vertex: closed, whatever the flag says
            closed = True
        if closed:
            if len(points) < 3:
                self.fail("cut", where, "is a closed loop of fewer than three distinct points")
            loops.append(points)
        elif len(points) < 2:
            self.fail("cut", where, "has no length")
        else:
            strokes.append(_Open(points, where))

    def _join(self, strokes):
        """Closed loops from open CUT strokes joined end to end."""
        if not strokes:
            return []
        cell = CHAIN_TOLERANCE
        grid = {}
        for index, stroke in enumerate(strokes):
            for end in (0, 1):
                point = stroke.points[-1 if end else 0]
                key = (math.floor(point[0] / cell), math.floor(point[1] / cell))
                grid.setdefault(key, []).append((index, end))

        def partners(index, end):
            point = strokes[index].points[-1 if end else 0]
            kx, ky = math.floor(point[0] / cell), math.floor(point[1] / cell)
            found = []
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    for other in grid.get((kx + dx, ky + dy), ()):
                        if other == (index, end):
                            continue
                        o = strokes[other[0]].points[-1 if other[1] else 0]
                        if math.dist(point, o) <= CHAIN_TOLERANCE:
                            found.append(other)
            if not found:
                x, y = point
                self.fail(
                    "cut",
                    strokes[index].where,
                    f"is open: its end ({x:.6g}, {y:.6g}) meets no other CUT line (every cut "
                    "must be a closed loop)",
                )
            if len(found) > 1:
                x, y = point
                others = ", ".join(strokes[i].where for i, _ in found)
                self.fail(
                    "cut",
                    strokes[index].where,
                    f"branches: its end ({x:.6g}, {y:.6g}) meets {len(found)} other CUT ends "
                    f"({others})",
                )
            return found[0]

        used = [False] * len(strokes)
        loops = []
        for first in range(len(strokes)):
            if used[first]:
                continue
            loop = []
            index, reverse = first, False
            while not used[index]:
                used[index] = True
                points = strokes[index].points[::-1] if reverse else strokes[index].points
                loop.extend(points[:-1])
                # Leave through the far end; enter the partner through the matching end.
                index, end = partners(index, 0 if reverse else 1)
                reverse = end == 1
            if index != first or reverse:
                # Came back into a stroke already used, but not the one the loop started with.
                self.fail(
                    "cut", strokes[index].where, "branches: more than two CUT ends meet at one end"
                )
            loop = _without_repeats(loop)
            if len(loop) < 3:
                self.fail("cut", strokes[first].where, "closes a loop of under three points")
            loops.append(loop)
        return loops

    # --- MOUNTAIN, VALLEY --------------------------------------------------------------------

    def _read_fold(self, entity, kind, where, role):
        if kind in ("TEXT", "MTEXT") + _IGNORED_TYPES:
            return []
        if kind == "LINE":
            points = self._points(role, where, (entity.dxf.start, entity.dxf.end))
        elif kind in ("LWPOLYLINE", "POLYLINE"):
            if kind == "LWPOLYLINE":
                bulged = any(b for *_, b in entity.get_points("xyb"))
            else:
                bulged = any(v.dxf.get("bulge", 0.0) for v in entity.vertices)
            points, closed = self._polyline(role, entity, kind, where)
            if bulged:
                self.fail(role, where, "has arcs: a fold line must be straight")
            if closed:
                self.fail(role, where, "is closed: a fold is a straight line")
        else:
            self.fail(role, where, "is not a straight line: folds are LINEs (or polylines)")
        points = _without_repeats(points)
        if len(points) < 2:
            self.fail(role, where, "has no length")
        return [DrawnFoldLine(a, b, role) for a, b in _straight_runs(points)]

    # --- GLUE --------------------------------------------------------------------------------

    def _read_glue(self, entity, kind, where):
        if kind in ("TEXT", "MTEXT") + _IGNORED_TYPES:
            return None
        if kind not in ("LWPOLYLINE", "POLYLINE"):
            self.fail(
                "glue",
                where,
                "is not a polyline: glue areas are closed polylines (their first edge marks "
                "where the tab's crease lands)",
            )
        points, closed = self._polyline("glue", entity, kind, where)
        points = _without_repeats(points)
        if not closed:
            if len(points) > 2 and _close(points[0], points[-1]):
                points.pop()
            else:
                self.fail("glue", where, "is open: a glue area is a closed polyline")
        if len(points) < 3:
            self.fail("glue", where, "has fewer than three distinct points")
        return points

    # --- LABEL -------------------------------------------------------------------------------

    def _read_label(self, entity, kind, where):
        text = entity.plain_text()
        if kind == "MTEXT":
            text = " ".join(line.strip() for line in text.splitlines() if line.strip())
        text = text.strip()
        if not text:
            return None
        if kind == "TEXT":
            centre = self._text_centre(entity, text)
        else:
            centre = self._mtext_centre(entity)
        return DrawnLabel(text, self._xy("label", where, centre))

    def _text_centre(self, entity, text):
        """The centre of a TEXT's cap height, in WCS."""
        dxf = entity.dxf
        halign, valign = dxf.get("halign", 0), dxf.get("valign", 0)
        height = dxf.get("height", 1.0)
        insert = Vec3(dxf.insert)
        align = Vec3(dxf.align_point) if dxf.hasattr("align_point") else insert
        turn = math.radians(dxf.get("rotation", 0.0))
        ux, uy = math.cos(turn), math.sin(turn)
        ocs = entity.ocs()
        if (halign, valign) == (1, 2) or halign == 4:
            # MIDDLE_CENTER (the writer's placement) and MIDDLE: the align point is the centre
            return ocs.to_wcs(align)
        if halign in (3, 5) and dxf.hasattr("align_point"):  # ALIGNED, FIT: between two points
            if halign == 3:  # ALIGNED scales the height with the width
                width = self._font(entity, height).text_width(text)
                if width > 0:
                    height *= insert.distance(align) / width
            middle = (insert + align) * 0.5
            return ocs.to_wcs(middle + Vec3(-uy, ux, 0) * (height / 2.0))
        reference = insert if (halign, valign) == (0, 0) else align
        font = self._font(entity, height)
        width = font.text_width(text)
        along = {0: width / 2.0, 1: 0.0, 2: -width / 2.0}.get(halign, width / 2.0)
        # From the reference line to the middle of the cap height: baseline, bottom (of the
        # descenders), middle, top.
        descender = font.measurements.descender_height
        across = {0: height / 2.0, 1: descender + height / 2.0, 3: -height / 2.0}.get(valign, 0.0)
        offset = Vec3(ux * along - uy * across, uy * along + ux * across, 0)
        return ocs.to_wcs(reference + offset)

    def _font(self, entity, height):
        """ezdxf's measuring font for a TEXT (matplotlib's metrics of its style's font)."""
        try:  # ezdxf 1.1 moved the fonts (Debian 13 has 1.4); Debian 12's 0.18 has them in tools
            from ezdxf.fonts import fonts
        except ImportError:
            from ezdxf.tools import fonts

        font_name = "DejaVuSans.ttf"
        style_name = entity.dxf.get("style", "Standard")
        if self.doc.styles.has_entry(style_name):
            font_name = self.doc.styles.get(style_name).dxf.get("font", font_name) or font_name
            if font_name.lower().endswith(".shx"):
                font_name = fonts.map_shx_to_ttf(font_name)
        with _quiet_matplotlib():
            return fonts.make_font(font_name, height, entity.dxf.get("width", 1.0))

    def _mtext_centre(self, entity):
        from ezdxf.tools.text import MAP_MTEXT_ALIGN_TO_FLAGS, estimate_mtext_extents

        with _quiet_matplotlib():
            width, height = estimate_mtext_extents(entity)
        halign, valign = MAP_MTEXT_ALIGN_TO_FLAGS.get(entity.dxf.get("attachment_point", 1), (0, 3))
        along = {0: width / 2.0, 1: 0.0, 2: -width / 2.0}.get(int(halign), 0.0)
        across = {3: -height / 2.0, 2: 0.0, 1: height / 2.0}.get(int(valign), 0.0)
        turn = math.radians(entity.get_rotation())
        ux, uy = math.cos(turn), math.sin(turn)
        insert = Vec3(entity.dxf.insert)
        return insert + Vec3(ux * along - uy * across, uy * along + ux * across, 0)


@contextlib.contextmanager
def _quiet_matplotlib():
    """ezdxf measures text with matplotlib, which logs a warning for every font it lacks."""
    logger = logging.getLogger("matplotlib.font_manager")
    level = logger.level
    logger.setLevel(logging.ERROR)
    try:
        yield
    finally:
        logger.setLevel(level)


def _close(a, b):
    return math.dist(a, b) <= CHAIN_TOLERANCE


def _without_repeats(points):
    """`points` less each vertex that repeats its predecessor (a zero-length segment)."""
    kept = []
    for point in points:
        if not kept or not _close(kept[-1], point):
            kept.append(point)
    return kept


def _straight_runs(points):
    """The (start, end) of each maximal straight run of a polyline."""
    runs = []
    start = 0
    for i in range(1, len(points) - 1):
        a, b = points[start], points[i + 1]
        length = math.dist(a, b)
        # Does vertex i lie on the chord from the run's start to the next vertex, between them?
        p = points[i]
        cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
        dot = (p[0] - a[0]) * (b[0] - a[0]) + (p[1] - a[1]) * (b[1] - a[1])
        if length == 0 or abs(cross) / length > COLLINEAR_TOLERANCE or not 0 < dot < length**2:
            runs.append((points[start], p))
            start = i
    runs.append((points[start], points[-1]))
    return runs
