"""Cutting sheets of the 53-piece card end to end in Python, as `popup sheet` runs them (issue 4's
goal: unfold + tabs + nest + DXF/SVG for 50 pieces in at most 1 s). Run by `make bench`:

    /usr/bin/python3 bench/sheets_bench.py

Prints the median of 5 runs for the core layout, the DXF and the SVG, and the sheet counts of
true-shape nesting against the bounding-box shelf packer run on the same pieces (goal ≤ 0.8 ×).
"""

import os
import statistics
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
BUILD = os.environ.get("POPUP_BUILD_DIR", os.path.join(REPO, "build"))
sys.path[:0] = [os.path.join(BUILD, "python"), os.path.join(REPO, "Workbench")]

from popupwb.core import popupcore  # noqa: E402
from popupwb.sheets.dxf_writer import write_dxf  # noqa: E402
from popupwb.sheets.export import layout  # noqa: E402
from popupwb.sheets.sheet_set import points  # noqa: E402
from popupwb.sheets.svg_writer import write_svg  # noqa: E402

DESIGN = os.path.join(REPO, "tests", "data", "many_pieces.json")
RUNS = 5


def median_ms(action):
    times = []
    for _ in range(RUNS):
        start = time.perf_counter()
        result = action()
        times.append(1000 * (time.perf_counter() - start))
    return statistics.median(times), result


def loop_area(loop):
    return 0.5 * abs(
        sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(loop, loop[1:] + loop[:1]))
    )


def sheets_line(sheet_set):
    """Sheets against the shelf packer and against the area bound no packer can beat."""
    options = sheet_set.options
    margin = options.margin
    printable = (options.paper_width - 2 * margin) * (options.paper_height - 2 * margin)
    area = sum(loop_area(points(r.outer)) for p in sheet_set.pieces for r in p.cut)
    sheets, shelf = sheet_set.sheet_count, sheet_set.shelf_sheet_count
    return (
        f"{options.paper}: {sheets} true-shape vs {shelf} shelf packer = {sheets / shelf:.2f}x "
        f"(goal <= 0.8x: {'met' if sheets <= 0.8 * shelf else 'MISSED'}); the pieces' area "
        f"fills {area / printable:.2f} sheets"
    )


def main():
    scaffold = popupcore.load_scaffold(DESIGN)
    with tempfile.TemporaryDirectory() as out:
        layout_ms, sheet_set = median_ms(lambda: layout(scaffold, paper="A3"))
        dxf_ms, _ = median_ms(lambda: write_dxf(sheet_set, os.path.join(out, "sheets.dxf")))
        svg_ms, _ = median_ms(lambda: write_svg(sheet_set, os.path.join(out, "sheets.svg")))
    total = layout_ms + dxf_ms + svg_ms
    print(f"{len(sheet_set.pieces)} pieces, {len(scaffold.patches)} patches (A3)")
    print(f"layout (unfold, tabs, labels, nest, round trip): {layout_ms:7.1f} ms")
    print(f"DXF: {dxf_ms:7.1f} ms   SVG: {svg_ms:7.1f} ms")
    print(f"total {total:.0f} ms (goal <= 1000 ms): {'met' if total <= 1000 else 'MISSED'}")
    print(sheets_line(sheet_set))
    print(sheets_line(layout(scaffold, paper="300x300")))


if __name__ == "__main__":
    main()
