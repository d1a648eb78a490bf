"""Lay a design out for cutting and write every production file into one folder.

    sheet_set = layout(scaffold, paper="A3", kerf=0.1)
    paths = export_sheets(sheet_set, "out/sheets")

`layout` is the core's layout_sheets: the bound popupcore.SheetSet (docs/SHEET_FORMAT.md), which
every writer takes. `export_sheets` writes sheets.dxf (all sheets side by side), sheets.svg
(sheets-2.svg, … for further sheets), sheets.pdf (one page per sheet), instructions.pdf,
report.json and sheets.json (the sheet set itself, popupcore.sheet_set_from_json reads it back),
re-reads the DXF to check it, and returns the paths by kind. The sheet set becomes JSON only here,
for the two JSON files. No FreeCAD needed.
"""

import json
import os
import re
from concurrent.futures import ThreadPoolExecutor

from .dxf_checks import check_dxf
from .dxf_writer import write_dxf
from .instructions_pdf import write_instructions
from .pdf_writer import write_pdf
from .print_artwork import place_artwork
from .sheet_options import core_options
from .svg_writer import write_svg


def layout(scaffold, cancel=None, **options):
    """The sheet set of a scaffold, a popupcore.SheetSet. Options are those of
    sheets/sheet_options.py (and `paper`), defaults the core's; raises ValueError for an unknown
    option and popupcore.DesignError (a ValueError) naming a bad value and its range, or a piece
    that does not fit the paper. `cancel`: a popupcore.CancelFlag (progress.CANCEL_FLAG) that
    stops it."""
    from popupwb.core import popupcore

    return popupcore.layout_sheets(scaffold, core_options(**options), cancel=cancel)


def sheet_set_document(sheet_set):
    """The sheet set as the JSON object of docs/SHEET_FORMAT.md, for the files that hold it
    (sheets.json, and the paper, options, round trip and findings of report.json)."""
    return json.loads(sheet_set.to_json())


def report(sheet_set, dxf_check=None, not_valid=None, document=None):
    """What report.json holds: the counts, the checks and every diagnostic; `not_valid` the
    stamp's text when the sheets were forced from a design the validity check rejects.
    `document`: sheet_set_document(sheet_set) when the caller has it."""
    if document is None:
        document = sheet_set_document(sheet_set)
    pieces = sheet_set.pieces
    piece_rows = [
        {
            "id": p.id,
            "sheet": p.sheet,
            "patches": [patch.id for patch in p.patches],
            "tabs": [t.code for t in p.tabs],
            "glue": [g.code for g in p.glue],
        }
        for p in pieces
    ]
    sheets, shelf = sheet_set.sheet_count, sheet_set.shelf_sheet_count
    findings = document["diagnostics"]  # the file's spelling of each diagnostic
    return {
        "paper": document["paper"],
        "options": document["options"],
        "pieces": piece_rows,
        "sheets": sheets,
        "shelf_packer_sheets": shelf,
        "sheets_vs_shelf_packer": sheets / shelf if shelf else None,
        "tabs": sum(len(p.tabs) for p in pieces),
        "cut_length": sheet_set.cut_length,
        "stack_height": sheet_set.stack_height,
        "round_trip": document["round_trip"],
        "assembly": [step.text for step in sheet_set.assembly],
        "errors": [d for d in findings if d["severity"] == "error"],
        "warnings": [d for d in findings if d["severity"] == "warning"],
        "dxf_check": dxf_check,
        "not_valid": None if not_valid is None else not_valid.text(),
    }


def remove_stale_sheet_files(out_dir):
    """Removes the numbered sheet files (sheets-2.svg, ...) an earlier export left in out_dir: a
    layout with fewer sheets would otherwise leave a cutter file of another design beside it."""
    pattern = re.compile(r"^sheets-[0-9]+\.(svg|dxf)$")
    for name in os.listdir(out_dir):
        if pattern.match(name):
            os.remove(os.path.join(out_dir, name))


def export_sheets(
    sheet_set, out_dir, style=None, registration_marks=False, not_valid=None, artwork=None
):
    """Writes the production files of `sheet_set` (a popupcore.SheetSet) into out_dir (created
    if needed); returns {kind: path(s)}.
    `not_valid` (a not_valid_stamp.NotValid) stamps every sheet and page: the design failed the
    validity check and the sheets were forced. `artwork` ({patch id: popupcore.PatchArtwork},
    print_artwork.py) goes on the print layer of the PDF and SVG, with registration marks; the
    DXF stays a cut file."""
    os.makedirs(out_dir, exist_ok=True)
    remove_stale_sheet_files(out_dir)
    dxf = write_dxf(sheet_set, os.path.join(out_dir, "sheets.dxf"), style, not_valid)
    place_artwork(sheet_set, artwork)  # each image read out of the core once, before the threads
    # The PDF and the SVG compress their images outside the GIL: the PDF is written in a thread
    # beside the SVG (each file as written alone).
    with ThreadPoolExecutor(max_workers=1) as pool:
        pdf = pool.submit(
            write_pdf,
            sheet_set,
            os.path.join(out_dir, "sheets.pdf"),
            style,
            registration_marks,
            not_valid=not_valid,
            artwork=artwork,
        )
        svg = write_svg(
            sheet_set, os.path.join(out_dir, "sheets.svg"), style, not_valid, artwork=artwork
        )
        paths = {"dxf": dxf, "svg": svg, "pdf": pdf.result()}
    paths["instructions"] = write_instructions(
        sheet_set, os.path.join(out_dir, "instructions.pdf"), style, not_valid=not_valid
    )
    document = sheet_set_document(sheet_set)
    paths["sheet_set"] = os.path.join(out_dir, "sheets.json")
    with open(paths["sheet_set"], "w") as f:
        json.dump(document, f)
    check = check_dxf(
        paths["dxf"],
        expected_cut_length=sheet_set.cut_length,
        cut_layer=style.cut.name if style else None,
    )
    paths["report"] = os.path.join(out_dir, "report.json")
    with open(paths["report"], "w") as f:
        json.dump(report(sheet_set, check, not_valid, document), f, indent=2)
    return paths
