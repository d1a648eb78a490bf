"""`popup verify DESIGN SHEETS`: the cutting file read back as the maker gets it, folded by the
simulator and compared patch by patch with the design; exit 0 when it makes the design.
"""

import json
import math
import os

from popupwb.cli.common import (
    EXIT_INVALID,
    EXIT_VALID,
    InputError,
    one_line,
    read_preferences,
    stdout_to_stderr,
)
from popupwb.cli.designs import card_printed_sides, load_designs
from popupwb.printable import printable

VERIFY_ANGLES = 13  # fold angles verify_sheets samples by default
MAX_VERIFY_ANGLES = 361  # the core's limit


def add_parser(sub):
    verify = sub.add_parser(
        "verify",
        help="prove that cutting files (DXF) make the design, reading only what the maker gets",
        description="Read the CUT, MOUNTAIN, VALLEY, GLUE and LABEL layers and the PopUpKerf "
        "header of a DXF cutting file, rebuild the pieces from them, fold them with the "
        "simulator and compare every patch with the design. Exit 0 when they match, 1 when they "
        "do not (each finding printed), 2 for unusable input.",
    )
    verify.add_argument(
        "design", help="design file (.json) or FreeCAD document with a Scaffold or a PopUpCard"
    )
    verify.add_argument(
        "sheets",
        help="the folder popup sheet --out wrote (its sheets.dxf is read) or a DXF cutting file",
    )
    verify.add_argument(
        "--card",
        metavar="NAME",
        help="the PopUpCard or Scaffold (object Name or Label) the sheets are of, when an .FCStd "
        "has several",
    )
    verify.add_argument(
        "--printed-side",
        dest="printed_side",
        action="append",
        metavar="PIECE=SIDE",
        help="a piece the sheets print on its back, as popup sheet was given it (P1=back); "
        "repeat for several pieces; overrides the card's CuttingSheet PrintedSides",
    )
    verify.add_argument(
        "--kerf",
        type=float,
        metavar="MM",
        help="the kerf the CUT lines were written with (default: the DXF header's PopUpKerf)",
    )
    verify.add_argument(
        "--angles",
        type=int,
        default=VERIFY_ANGLES,
        metavar="N",
        help=f"fold angles compared, evenly from the design angle to closed (default "
        f"{VERIFY_ANGLES})",
    )
    verify.add_argument("--json", action="store_true", help="print the result as one JSON object")
    verify.set_defaults(run=run)
    return verify


def _verify_sides(args, design):
    """The printed sides the sheets were written with: the card's CuttingSheet's PrintedSides
    (for an .FCStd card), each piece --printed-side names overriding it."""
    from popupwb.sheets.sheet_options import parse_sides

    try:
        given = parse_sides(args.printed_side or [])
    except ValueError as e:
        raise InputError(f"--printed-side: {e}")
    for piece, side in given.items():
        if side not in ("front", "back"):
            raise InputError(f"--printed-side {piece}={side}: the side must be front or back")
    return {**card_printed_sides(args, design, flag_given=bool(given)), **given}


def _verify_failure(args, error):
    """A DesignError of verify_sheets as one line, led by the flag at fault when there is one."""
    findings = [d for d in getattr(error, "diagnostics", None) or [] if d["severity"] == "error"]
    flags = {"printed_sides": "--printed-side", "angles": "--angles", "kerf": "--kerf"}
    if findings and all(d["parameter"] in flags for d in findings):
        return "; ".join(f"{flags[d['parameter']]}: {d['message']}" for d in findings)
    text = "; ".join(d["message"] for d in findings) or one_line(error)
    return f"{args.design}: cannot verify against this design: {text}"


def _finite_or_none(value):
    return value if isinstance(value, (int, float)) and math.isfinite(value) else None


def run(args):
    if args.kerf is not None and (not math.isfinite(args.kerf) or args.kerf < 0):
        raise InputError(f"--kerf {args.kerf:g}: must be a finite length >= 0 mm")
    if not 2 <= args.angles <= MAX_VERIFY_ANGLES:
        raise InputError(f"--angles {args.angles}: must be 2 to {MAX_VERIFY_ANGLES}")
    from popupwb.sheets.dxf_reader import DxfReadError, read_dxf, sheets_path

    # The sheets first: reading them is quick, and a wrong path should not wait for FreeCAD.
    try:
        dxf = sheets_path(args.sheets)
        # The layers are those `popup sheet` writes: the names in the preferences.
        drawing = read_dxf(dxf, kerf=args.kerf, style=read_preferences().style)
    except DxfReadError as e:
        raise InputError(str(e))
    popupcore, (design,) = load_designs(args.design, args.card, one=True)
    sides = _verify_sides(args, design)
    with stdout_to_stderr():
        try:
            result = popupcore.verify_sheets(
                design.scaffold,
                [drawing.to_sheet_drawing(popupcore)],
                printed_sides=sides,
                angles=args.angles,
            )
        except popupcore.DesignError as e:
            raise InputError(_verify_failure(args, e))
    diagnostics = list(result["diagnostics"])
    errors = [d for d in diagnostics if d["severity"] == "error"]
    ok = bool(result["ok"]) and not errors
    if args.json:
        report = {
            "design": os.path.abspath(args.design),
            "sheets": os.path.abspath(dxf),
            **design.fields,
            "ok": ok,
            "max_error": _finite_or_none(result["max_error"]),
            "tolerance": _finite_or_none(result["tolerance"]),
            "angles": result["angles"],
            "kerf": drawing.kerf,
            "printed_sides": sides,
            "diagnostics": diagnostics,
        }
        print(json.dumps(report, indent=2))
        return EXIT_VALID if ok else EXIT_INVALID
    for d in errors + [d for d in diagnostics if d["severity"] != "error"]:
        print(printable(f"{d['severity']}: {d['code']}: {d['message']}"))
    error, tolerance = result["max_error"], result["tolerance"]
    if ok:
        print(
            f"sheets match the design: every patch within {error:.3g} mm (tolerance "
            f"{tolerance:.3g} mm) over {result['angles']} fold angles"
        )
        return EXIT_VALID
    measured = (
        f"largest patch error {error:.3g} mm"
        if error is not None and math.isfinite(error)
        else "the re-folded card could not be compared"
    )
    print(
        f"sheets do NOT match the design: {len(errors)} error(s); {measured} (tolerance "
        f"{tolerance:.3g} mm) over {result['angles']} fold angles"
    )
    return EXIT_INVALID
