"""paths.png of `popup animate`: each chain's target path (its end effector projected on the card,
thesis §6.2) against the path the design's mechanism point follows, on the open card seen from the
viewer's side (+z: the card's x to the right, y up, so the character stands upright).

Drawn with matplotlib's Agg canvas (no display, as preview.png of `popup fit`); deterministic: the
colours come from a fixed cycle in chain order, no random jitter, no timestamps in the file.
"""

import numpy as np

IMAGE_SIZE_PX = (1200, 900)
DPI = 100
# For a task panel in FreeCAD's side pane (300-400 px): narrow, the legend under the card, drawn
# at a lower DPI so its text stays legible at the width it is shown.
NARROW_SIZE_PX = (400, 600)
NARROW_DPI = 60
CARD_EDGE = (0.45, 0.45, 0.45)
COLOURS = (
    "#1f77b4",
    "#d62728",
    "#2ca02c",
    "#9467bd",
    "#ff7f0e",
    "#17becf",
    "#8c564b",
    "#e377c2",
    "#7f7f7f",
    "#bcbd22",
)
STATUS_MARK = {"animated": "", "merged": " [merged]", "stationary": " [stationary]"}


def chain_paths(chains):
    """[(label, status, target Nx2, achieved Nx2)] of ChainReports (or dicts of report.json)."""
    rows = []
    for chain in chains:
        get = chain.get if isinstance(chain, dict) else lambda k, c=chain: getattr(c, k, None)
        mapping = get("mechanism") if isinstance(chain, dict) else get("mapping")
        error, floor = get("error"), get("floor")
        label = f"{get('name')}: {mapping}, E = {error:.3f}" if error is not None else get("name")
        if error is not None and floor:
            label += f" (floor {floor:.3f})"  # the reach floor: no design follows it closer
        status = get("status")
        rows.append(
            (
                label + STATUS_MARK.get(status, f" [{status}]"),
                status,
                np.asarray(get("target"), dtype=float).reshape(-1, 2),
                np.asarray(get("achieved"), dtype=float).reshape(-1, 2),
            )
        )
    return rows


def write_paths_plot(path, chains, card_width, card_depth, title="", narrow=False):
    """Writes the PNG to `path`: the card (x from -depth to +depth, y from 0 to width, mm) and,
    per chain, its target path (solid, a dot at the open state) and the mechanism's path
    (dashed, a cross at the open state). `narrow`: for a task panel (NARROW_SIZE_PX, the legend
    under the card)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    (width_px, height_px), dpi = (NARROW_SIZE_PX, NARROW_DPI) if narrow else (IMAGE_SIZE_PX, DPI)
    figure = Figure(figsize=(width_px / dpi, height_px / dpi), dpi=dpi)
    FigureCanvasAgg(figure)
    axes = figure.add_subplot(1, 1, 1)
    depth, width = float(card_depth), float(card_width)
    axes.plot(
        [-depth, depth, depth, -depth, -depth], [0, 0, width, width, 0], color=CARD_EDGE, lw=1.2
    )
    axes.plot([0, 0], [0, width], color=CARD_EDGE, lw=0.8, ls=":")  # the central fold
    for i, (label, status, target, achieved) in enumerate(chain_paths(chains)):
        colour = COLOURS[i % len(COLOURS)]
        if len(target):
            axes.plot(target[:, 0], target[:, 1], "-", color=colour, lw=2.0, label=label)
            axes.plot(target[-1, 0], target[-1, 1], "o", color=colour, ms=6)
            axes.plot(target[0, 0], target[0, 1], "o", color=colour, ms=4, mfc="white")
        if len(achieved):
            style = ":" if status == "stationary" else "--"
            axes.plot(achieved[:, 0], achieved[:, 1], style, color=colour, lw=1.5)
            axes.plot(achieved[-1, 0], achieved[-1, 1], "x", color=colour, ms=8, mew=2)
    axes.set_aspect("equal")
    axes.set_xlabel("card x (mm), ground page to the right")
    axes.set_ylabel("card y (mm), along the fold")
    key = (
        "solid: target path of each end effector; dashed: its mechanism's point "
        "(open circle: closed card, dot and cross: open card)"
    )
    axes.set_title(title if narrow else title + ("\n" if title else "") + key, fontsize=10)
    if chains and narrow:
        axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), fontsize=9, frameon=False)
    elif chains:
        axes.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    axes.grid(True, lw=0.3, alpha=0.5)
    figure.tight_layout()
    figure.savefig(path, format="png", metadata={"Software": None})
    return path
