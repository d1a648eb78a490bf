#!/usr/bin/python3
"""docs/SHAPE_RESULTS.md: `popup fit` on every model tools/make_models.py makes, next to Table 8.1.

    /usr/bin/python3 tools/shape_results.py --build build [--out out/shape_results]

Each model is made afresh, fitted with seed 1 (the default alignment, and the up and facing the
model was built with), and its report.json read back; the table is written from those files only.
"""

import argparse
import json
import os
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PYTHON = "/usr/bin/python3"
BLOCKY = ("cuboid", "house", "truck", "tent", "l_building", "truck_with_wheels")
ORGANIC = ("blob", "figure", "defective")
# The models stand on z with their front towards -y (tools/make_models.py).
ALIGNMENTS = {"given axes": ["--up", "0,0,1", "--facing", "0,-1,0"], "NPCA": []}

HEADER = """# Shape from a model: results

Written by `tools/shape_results.py` from the report.json of `popup fit` (seed 1, A4) on the models
`tools/make_models.py` makes; none comes from elsewhere. Distances are those of
`popupcore.fit_metrics` (docs/MATH.md, "Fit metrics"): point-to-surface distances between the
model placed by `model_to_card` and the pop-up at its design state (the card open flat at 180°),
**divided by the model's bounding-box diagonal**. Model to pop-up is the one-sided figure of the
thesis's Table 8.1; the thesis does not say how it normalised, so its ranges are shown for scale,
not as a like-for-like comparison. Volume difference is vol(model △ fitted prisms) / vol(model)
(empty for a model that is not closed). Exit is `popup fit`'s: 0 valid design and error-free
sheets, 1 otherwise.

Thesis Table 8.1 on its six models: mean 0.013–0.035, RMS 0.021–0.047, max 0.068–0.153, volume
difference 0.05–0.55. The issue's goal: every blocky model under the thesis's best mean, 0.0128,
with at most 8 mechanisms.

"""


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(REPO, "build"))
    parser.add_argument("--out", default=os.path.join(REPO, "out", "shape_results"))
    parser.add_argument("--doc", default=os.path.join(REPO, "docs", "SHAPE_RESULTS.md"))
    args = parser.parse_args(argv)
    models_dir = os.path.join(args.out, "models")
    made = run([PYTHON, os.path.join(REPO, "tools", "make_models.py"), "--out", models_dir])
    if made.returncode:
        sys.exit(f"make_models.py failed: {made.stderr.strip()}")
    popup = os.path.join(args.build, "bin", "popup")
    rows = []
    for name in BLOCKY + ORGANIC:
        model = next(
            os.path.join(models_dir, f)
            for f in sorted(os.listdir(models_dir))
            if os.path.splitext(f)[0] == name
        )
        for alignment, flags in ALIGNMENTS.items():
            out = os.path.join(args.out, name, alignment.replace(" ", "_"))
            proc = run([popup, "fit", model, "--out", out, "--seed", "1"] + flags, timeout=600)
            report_path = os.path.join(out, "report.json")
            if not os.path.isfile(report_path):
                rows.append((name, alignment, proc.returncode, None))
                continue
            with open(report_path, encoding="utf-8") as f:
                rows.append((name, alignment, proc.returncode, json.load(f)))
            print(f"{name} ({alignment}): exit {proc.returncode}", file=sys.stderr)
    lines = [HEADER]
    lines.append(
        "| model | alignment | exit | valid | mechanisms | mean | RMS | max | pop-up to model "
        "max | volume diff. | coverage | fit_design s |"
    )
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, alignment, code, report in rows:
        if report is None or not report.get("metrics"):
            lines.append(f"| {name} | {alignment} | {code} | no | – | – | – | – | – | – | – | – |")
            continue
        m = report["metrics"]
        to_popup = m["hausdorff"]["model_to_popup"]
        back = m["hausdorff"]["popup_to_model"]
        kinds = ", ".join(x["name"] for x in report["mechanisms"])
        volume = m.get("volume_difference")
        fit_s = sum(
            v
            for k, v in report["timings_s"].items()
            if k in ("align", "sample", "fit_primitives", "map", "validate", "outlines")
        )
        lines.append(
            f"| {name} | {alignment} | {code} | {'yes' if report['valid'] else 'no'} | {kinds} | "
            f"{to_popup['mean']:.4f} | {to_popup['rms']:.4f} | {to_popup['max']:.4f} | "
            f"{back['max']:.4f} | {'–' if volume is None else f'{volume:.3f}'} | "
            f"{m['coverage']:.2f} | {fit_s:.2f} |"
        )
    # The sections after the table (what it says, written by hand; the corpus section of
    # tools/corpus_results.py --doc) stay as they are.
    kept = ""
    if os.path.isfile(args.doc):
        with open(args.doc, encoding="utf-8") as f:
            old = f.read()
        if "\n## " in old:
            kept = old[old.index("\n## ") :]
    with open(args.doc, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n" + kept)
    print(f"wrote {args.doc}", file=sys.stderr)


if __name__ == "__main__":
    main()
