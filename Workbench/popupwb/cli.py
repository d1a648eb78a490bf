"""The `popup` command line: check a pop-up design without opening FreeCAD's GUI.

    popup check design.json [--json] [--samples N] [--clearance MM]
    popup check card.FCStd                  # the first PopUp Scaffold's design or PopUpCard
    popup sheet card.FCStd --out DIR [--paper A4] [--kerf 0.1] [--json]
    popup --version

Exit status: 0 the design is valid (check) or its sheets are usable (sheet), 1 it is not (the
report says why; sheet still writes every file), 2 the input could not be used (missing file, bad
JSON, bad design, no scaffold, bad option, a piece larger than the paper), 3 an internal error.
Errors are one line on stderr naming the file and what is wrong.
"""

import argparse
import contextlib
import json
import math
import os
import sys

EXIT_VALID = 0
EXIT_INVALID = 1
EXIT_BAD_INPUT = 2
EXIT_INTERNAL = 3

FREECAD_LIB = "/usr/lib/freecad-python3/lib"
VERSION = "0.1.0"


class InputError(Exception):
    """Input the command cannot use; the message is the whole explanation (one line)."""


class _Parser(argparse.ArgumentParser):
    # argparse prints the usage and exits on a bad option; we want one line and our exit code.
    def error(self, message):
        raise InputError(f"{message} (see '{self.prog} --help')")


def _one_line(text):
    return "; ".join(line.strip() for line in str(text).splitlines() if line.strip())


@contextlib.contextmanager
def _stdout_to_stderr():
    """Sends whatever FreeCAD or the core print to stderr, so stdout carries only our output."""
    sys.stdout.flush()
    saved = os.dup(1)
    try:
        os.dup2(2, 1)
        yield
    finally:
        sys.stdout.flush()
        os.dup2(saved, 1)
        os.close(saved)


def _import_core():
    try:
        import popupcore
    except ImportError:
        try:
            import popupwb.core  # noqa: F401  (puts build/python on sys.path when run from source)
            import popupcore
        except ImportError as e:  # popupwb.core's message says where it looked and what to do
            raise InputError(str(e))
    return popupcore


def _format_report(report_dict):
    # popupwb.validity is FreeCAD-side (it also checks Scaffold objects): it imports FreeCAD.
    with _stdout_to_stderr():
        _import_freecad()
        try:
            from popupwb.validity import format_report
        except ImportError as e:
            raise InputError(f"cannot import popupwb.validity ({e}); use --json")
    return format_report(report_dict)


def _import_freecad():
    if FREECAD_LIB not in sys.path:
        sys.path.append(FREECAD_LIB)
    try:
        import FreeCAD
    except ImportError as e:
        raise InputError(f"cannot import FreeCAD from {FREECAD_LIB} ({e}); is freecad installed?")
    # Debian's FreeCAD restores a document's Python proxies only from modules inside a Mod folder
    # (the protection against documents importing arbitrary modules). Trust this workbench's own
    # folder, as `freecadcmd -M <Workbench>` would, so the Scaffold proxy loads.
    mod_dirs = getattr(FreeCAD, "__ModDirs__", None)
    if isinstance(mod_dirs, list):
        for resolve in (os.path.abspath, os.path.realpath):  # the path as imported, and resolved
            workbench_dir = os.path.dirname(os.path.dirname(resolve(__file__)))
            if workbench_dir not in mod_dirs:
                mod_dirs.append(workbench_dir)
    return FreeCAD


def _find_scaffold(doc):
    """The first Scaffold or PopUpCard object of `doc` (None if there is neither)."""
    from popupwb.assembly import is_card
    from popupwb.features.scaffold_feature import is_scaffold

    return next((obj for obj in doc.Objects if is_scaffold(obj) or is_card(obj)), None)


def _card_design(path, card):
    """The assembled scaffold of a PopUpCard and its mechanisms; a part that does not build makes
    the input unusable (the message is the feature's error)."""
    from popupwb.assembly import assembly_of

    built = assembly_of(card)
    problems = ([built.card_error] if built.card_error else []) + list(built.errors.values())
    if problems:
        raise InputError(f"{path}: {problems[0]}")
    return built.scaffold.copy(), {"object": card.Name}


def _load_json_design(popupcore, path, label):
    try:
        return popupcore.load_scaffold(path)
    except (ValueError, RuntimeError, OSError) as e:
        raise InputError(f"{label}: {_one_line(e)}")


def _load_fcstd_design(popupcore, path):
    """Loads the design of the first Scaffold or PopUpCard object in an .FCStd file."""
    with _stdout_to_stderr():
        FreeCAD = _import_freecad()
        try:
            doc = FreeCAD.openDocument(os.path.abspath(path))
        except Exception as e:  # FreeCAD raises plain Exception/OSError/ValueError on bad files
            raise InputError(f"{path}: cannot open as a FreeCAD document ({_one_line(e)})")
        try:
            obj = _find_scaffold(doc)
            if obj is None:
                orphans = [o.Label for o in doc.Objects if "DesignFile" in o.PropertiesList]
                if orphans:
                    raise InputError(
                        f"{path}: object '{orphans[0]}' looks like a PopUp Scaffold but its "
                        "proxy did not load (install the workbench: make install-dev)"
                    )
                raise InputError(f"{path}: no PopUp Scaffold or PopUpCard object in this document")
            if "DesignFile" not in obj.PropertiesList:
                return _card_design(path, obj)
            design = str(obj.DesignFile)
            what = f"{path}: {obj.Label}.DesignFile"
            if not design:
                raise InputError(f"{what} is empty")
            if not os.path.isabs(design):
                design = os.path.join(os.path.dirname(os.path.abspath(path)), design)
            if not os.path.isfile(design):
                raise InputError(f"{what} = '{obj.DesignFile}': no such file")
            # Load now: a PropertyFileIncluded path lies in the document's transient folder,
            # which goes away when the document closes.
            scaffold = _load_json_design(popupcore, design, f"{what} = '{obj.DesignFile}'")
            # The folder of an embedded design is the document's temporary one: name only.
            return scaffold, {"object": obj.Name, "design_file": os.path.basename(design)}
        finally:
            FreeCAD.closeDocument(doc.Name)


def load_design(path):
    """Returns (popupcore, scaffold, extra report fields) for a .json or .FCStd path."""
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file")
    if not os.path.isfile(path):
        raise InputError(f"{path}: not a file")
    if not os.access(path, os.R_OK):
        raise InputError(f"{path}: not readable (permission denied)")
    popupcore = _import_core()
    if path.lower().endswith(".fcstd"):
        scaffold, extra = _load_fcstd_design(popupcore, path)
    else:
        scaffold, extra = _load_json_design(popupcore, path, path), {}
    return popupcore, scaffold, extra


def cmd_check(args):
    if args.samples < 2:
        raise InputError(f"--samples {args.samples}: must be at least 2")
    if not math.isfinite(args.clearance) or args.clearance < 0:
        raise InputError(f"--clearance {args.clearance}: must be a finite length >= 0 mm")
    popupcore, scaffold, extra = load_design(args.design)
    with _stdout_to_stderr():
        report = popupcore.check_validity(scaffold, samples=args.samples, clearance=args.clearance)
    result = report.to_dict()
    rejected = [d["message"] for d in result["diagnostics"] if d["code"] == "bad_option"]
    if rejected:  # limits the core enforces beyond the checks above
        raise InputError(f"--samples {args.samples} --clearance {args.clearance}: {rejected[0]}")
    if args.json:
        result = dict(result)
        result["file"] = os.path.abspath(args.design)
        result["samples"] = args.samples
        result["clearance"] = args.clearance
        result.update(extra)
        print(json.dumps(result, indent=2))
    else:
        print(_format_report(result))
    return EXIT_VALID if result["valid"] else EXIT_INVALID


def cmd_sheet(args):
    from popupwb.sheets.export import export_sheets, layout

    popupcore, scaffold, extra = load_design(args.design)
    options = dict(
        paper=args.paper,
        kerf=args.kerf,
        margin=args.margin,
        spacing=args.spacing,
        tab_width=args.tab_width,
        tab_angle=args.tab_angle,
        fold_hints=args.fold_hints,
    )
    with _stdout_to_stderr():
        try:
            sheet_set = layout(scaffold, **options)
        except ValueError as e:  # DesignError: a bad option or a piece too large for the paper
            raise InputError(f"{args.design}: {_one_line(e)}")
        try:
            paths = export_sheets(sheet_set, args.out, registration_marks=args.registration_marks)
        except OSError as e:
            raise InputError(f"--out {args.out}: {_one_line(e)}")
    with open(paths["report"]) as f:
        report = json.load(f)
    errors = report["errors"]
    if args.json:
        report.update(extra, file=os.path.abspath(args.design), files=paths)
        print(json.dumps(report, indent=2))
    else:
        svg = paths["svg"]
        for path in [
            paths["dxf"],
            *svg,
            paths["pdf"],
            paths["instructions"],
            paths["report"],
            paths["sheet_set"],
        ]:
            print(f"wrote {path}")
        trip = report["round_trip"]
        print(
            f"{len(report['pieces'])} pieces, {report['tabs']} glue tabs on {report['sheets']} "
            f"{sheet_set['paper']['name']} sheet(s) (bounding-box shelf packing: "
            f"{report['shelf_packer_sheets']}); cut length {report['cut_length']:.1f} mm; "
            f"closed stack {report['stack_height']:.2f} mm"
        )
        print(
            f"round trip: {trip['max_error']:.3g} mm over {trip['angles']} fold angles "
            f"(tolerance {trip['tolerance']:.3g} mm) - {'ok' if trip['ok'] else 'FAILED'}"
        )
        for d in errors + report["warnings"]:
            print(f"{d['severity']}: {d['code']}: {d['message']}")
    return EXIT_INVALID if errors else EXIT_VALID


def _version():
    try:
        import popupwb

        return getattr(popupwb, "__version__", VERSION)
    except ImportError:
        return VERSION


def build_parser():
    parser = _Parser(
        prog="popup",
        description="PopUp: precise paper pop-up design (FreeCAD workbench) from the shell.",
        epilog="Exit status: 0 valid, 1 invalid, 2 unusable input, 3 internal error.",
    )
    parser.add_argument("--version", action="version", version=f"popup {_version()}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
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
    check.set_defaults(run=cmd_check)

    sheet = sub.add_parser(
        "sheet",
        help="lay a design out flat for cutting: DXF, SVG, PDF, instructions and a report",
        description="Unfold the design into pieces with glue tabs, fold lines and labels, nest "
        "them onto sheets and write DIR/sheets.dxf, sheets.svg, sheets.pdf, instructions.pdf and "
        "report.json (and sheets.json, the layout itself).",
    )
    sheet.add_argument(
        "design", help="design file (.json) or FreeCAD document with a Scaffold or a PopUpCard"
    )
    sheet.add_argument("--out", required=True, metavar="DIR", help="folder for the files")
    sheet.add_argument(
        "--paper", default="A4", help="A4, A3, Letter, Tabloid or WxH in mm (default A4)"
    )
    sheet.add_argument("--kerf", type=float, default=0.1, metavar="MM", help="default 0.1")
    sheet.add_argument("--margin", type=float, default=10.0, metavar="MM", help="default 10")
    sheet.add_argument(
        "--spacing", type=float, default=2.0, metavar="MM", help="between pieces, default 2"
    )
    sheet.add_argument("--tab-width", type=float, default=8.0, metavar="MM", help="default 8")
    sheet.add_argument(
        "--tab-angle", type=float, default=45.0, metavar="DEG", help="tab side angle, default 45"
    )
    sheet.add_argument("--fold-hints", action="store_true", help="print M/V beside each fold")
    sheet.add_argument(
        "--registration-marks", action="store_true", help="print-then-cut marks in the PDF"
    )
    sheet.add_argument("--json", action="store_true", help="print the report as one JSON object")
    sheet.set_defaults(run=cmd_sheet)
    return parser


def main(argv=None):
    try:
        args = build_parser().parse_args(argv)
        return args.run(args)
    except InputError as e:
        print(f"popup: error: {_one_line(e)}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except BrokenPipeError:  # stdout closed early (popup check ... | head): not an error of ours
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141
    except KeyboardInterrupt:
        print("popup: interrupted", file=sys.stderr)
        return 130
    except Exception as e:  # never a traceback on the terminal
        print(f"popup: internal error: {type(e).__name__}: {_one_line(e)}", file=sys.stderr)
        return EXIT_INTERNAL


if __name__ == "__main__":
    sys.exit(main())
