"""Cutting sheets: the sheet set the core lays out (docs/SHEET_FORMAT.md) and the files made from
it (DXF, SVG, PDF, instructions PDF, PNG preview, report.json). No FreeCAD needed here, except in
techdraw_pages."""
