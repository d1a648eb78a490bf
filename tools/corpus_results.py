#!/usr/bin/python3
"""`popup fit` on every model of the realistic corpus (tools/make_corpus.py): one row per model.

    /usr/bin/python3 tools/corpus_results.py --build build --corpus build/corpus \
        --out out/corpus_results [--json rows.json] [--before before.json] [--doc FILE]

Each model is fitted with seed 1 and the automatic axes, as a maker who does not know the file's up
axis would; the row is read back from report.json only, with the wall time of the whole command.
`--json` keeps the rows; `--before` names rows kept earlier (another build) to print beside;
`--doc` writes the corpus section of docs/SHAPE_RESULTS.md (from its heading to the end of the
file) with each preview, shrunk into docs/images/corpus_fit/, under the table.
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


SECTION = "## The realistic corpus"
PREVIEW_WIDTH = 800  # px: the doc's pictures, half the size popup fit writes


def write_section(doc, rows, before, images):
    """Replaces the corpus section of `doc` (SECTION to the end) with the table and previews."""
    from PIL import Image

    os.makedirs(images, exist_ok=True)
    lines = [
        SECTION,
        "",
        "Written by `tools/corpus_results.py` from the report.json of `popup fit` (seed 1, A4, the",
        "automatic axes: a maker who does not know the file's up) on every model of",
        "`tools/make_corpus.py` (docs/CORPUS.md). *Before* is the same command on the build before",
        "issue 25's search (commit 0dc57cb). Mean is model to pop-up over the diagonal of the model",
        "(above its plate, where it has one); outlines counts the principal parts that kept the",
        "model's silhouette; s is the whole command's wall time on this 2-core machine. Exit 1 is",
        "a design whose sheets did not verify or no design.",
        "",
    ]
    lines += table(rows, before)
    lines.append("")
    for row in rows:
        src = row.get("preview")
        if not src or not os.path.isfile(src):
            continue
        name = row["model"]
        with Image.open(src) as im:
            h = round(im.height * PREVIEW_WIDTH / im.width)
            im.convert("RGB").resize((PREVIEW_WIDTH, h), Image.LANCZOS).save(
                os.path.join(images, f"{name}.png"), optimize=True
            )
        rel = os.path.relpath(os.path.join(images, f"{name}.png"), os.path.dirname(doc))
        lines += [f"**{name}**: {mechanisms_cell(row)}", "", f"![{name}]({rel})", ""]
    with open(doc, encoding="utf-8") as f:
        text = f.read()
    head = text.split(SECTION)[0].rstrip() + "\n\n"
    with open(doc, "w", encoding="utf-8") as f:
        f.write(head + "\n".join(lines) + "\n")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(REPO, "build"))
    parser.add_argument("--corpus", default=os.path.join(REPO, "build", "corpus"))
    parser.add_argument("--out", default=os.path.join(REPO, "out", "corpus_results"))
    parser.add_argument("--json", help="keep the rows in this file")
    parser.add_argument("--before", help="rows kept earlier, printed beside")
    parser.add_argument("--doc", help="write the corpus section of this file (SHAPE_RESULTS.md)")
    parser.add_argument("--from-json", help="rows kept earlier: write them instead of fitting")
    parser.add_argument("names", nargs="*", help="models (default: the whole corpus)")
    args = parser.parse_args(argv)
    popup = os.path.join(args.build, "bin", "popup")
    rows = []
    if args.from_json:
        with open(args.from_json, encoding="utf-8") as f:
            rows = json.load(f)
    for name in [] if args.from_json else args.names or list(CORPUS):
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
    if args.doc:
        images = os.path.join(os.path.dirname(os.path.abspath(args.doc)), "images", "corpus_fit")
        write_section(args.doc, rows, before, images)


if __name__ == "__main__":
    main()
