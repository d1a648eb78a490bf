"""`popup check DESIGN`: the validity check of a .json design or of every card of a FreeCAD
document (or the one --card names), as text or one JSON object; exit 0 when every design is valid.
"""

import json
import math
import os

from popupwb.cli.common import EXIT_INVALID, EXIT_VALID, InputError, format_report, stdout_to_stderr
from popupwb.cli.designs import is_document, load_designs
from popupwb.validity.card_titles import add_scaffold_titles
from popupwb.printable import printable_lines

MAX_SAMPLES = 100000


def add_parser(sub):
    check = sub.add_parser(
        "check",
        help="check that a design folds, stays stable, never self-intersects and closes enclosed",
        description="Simulate the fold from open (180 deg) to closed (0 deg) and report the "
        "validity verdicts: foldable, stable, intersection-free, enclosed.",
    )
    check.add_argument(
        "design", help="design file (.json) or FreeCAD document with a Scaffold or a PopUpCard"
    )
    check.add_argument("--json", action="store_true", help="print the report as one JSON object")
    check.add_argument(
        "--card",
        metavar="NAME",
        help="check only this PopUpCard or Scaffold (object Name or Label) of an .FCStd",
    )
    check.add_argument(
        "--samples",
        type=int,
        default=181,
        metavar="N",
        help="fold angles sampled evenly over 0..180 deg (default 181)",
    )
    check.add_argument(
        "--clearance",
        type=float,
        default=0.0,
        metavar="MM",
        help="gap in mm two patches must keep, e.g. the paper thickness (default 0)",
    )
    check.set_defaults(run=run)
    return check


def _check_options(args):
    if not 2 <= args.samples <= MAX_SAMPLES:  # the core's range (ValidityOptions)
        raise InputError(f"--samples {args.samples}: must be 2 to {MAX_SAMPLES}")
    if not math.isfinite(args.clearance) or args.clearance < 0:
        raise InputError(f"--clearance {args.clearance}: must be a finite length >= 0 mm")


def check_design(popupcore, design, samples, clearance):
    """The validity report of one design as a dict, with the design's object fields."""
    with stdout_to_stderr():
        report = popupcore.check_validity(design.scaffold, samples=samples, clearance=clearance)
    result = report.to_dict()
    rejected = [d for d in result["diagnostics"] if d["code"] == "bad_option"]
    if rejected:  # limits the core enforces beyond the checks above (they depend on the design)
        given = {"samples": samples, "clearance": clearance}
        d = rejected[0]
        flag = f"--{d['parameter']} {given[d['parameter']]:g}" if d["parameter"] in given else ""
        raise InputError(f"{flag}: {d['message']}" if flag else d["message"])
    add_scaffold_titles(result, design.patch_titles, design.scaffold)
    return {**result, **design.fields}


def _card_header(report):
    name, label = report["object"], report["label"]
    return f"== {label} ==" if label == name else f"== {label} ({name}) =="


def run(args):
    _check_options(args)
    popupcore, designs = load_designs(args.design, args.card)
    reports = [check_design(popupcore, design, args.samples, args.clearance) for design in designs]
    valid = all(report["valid"] for report in reports)
    if args.json:
        # One design: its report at the top level, as before several cards were checked.
        result = dict(reports[0]) if len(reports) == 1 else {}
        result.update(
            file=os.path.abspath(args.design),
            samples=args.samples,
            clearance=args.clearance,
            valid=valid,
        )
        if is_document(args.design):
            result["cards"] = reports
        print(json.dumps(result, indent=2))
    elif len(reports) == 1:
        print(printable_lines(format_report(reports[0])))
    else:
        blocks = [f"{_card_header(r)}\n{format_report(r)}" for r in reports]
        print(printable_lines("\n\n".join(blocks)))
        invalid = sum(1 for r in reports if not r["valid"])
        print(f"\n{len(reports)} cards checked: {len(reports) - invalid} valid, {invalid} invalid")
    return EXIT_VALID if valid else EXIT_INVALID
