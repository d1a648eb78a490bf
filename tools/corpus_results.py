#!/usr/bin/python3
"""`popup fit` on every model of the realistic corpus (tools/make_corpus.py): one row per model.

    /usr/bin/python3 tools/corpus_results.py --build build --corpus build/corpus \
        --out out/corpus_results [--json rows.json] [--before before.json] [--doc FILE]

Each model is fitted with seed 1 and the automatic axes, as a maker who does not know the file's up
axis would; the row is read back from report.json only, with the wall time of the whole command.
`--json` keeps the rows; `--before` names rows kept earlier (another build) to print beside;
`--doc` writes the corpus section of docs/SHAPE_RESULTS.md with each preview beside its row.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "tools"))

from make_corpus import CORPUS  # noqa: E402

ORGANIC = "organic"
PLATE_ONLY = ()  # every corpus model stands up from its plate; tools/make_models.py has plates
BLOCKY = (
    "house_gable",
    "house_hip",
    "shed_cabin",
    "apartment_blocks",
    "terrain_village",
    "open_roof_game",
    "cottage_tga",
    "barn_bmp",
    "vehicle",
    "engine",
    "bookshelf",
    "print_bed_bracket",
    "chair_x_up",
)
# The principal patches of a mechanism (those that carry the model's outline, §5.1.3).
PRINCIPAL_PARTS = ("F", "T", "FG", "FB", "L", "R", "C")


def model_file(corpus, name):
    return os.path.join(corpus, f"{name}.{CORPUS[name]['file']}")


def fit_row(popup, corpus, name, out):
    """`popup fit` on one model; the row from its report.json and the wall time."""
    dest = os.path.join(out, name)
    shutil.rmtree(dest, ignore_errors=True)
    start = time.perf_counter()
    proc = subprocess.run(
        [popup, "fit", model_file(corpus, name), "--out", dest, "--seed", "1"],
        capture_output=True,
        text=True,
        timeout=900,
    )
    seconds = time.perf_counter() - start
    row = {"model": name, "exit": proc.returncode, "seconds": round(seconds, 2)}
    report_path = os.path.join(dest, "report.json")
    if not os.path.isfile(report_path):
        row["error"] = (proc.stderr.strip().splitlines() or ["no report"])[-1]
        return row
    with open(report_path, encoding="utf-8") as f:
        report = json.load(f)
    metrics = report.get("metrics") or {}
    row.update(
        valid=report["valid"],
        mechanisms=[m["name"] for m in report["mechanisms"]],
        bulk_box=any(r["action"] == "replaced" for r in report.get("repairs", [])),
        outlines=len(report.get("profiles", [])),
        sheets_ok=report.get("sheets_ok"),
        fit_s=round(sum(report["timings_s"].get(k, 0.0) for k in FIT_STAGES), 2),
    )
    if metrics:
        row["mean"] = metrics["hausdorff"]["model_to_popup"]["mean"]
        row["coverage"] = metrics["coverage"]
    row["preview"] = os.path.join(dest, "preview.png")
    return row


FIT_STAGES = ("align", "sample", "fit_primitives", "map", "validate", "outlines", "depth_layers")


def cell(row, key, fmt="{}"):
    value = row.get(key) if row else None
    return "–" if value is None else fmt.format(value)


def mechanisms_cell(row):
    if not row or "mechanisms" not in row:
        return "–"
    names = ", ".join(row["mechanisms"]) or "none"
    return names + (" (bulk box)" if row.get("bulk_box") else "")


def table(rows, before):
    """The markdown table: after, with the before figures beside where given."""
    old = {r["model"]: r for r in before}
    head = "| model | kind | exit | mechanisms | mean | coverage | outlines | s |"
    if before:
        head += " before: mechanisms | mean | coverage | outlines | s |"
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for row in rows:
        name = row["model"]
        kind = ORGANIC if ORGANIC in CORPUS[name]["defects"] else "blocky"
        line = (
            f"| {name} | {kind} | {row['exit']} | {mechanisms_cell(row)} | "
            f"{cell(row, 'mean', '{:.4f}')} | {cell(row, 'coverage', '{:.2f}')} | "
            f"{cell(row, 'outlines')} | {cell(row, 'seconds', '{:.1f}')} |"
        )
        if before:
            b = old.get(name)
            line += (
                f" {mechanisms_cell(b)} | {cell(b, 'mean', '{:.4f}')} | "
                f"{cell(b, 'coverage', '{:.2f}')} | {cell(b, 'outlines')} | "
                f"{cell(b, 'seconds', '{:.1f}')} |"
            )
        lines.append(line)
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(REPO, "build"))
    parser.add_argument("--corpus", default=os.path.join(REPO, "build", "corpus"))
    parser.add_argument("--out", default=os.path.join(REPO, "out", "corpus_results"))
    parser.add_argument("--json", help="keep the rows in this file")
    parser.add_argument("--before", help="rows kept earlier, printed beside")
    parser.add_argument("names", nargs="*", help="models (default: the whole corpus)")
    args = parser.parse_args(argv)
    popup = os.path.join(args.build, "bin", "popup")
    rows = []
    for name in args.names or list(CORPUS):
        row = fit_row(popup, args.corpus, name, args.out)
        rows.append(row)
        print(
            f"{name}: exit {row['exit']} {mechanisms_cell(row)} mean {cell(row, 'mean', '{:.4f}')}"
            f" cov {cell(row, 'coverage', '{:.2f}')} outlines {cell(row, 'outlines')}"
            f" {row['seconds']:.1f} s",
            file=sys.stderr,
        )
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(rows, f, indent=1)
    before = []
    if args.before:
        with open(args.before, encoding="utf-8") as f:
            before = json.load(f)
    print("\n".join(table(rows, before)))


if __name__ == "__main__":
    main()
