"""Checks on a written DXF cutting file, read back with ezdxf (tests and the CLI report use them),
and a round trip through LibreCAD's command-line converter as an independent DXF client."""

import math
import os
import shutil
import subprocess

import ezdxf

from .layer_style import SheetStyle

OVERLAP_TOLERANCE = 1e-6  # mm: collinear CUT segments sharing more than this are cut twice
# Candidate pairs for the collinearity test: directions closer than this (rad). Generous, the
# exact test is on distances.
_ANGLE_WINDOW = 1e-3
LIBRECAD_TIMEOUT = 60  # s


def check_dxf(path, expected_cut_length=None, cut_layer=None):
    """Reads the DXF at `path` and measures what a cutter cares about. Returns a dict:

    audit_errors      errors ezdxf's auditor finds
    insunits          header $INSUNITS (4 = mm)
    layers_used       sorted names of the layers modelspace entities are on
    entity_counts     {layer: {dxftype: count}}
    cut_loops         closed polylines on the cut layer
    max_closure_gap   largest distance from an open CUT end to the nearest other CUT end (mm);
                      0 when every CUT polyline is closed
    overlapping_cut_segments  pairs of CUT segments on one line sharing more than 1e-6 mm (each
                      such stretch would be cut twice). Sheets in one file lie apart, so checking
                      all segments together is the same as checking each sheet.
    cut_length        total length of the CUT entities (mm)
    cut_length_error  |cut_length - expected| / expected, only if expected_cut_length is given
    """
    cut_layer = cut_layer or SheetStyle().cut.name
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    modelspace = doc.modelspace()
    counts = {}
    for entity in modelspace:
        per_layer = counts.setdefault(entity.dxf.layer, {})
        per_layer[entity.dxftype()] = per_layer.get(entity.dxftype(), 0) + 1
    chains = _cut_chains(modelspace, cut_layer)
    segments = [
        (chain[i], chain[(i + 1) % len(chain)])
        for chain, closed in chains
        for i in range(len(chain) if closed else len(chain) - 1)
    ]
    cut_length = sum(math.dist(start, end) for start, end in segments)
    result = {
        "audit_errors": len(auditor.errors),
        "insunits": doc.header.get("$INSUNITS", 0),
        "layers_used": sorted(counts),
        "entity_counts": counts,
        "cut_loops": sum(1 for _, closed in chains if closed),
        "max_closure_gap": _max_closure_gap([chain for chain, closed in chains if not closed]),
        "overlapping_cut_segments": _count_overlaps(segments),
        "cut_length": cut_length,
    }
    if expected_cut_length is not None:
        result["cut_length_error"] = abs(cut_length - expected_cut_length) / expected_cut_length
    return result


def _cut_chains(modelspace, cut_layer):
    """The CUT entities as (points, closed) polylines; straight segments only."""
    chains = []
    for entity in modelspace.query(f'*[layer=="{cut_layer}"]'):
        kind = entity.dxftype()
        if kind == "LINE":
            chains.append(([_xy(entity.dxf.start), _xy(entity.dxf.end)], False))
        elif kind == "LWPOLYLINE":
            if any(bulge for *_, bulge in entity.get_points("xyb")):
                raise ValueError(f"{kind} {entity.dxf.handle} on {cut_layer}: arcs are not checked")
            chains.append(([(x, y) for x, y in entity.get_points("xy")], bool(entity.closed)))
        else:
            raise ValueError(f"{kind} {entity.dxf.handle} on {cut_layer}: only LINE and LWPOLYLINE")
    return chains


def _xy(vector):
    return (vector[0], vector[1])


def _max_closure_gap(open_chains):
    """For each end of an open chain, the distance to the nearest other end (its own other end
    included: a polyline that returns to its start without the closed flag has gap 0)."""
    ends = [end for chain in open_chains for end in (chain[0], chain[-1])]
    return max(
        (
            min(math.dist(end, other) for j, other in enumerate(ends) if j != i)
            for i, end in enumerate(ends)
        ),
        default=0.0,
    )


def _count_overlaps(segments):
    """Pairs of segments within OVERLAP_TOLERANCE of one line whose extents along it overlap by
    more than OVERLAP_TOLERANCE. Sorted by direction so only near-parallel pairs are compared."""
    directed = []
    for start, end in segments:
        length = math.dist(start, end)
        if length > OVERLAP_TOLERANCE:
            angle = math.atan2(end[1] - start[1], end[0] - start[0]) % math.pi
            directed.append((angle, start, end, length))
    directed.sort(key=lambda item: item[0])
    count = 0
    for i, first in enumerate(directed):
        for second in directed[i + 1 :]:
            if second[0] - first[0] > _ANGLE_WINDOW:
                break
            count += _overlap(first, second)
        # Directions near 0 and near pi are the same line direction.
        if first[0] < _ANGLE_WINDOW:
            for second in reversed(directed[i + 1 :]):
                if second[0] < math.pi - _ANGLE_WINDOW:
                    break
                count += _overlap(first, second)
    return count


def _overlap(first, second):
    _, start, end, length = first
    ux, uy = (end[0] - start[0]) / length, (end[1] - start[1]) / length
    offsets = [(p[0] - start[0]) * -uy + (p[1] - start[1]) * ux for p in second[1:3]]
    if any(abs(offset) > OVERLAP_TOLERANCE for offset in offsets):
        return 0
    a, b = sorted((p[0] - start[0]) * ux + (p[1] - start[1]) * uy for p in second[1:3])
    return 1 if min(length, b) - max(0.0, a) > OVERLAP_TOLERANCE else 0


def librecad_available():
    return shutil.which("librecad") is not None


def convert_with_librecad(dxf_path, out_dir):
    """Prints `dxf_path` to <out_dir>/<stem>.pdf with `librecad dxf2pdf`, fitted to its default
    page, and returns that path; RuntimeError with LibreCAD's output if it fails.

    LibreCAD 2.2 needs no display with Qt's offscreen platform. Its `-o` takes no file name in
    2.2.0, so the output goes through `-t <directory>`."""
    pdf_path = os.path.join(out_dir, os.path.splitext(os.path.basename(dxf_path))[0] + ".pdf")
    if os.path.exists(pdf_path):
        os.remove(pdf_path)
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    process = subprocess.run(
        ["librecad", "dxf2pdf", "-a", "-t", out_dir, dxf_path],
        env=env,
        capture_output=True,
        text=True,
        timeout=LIBRECAD_TIMEOUT,
    )
    if process.returncode != 0 or not os.path.isfile(pdf_path) or not os.path.getsize(pdf_path):
        raise RuntimeError(
            f"librecad dxf2pdf {dxf_path} failed (exit {process.returncode}, "
            f"expected {pdf_path}):\n{process.stderr.strip()}\n{process.stdout.strip()}"
        )
    return pdf_path
