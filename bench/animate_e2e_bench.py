"""`popup animate FILE --out DIR` end to end on capture-like takes (issue 26: at most 3 s on a
4,500-frame capture on two idle cores). Run by `make bench`:

    /usr/bin/python3 bench/animate_e2e_bench.py [TAKE ...]

Writes tools/make_captures.py's takes (long_take: 4,500 frames of a 61-joint humanoid with root
motion; walk; gallop) into a temporary folder and runs the build's `popup` launcher on each, and
on the committed skinned takes of tools/blender_capture.py (capture_walk.glb, capture_wave.glb),
each from the view its JSON gives. Prints the least wall-clock seconds of RUNS runs and, of that
run, report.json's timings_s per stage. Beside it, in the same process, the core alone
(popupcore.load_animation + design_motion with the same options): what the stages around it
(document, plot, movie, sheets) add.
"""

import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
BUILD = os.environ.get("POPUP_BUILD_DIR", os.path.join(REPO, "build"))
DATA = os.path.join(REPO, "tests", "data", "animations")
sys.path[:0] = [os.path.join(BUILD, "python"), os.path.join(REPO, "Workbench")]
sys.path.append(os.path.join(REPO, "tools"))

RUNS = 3
GENERATED = ("long_take", "walk", "gallop")
COMMITTED = ("capture_walk", "capture_wave")
STAGES = ("load", "targets", "mapping", "annealing", "plot", "movie", "sheets", "total")
A4_CARD_MM = (186.0, 136.5)  # `popup animate`'s card on A4 (cli/animate.py)


def takes(folder, names):
    """{name: (path, its JSON)} of the takes asked for."""
    import make_captures

    out = {}
    for name in names:
        if name in GENERATED:
            _, known = make_captures.build(name)
            out[name] = (make_captures.write(name, folder), known)
        elif name in COMMITTED:
            with open(os.path.join(DATA, name + ".json"), encoding="utf-8") as f:
                out[name] = (os.path.join(DATA, name + ".glb"), json.load(f))
        else:
            raise SystemExit(f"unknown take {name}: choose from {GENERATED + COMMITTED}")
    return out


def axis(values):
    return ",".join(f"{v:g}" for v in values)


def run_animate(path, known, out):
    """Wall-clock seconds of `popup animate` and its report's timings_s."""
    command = [os.path.join(BUILD, "bin", "popup"), "animate", path, "--out", out]
    command += [f"--view={axis(known['view'])}", f"--up={axis(known['up'])}"]
    start = time.perf_counter()
    run = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if run.returncode not in (0, 1):
        raise RuntimeError(f"popup animate {path}: exit {run.returncode}\n{run.stderr}")
    with open(os.path.join(out, "report.json")) as f:
        return wall, json.load(f)["timings_s"]


def core_alone(path, known):
    """Seconds of load_animation + design_motion as `popup animate` calls them (A4 card)."""
    import popupcore

    options = popupcore.MotionOptions()
    options.view.view, options.view.up = tuple(known["view"]), tuple(known["up"])
    options.view.card_width, options.view.card_depth = A4_CARD_MM
    start = time.perf_counter()
    popupcore.design_motion(popupcore.load_animation(path), options)
    return time.perf_counter() - start


def main(argv):
    names = argv or list(GENERATED + COMMITTED)
    with tempfile.TemporaryDirectory() as folder:
        print(f"popup animate end to end, seconds (least wall of {RUNS} runs; its stages)")
        print(f"{'take':<14} {'wall':>6} {'core':>6} " + " ".join(f"{s:>9}" for s in STAGES))
        for name, (path, known) in takes(folder, names).items():
            runs = [
                run_animate(path, known, os.path.join(folder, f"{name}_{k}")) for k in range(RUNS)
            ]
            wall, timings = min(runs, key=lambda r: r[0])
            core = min(core_alone(path, known) for _ in range(RUNS))
            cells = " ".join(f"{timings.get(s, 0.0):9.2f}" for s in STAGES)
            print(f"{name:<14} {wall:6.2f} {core:6.2f} {cells}")


if __name__ == "__main__":
    main(sys.argv[1:])
