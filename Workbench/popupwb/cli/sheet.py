"""`popup sheet DESIGN --out DIR`: a design laid out flat for cutting (DXF, SVG, PDF, instructions
and a report); a design the validity check rejects is refused unless --force stamps it NOT VALID.
"""

import json
import os
import sys

from popupwb.cli.check import check_design
from popupwb.cli.common import (
    EXIT_INVALID,
    EXIT_VALID,
    InputError,
    Parser,
    format_report,
    import_core,
    one_line,
    read_preferences,
    stdout_to_stderr,
)
from popupwb.cli.designs import card_printed_sides, load_designs
from popupwb.patch_titles import name_patches
from popupwb.validity.card_titles import subjects_and_names
from popupwb.printable import printable, printable_lines
from popupwb.sheets import sheet_options


def add_parser(sub):
    sheet = sub.add_parser(
        "sheet",
        help="lay a design out flat for cutting: DXF, SVG, PDF, instructions and a report",
        description="Unfold the design into pieces with glue tabs, fold lines and labels, nest "
        "them onto sheets and write DIR/sheets.dxf, sheets.svg, sheets.pdf, instructions.pdf and "
        "report.json (and sheets.json, the layout itself). Paper, kerf, tab width and angle, "
        "layer names and colours and the folder default to FreeCAD's PopUp preferences (the "
        "user.cfg of FREECAD_USER_HOME, else ~/.config/FreeCAD); options override them.",
    )
    sheet.add_argument(
        "design", help="design file (.json) or FreeCAD document with a Scaffold or a PopUpCard"
    )
    sheet.add_argument(
        "--out",
        metavar="DIR",
        help="folder for the files (default: the export folder of the PopUp preferences)",
    )
    sheet.add_argument(
        "--card",
        metavar="NAME",
        help="the PopUpCard or Scaffold (object Name or Label) to lay out, when an .FCStd has "
        "several",
    )
    sheet.add_argument(
        "--paper",
        help="A4, A3, Letter, Tabloid or WxH in mm (default: the PopUp preference, else the "
        "smallest preset holding every piece, presets of the system's paper family first)",
    )
    sheet_options.add_cli_arguments(sheet)
    sheet.add_argument(
        "--registration-marks", action="store_true", help="print-then-cut marks in the PDF"
    )
    sheet.add_argument(
        "--force",
        action="store_true",
        help="write the sheets of a design the validity check rejects, stamped NOT VALID",
    )
    sheet.add_argument("--json", action="store_true", help="print the report as one JSON object")
    sheet.set_defaults(run=run)
    return sheet


def parse_args(words):
    """The arguments of `popup sheet WORDS...`, parsed as the command line parses them (for the
    commands that write their sheets through this one)."""
    parser = Parser(prog="popup")
    add_parser(parser.add_subparsers(dest="command", parser_class=Parser))
    return parser.parse_args(["sheet", *words])


def _flag_findings(findings):
    """Option findings as one line, each led by the flag at fault (--tab-angle: ...); None when a
    finding is not about a flag."""
    flags = {option.name: sheet_options.cli_flag(option) for option in sheet_options.SHEET_OPTIONS}
    if findings and all(d["parameter"] in flags for d in findings):
        return "; ".join(f"{flags[d['parameter']]}: {d['message']}" for d in findings)
    return None


def _option_message(design, error):
    """A layout error as one line, each finding led by the flag at fault (--tab-angle: ...)."""
    return _flag_findings(getattr(error, "diagnostics", None) or []) or (
        f"{design}: {one_line(error)}"
    )


def _check_sheet_options(options):
    """The layout options' range errors, before the design is loaded and checked: a bad value
    should not wait for them (the layout checks the same again)."""
    ranged = {name: value for name, value in options.items() if name != "printed_sides"}
    try:
        sheet_options.parse_sides(options.get("printed_sides", []))
    except ValueError as e:
        raise InputError(f"--printed-side: {e}")
    import_core()
    findings = sheet_options.core_options(**ranged).check()
    if findings:
        raise InputError(_flag_findings(findings) or "; ".join(d["message"] for d in findings))


def _refuse_invalid(args, design, validity, not_valid):
    """Prints why the sheets of a rejected design are not written; returns the exit status."""
    if args.json:
        result = {"file": os.path.abspath(args.design), **design.fields}
        result.update(valid=False, written=False, validity=validity)
        print(json.dumps(result, indent=2))
    else:
        print(printable_lines(format_report(validity)))
    print(
        f"popup: {args.design}: {not_valid.text()}; no sheets written "
        "(--force writes them stamped NOT VALID)",
        file=sys.stderr,
    )
    return EXIT_INVALID


def _print_sheet_summary(report, paths, choice, not_valid, titles, scaffold):
    if choice is not None:
        print(choice.text())
    for path in [
        paths["dxf"],
        *paths["svg"],
        paths["pdf"],
        paths["instructions"],
        paths["report"],
        paths["sheet_set"],
    ]:
        print(f"wrote {path}")
    trip = report["round_trip"]
    print(
        f"{len(report['pieces'])} pieces, {report['tabs']} glue tabs on {report['sheets']} "
        f"{report['paper']['name']} sheet(s) (bounding-box shelf packing: "
        f"{report['shelf_packer_sheets']}); cut length {report['cut_length']:.1f} mm; "
        f"closed stack {report['stack_height']:.2f} mm"
    )
    print(
        f"round trip: {trip['max_error']:.3g} mm over {trip['angles']} fold angles "
        f"(tolerance {trip['tolerance']:.3g} mm) - {'ok' if trip['ok'] else 'FAILED'}"
    )
    if not_valid is not None:
        print(f"{not_valid.text()}: sheets written anyway (--force), every sheet stamped")
    subjects, names = subjects_and_names(scaffold)
    for d in report["errors"] + report["warnings"]:
        message = name_patches(d["message"], titles, subjects, names)
        print(printable(f"{d['severity']}: {d['code']}: {message}"))


def run(args):
    if args.paper is not None:  # before the slower steps: a typo should not wait for them
        try:
            import_core().paper_size(args.paper)
        except ValueError as e:
            raise InputError(f"--paper {args.paper}: {one_line(e)}")
    _check_sheet_options(sheet_options.from_cli(args))
    # The preferences are the defaults; each option given overrides its own.
    prefs = read_preferences()
    args.paper = prefs.sheet_paper if args.paper is None else args.paper
    args.out = args.out or prefs.export_folder
    if not args.out:
        raise InputError(
            "--out DIR: say which folder to write into (or set the export folder in Edit › "
            "Preferences › PopUp)"
        )
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        raise InputError(f"--out {args.out}: is a file, not a folder")
    from popupwb.sheets.export import export_sheets, layout
    from popupwb.sheets.not_valid_stamp import not_valid_of
    from popupwb.sheets.paper_choice import layout_on_smallest_paper

    popupcore, (design,) = load_designs(args.design, args.card, one=True, with_model=True)
    # Sheets are for valid designs: the check with `popup check`'s defaults comes first.
    validity = check_design(popupcore, design, samples=181, clearance=0.0)
    not_valid = not_valid_of(validity)
    if not_valid is not None and not args.force:
        return _refuse_invalid(args, design, validity, not_valid)
    options = {**prefs.sheet_options, **sheet_options.from_cli(args)}
    if "printed_sides" not in options:  # the card's CuttingSheet says, as in the feature
        card_sides = card_printed_sides(args, design)
        if card_sides:
            options["printed_sides"] = sheet_options.sides_text(card_sides)
    choice = None
    with stdout_to_stderr():
        try:
            if args.paper is None:
                sheet_set, choice = layout_on_smallest_paper(design.scaffold, **options)
            else:
                sheet_set = layout(design.scaffold, paper=args.paper, **options)
        except ValueError as e:  # a bad option, or a piece too large for the paper(s)
            raise InputError(_option_message(args.design, e))
        artwork = _artwork(args, design, sheet_set)
        try:
            paths = export_sheets(
                sheet_set,
                args.out,
                style=prefs.style,
                registration_marks=args.registration_marks,
                not_valid=not_valid,
                artwork=artwork,
            )
        except OSError as e:
            raise InputError(f"--out {args.out}: {one_line(e)}")
    with open(paths["report"]) as f:
        report = json.load(f)
    if args.json:
        report.update(design.fields, file=os.path.abspath(args.design), files=paths)
        report.update(
            paper_chosen_automatically=choice is not None,
            valid=not_valid is None,
            written=True,
            validity=validity,
        )
        print(json.dumps(report, indent=2))
    else:
        _print_sheet_summary(report, paths, choice, not_valid, design.patch_titles, design.scaffold)
    return EXIT_INVALID if report["errors"] or not_valid is not None else EXIT_VALID


def _artwork(args, design, sheet_set):
    """The model's appearance on each laid-out patch, for a card designed from a model (its
    SourceModel) whose CuttingSheets print it (PrintArtwork, cutting_sheet.card_prints_artwork);
    None otherwise. The print layer of the PDF and SVG carries it, with registration marks; its
    warnings (a texture that cannot be read) are said on stderr."""
    if design.model is None:
        return None
    from popupwb.sheets.print_artwork import artwork_warnings, source_model_artwork

    try:
        artwork = source_model_artwork(
            design.model, design.scaffold, sheet_set, args.design, limbs=design.limbs
        )
    except ValueError as e:
        raise InputError(one_line(e))
    for d in artwork_warnings(artwork):  # an unreadable texture: the model prints shaded
        print(printable(f"warning: {d['code']}: {d['message']}"), file=sys.stderr)
    return artwork
