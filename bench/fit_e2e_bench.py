"""`popup fit MODEL --out DIR` end to end on realistic models (issue 25 item 7: at most 3 s on a
30k-vertex model, the core fit at most 0.5 s). Run by `make bench`:

    /usr/bin/python3 bench/fit_e2e_bench.py [CORPUS_NAME ...]

Writes corpus models (tools/make_corpus.py: bust_scan_dense is the 30k-vertex scan) and the
synthetic 30k truck (tools/make_models.py's truck, each triangle cut into a grid of smaller ones
as the C++ fit_bench's tessellated() does) into a temporary folder, runs the `popup` launcher of
the build on each and prints the wall-clock seconds and report.json's timings_s per stage. Then,
in this process and on the same fitted model, the old matplotlib preview
(bench/matplotlib_preview.py) against the new one (popupcore.render_view) and their ratio.
"""

import json
import os
import struct
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
BUILD = os.environ.get("POPUP_BUILD_DIR", os.path.join(REPO, "build"))
sys.path[:0] = [os.path.join(BUILD, "python"), os.path.join(REPO, "Workbench"), HERE]
sys.path.append(os.path.join(REPO, "tools"))

DEFAULT_MODELS = ("bust_scan_dense", "bust_scan", "house_gable", "vehicle", "statue_pedestal")
SYNTHETIC = "synthetic_truck_30k"
STAGES = (
    "load",
    "clean",
    "fit",
    "outlines",
    "document",
    "metrics",
    "preview",
    "sheets",
    "total",
)
# The core's fit stages, summed into "fit" (the goal's "core fit"); outlines shown apart.
FIT_STAGES = ("align", "sample", "fit_primitives", "map", "validate", "depth_layers", "report")


def tessellated(vertices, triangles, count):
    """Each triangle cut into n x n smaller ones (unshared corners), n the smallest giving about
    `count` vertices: the C++ benches' tessellated()."""
    per_triangle = count / max(1, len(triangles))
    n = 1
    while (n + 2) * (n + 3) / 2.0 <= per_triangle:
        n += 1
    out = []
    for a, b, c in vertices[triangles]:
        grid = {}
        for i in range(n + 1):
            for j in range(n + 1 - i):
                grid[i, j] = a + (b - a) * (j / n) + (c - a) * (i / n)
        for i in range(n):
            for j in range(n - i):
                out.append((grid[i, j], grid[i, j + 1], grid[i + 1, j]))
                if j + 1 < n - i:
                    out.append((grid[i, j + 1], grid[i + 1, j + 1], grid[i + 1, j]))
    return np.array(out)


def write_binary_stl(path, corners):
    """corners: M x 3 x 3 triangle corners."""
    with open(path, "wb") as f:
        f.write(b"synthetic truck".ljust(80, b" "))
        f.write(struct.pack("<I", len(corners)))
        for t in corners:
            f.write(struct.pack("<12fH", 0, 0, 0, *t.ravel(), 0))
    return path


def write_synthetic(folder):
    import popupcore
    from make_models import write_model

    coarse = popupcore.load_model(write_model("truck", os.path.join(folder, "truck.stl")))
    corners = tessellated(np.asarray(coarse.vertices), np.asarray(coarse.triangles), 30000)
    return write_binary_stl(os.path.join(folder, SYNTHETIC + ".stl"), corners)


def write_models(folder, names):
    from make_corpus import CORPUS, write_corpus_model

    paths = {}
    for name in names:
        paths[name] = write_corpus_model(
            name, os.path.join(folder, f"{name}.{CORPUS[name]['file']}")
        )
    paths[SYNTHETIC] = write_synthetic(folder)
    return paths


def run_fit(path, out):
    """Wall-clock seconds of `popup fit`, its report's timings_s and vertex count."""
    start = time.perf_counter()
    run = subprocess.run(
        [os.path.join(BUILD, "bin", "popup"), "fit", path, "--out", out],
        capture_output=True,
        text=True,
    )
    wall = time.perf_counter() - start
    if run.returncode not in (0, 1):
        raise RuntimeError(f"popup fit {path}: exit {run.returncode}\n{run.stderr}")
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    return wall, report["timings_s"], report["model"].get("vertices")


def stage_row(timings):
    row = dict(timings)
    row["fit"] = sum(timings.get(s, 0.0) for s in FIT_STAGES)
    return [row.get(s, 0.0) for s in STAGES]


def compare_previews(path, out):
    """Seconds of the old and the new preview of the same fitted model, in this process."""
    import matplotlib_preview
    import popupcore
    from popupwb.fitting import preview
    from popupwb.model.model_source import transformed

    model, _ = popupcore.clean_model(popupcore.load_model(path))
    result = popupcore.fit_design(model, popupcore.FitOptions())
    vertices = transformed(model.vertices, result.model_to_card)
    loops, card = preview.scaffold_outlines(result.scaffold)
    outlines = [patch[0] for patch in loops]
    seconds = []
    for module, patches, name in (
        (matplotlib_preview, outlines, "old.png"),
        (preview, loops, "new.png"),
    ):
        start = time.perf_counter()
        module.write_preview(os.path.join(out, name), vertices, model.triangles, patches, card)
        seconds.append(time.perf_counter() - start)
    return seconds


def main(argv):
    names = argv or list(DEFAULT_MODELS)
    with tempfile.TemporaryDirectory() as folder:
        paths = write_models(folder, names)
        print("popup fit end to end, seconds (fit = the core's stages but outlines)")
        print(f"{'model':<22} {'vertices':>8} {'wall':>6} " + " ".join(f"{s:>8}" for s in STAGES))
        for name, path in paths.items():
            wall, timings, vertices = run_fit(path, os.path.join(folder, "out_" + name))
            cells = " ".join(f"{v:8.2f}" for v in stage_row(timings))
            print(f"{name:<22} {vertices or 0:>8} {wall:6.2f} {cells}")
        print("\npreview of the same fitted model, same process: matplotlib (old) vs render_view")
        for name in ("bust_scan_dense", SYNTHETIC):
            if name in paths:
                old, new = compare_previews(paths[name], folder)
                print(f"{name:<22} old {old:6.2f} s  new {new:6.2f} s  ratio {old / new:5.1f}x")


if __name__ == "__main__":
    main(sys.argv[1:])
