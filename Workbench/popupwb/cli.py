"""The `popup` command line: check a pop-up design without opening FreeCAD's GUI.

    popup check design.json [--json] [--samples N] [--clearance MM]
    popup check card.FCStd [--card NAME]    # every PopUpCard and Scaffold, or the one named
    popup sheet card.FCStd --out DIR [--card NAME] [--paper A4] [--kerf 0.1] [--force] [--json]
    popup verify card.FCStd DIR|sheets.dxf [--card NAME] [--printed-side P1=back] [--kerf MM]
    popup fit model.stl --out DIR [--max-mechanisms N] [--seed S] [--paper A4] [--up X,Y,Z]
              [--facing X,Y,Z] [--detail D]    # cli_fit.py: the card designed from a 3D model
    popup animate walk.bvh --out DIR [--seed S] [--iterations N] [--first-frame F]
              [--last-frame L] [--view X,Y,Z] [--up X,Y,Z] [--scale MM] [--paper A4]
                                               # cli_animate.py: motion from an animation
    popup --version

Exit status: 0 the design is valid (check; for a document every card checked), its sheets are
usable (sheet) or the cutting file makes the design (verify), 1 it is not or does not (the report
says why; sheet refuses a design the validity check rejects unless --force, and still writes every
file when only the layout reports errors; verify prints each finding), 2 the
input could not be used (missing file, bad JSON, bad design, no scaffold, unknown --card, bad
option, a piece larger than the paper), 3 an internal error. Errors are one line on stderr naming
the file and what is wrong.
"""

import argparse
import collections
import contextlib
import json
import math
import os
import re
import sys

from popupwb.patch_titles import add_titles, name_patches
from popupwb.printable import printable, printable_lines
from popupwb.readable_file import unreadable
from popupwb.sheets import sheet_options

EXIT_VALID = 0
EXIT_INVALID = 1
EXIT_BAD_INPUT = 2
EXIT_INTERNAL = 3

FREECAD_LIB = "/usr/lib/freecad-python3/lib"
VERSION = "0.1.0"


# A design to check, lay out or verify, and what the reports say about where it came from (object
# Name, Label, design file; empty for a .json design). `printed_sides` is what the card's
# CuttingSheet features say ({CuttingSheet Name: {piece: side}}), empty for anything else.
# `patch_titles` ({patch id: maker title}, patch_titles.py) names a card's patches in findings.
# `model` is the ModelMesh (card mm) a card was designed from (card.SourceModel, `popup fit`), whose
# appearance the sheets print as artwork; None for anything else.
Design = collections.namedtuple(
    "Design", "scaffold fields printed_sides patch_titles model", defaults=({}, {}, None)
)


class InputError(Exception):
    """Input the command cannot use; the message is the whole explanation (one line)."""


# What argparse takes for a negative number, hence an option's value rather than an option: its own
# pattern (-1, -.5) misses -1e-3, -inf and -nan, so `--kerf -inf` got "expected one argument"
# instead of the option's range check.
_NEGATIVE_NUMBER = re.compile(
    r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$", re.IGNORECASE
)


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # A private attribute of argparse (the same from Python 3.2 to 3.13); test_cli checks
        # that negative values reach every float option.
        self._negative_number_matcher = _NEGATIVE_NUMBER

    # argparse prints the usage and exits on a bad option; we want one line and our exit code.
    def error(self, message):
        raise InputError(f"{message} (see '{self.prog} --help')")


def _one_line(text):
    return "; ".join(line.strip() for line in str(text).splitlines() if line.strip())


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
        f"{design}: {_one_line(error)}"
    )


def _check_sheet_options(options):
    """The layout options' range errors, before the design is loaded and checked: a bad value
    should not wait for them (the layout checks the same again)."""
    ranged = {name: value for name, value in options.items() if name != "printed_sides"}
    try:
        sheet_options.parse_sides(options.get("printed_sides", []))
    except ValueError as e:
        raise InputError(f"--printed-side: {e}")
    _import_core()
    findings = sheet_options.core_options(**ranged).check()
    if findings:
        raise InputError(_flag_findings(findings) or "; ".join(d["message"] for d in findings))


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
            from popupwb.validity.report_text import format_report
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


def _design_objects(doc):
    """The Scaffold and PopUpCard objects of `doc`, in document order."""
    from popupwb.card_scaffold import is_card
    from popupwb.features.scaffold_feature import is_scaffold

    return [obj for obj in doc.Objects if is_scaffold(obj) or is_card(obj)]


def _object_names(objects):
    return ", ".join(o.Name if o.Label == o.Name else f"{o.Name} ('{o.Label}')" for o in objects)


def _select_cards(path, objects, card):
    """All of `objects`, or the one whose Name (else Label) is `card`."""
    if card is None:
        return objects
    chosen = [o for o in objects if o.Name == card] or [o for o in objects if o.Label == card]
    if not chosen:
        raise InputError(
            f"{path}: --card {card}: no PopUpCard or Scaffold has this Name or Label; "
            f"the document has: {_object_names(objects)}"
        )
    return chosen[:1]


def _card_design(path, card, several, with_model=False):
    """The assembled scaffold of a PopUpCard and its mechanisms; a part that does not build makes
    the input unusable (the message is the feature's error)."""
    from popupwb.card_scaffold import for_card, stray_features
    from popupwb.features.cutting_sheet import card_prints_artwork
    from popupwb.patch_titles import titles_of_card

    built = for_card(card)
    problems = ([built.card_error] if built.card_error else []) + list(built.errors.values())
    problems += stray_features(card.Document)
    if problems:
        # Several cards: say which one, and that the others can still be checked alone.
        where = f"{path}: card {card.Label}" if several else path
        hint = " (--card checks another card alone)" if several else ""
        raise InputError(f"{where}: {problems[0]}{hint}")
    return Design(
        built.scaffold.copy(),
        {"object": card.Name, "label": card.Label},
        _cutting_sides(card),
        titles_of_card(card, built),
        _source_model(path, card) if with_model and card_prints_artwork(card) else None,
    )


def _source_model(path, card):
    """The model the card was designed from, in card mm, or None (popupwb.fitting.model_source)."""
    from popupwb.fitting.model_source import card_model

    try:
        return card_model(card)
    except ValueError as e:
        raise InputError(f"{path}: {card.Label}.SourceModel: {_one_line(e)}")


def _cutting_sides(card):
    """{CuttingSheet Name: {piece: side}} of the CuttingSheets laying out `card`."""
    from popupwb.features.cutting_sheet import is_cutting_sheet
    from popupwb.sheets.sheet_options import parse_sides

    sides = {}
    for obj in card.Document.Objects:
        if is_cutting_sheet(obj) and obj.Card is not None and obj.Card.Name == card.Name:
            try:
                sides[obj.Name] = parse_sides(list(getattr(obj, "PrintedSides", [])))
            except ValueError as e:
                raise InputError(f"{card.Document.FileName}: {obj.Label}.PrintedSides: {e}")
    return sides


def _scaffold_design(popupcore, path, obj):
    design = str(obj.DesignFile)
    what = f"{path}: {obj.Label}.DesignFile"
    if not design:
        raise InputError(f"{what} is empty")
    if not os.path.isabs(design):
        design = os.path.join(os.path.dirname(os.path.abspath(path)), design)
    if not os.path.isfile(design):
        raise InputError(f"{what} = '{obj.DesignFile}': no such file")
    # Load now: a PropertyFileIncluded path lies in the document's transient folder, which goes
    # away when the document closes.
    scaffold = _load_json_design(popupcore, design, f"{what} = '{obj.DesignFile}'")
    # The folder of an embedded design is the document's temporary one: name only.
    fields = {"object": obj.Name, "label": obj.Label, "design_file": os.path.basename(design)}
    return Design(scaffold, fields)


def _load_json_design(popupcore, path, label):
    try:
        return popupcore.load_scaffold(path)
    except (ValueError, RuntimeError, OSError) as e:
        raise InputError(f"{label}: {_one_line(e)}")


def _load_fcstd_designs(popupcore, path, card, one, with_model=False):
    """The designs of the Scaffold and PopUpCard objects of an .FCStd file (or of the one named
    `card`); with `one`, several of them make the input unusable."""
    from popupwb.document_precheck import check_fcstd

    try:
        check_fcstd(path)
    except ValueError as e:
        raise InputError(f"{path}: {e}")
    with _stdout_to_stderr():
        FreeCAD = _import_freecad()
        try:
            doc = FreeCAD.openDocument(os.path.abspath(path))
        except Exception as e:  # FreeCAD raises plain Exception/OSError/ValueError on bad files
            raise InputError(f"{path}: cannot open as a FreeCAD document ({_one_line(e)})")
        try:
            objects = _design_objects(doc)
            if not objects:
                orphans = [o.Label for o in doc.Objects if "DesignFile" in o.PropertiesList]
                if orphans:
                    raise InputError(
                        f"{path}: object '{orphans[0]}' looks like a PopUp Scaffold but its "
                        "proxy did not load (install the workbench: make install-dev)"
                    )
                raise InputError(f"{path}: no PopUp Scaffold or PopUpCard object in this document")
            chosen = _select_cards(path, objects, card)
            if one and len(chosen) > 1:
                raise InputError(
                    f"{path}: {len(chosen)} cards ({_object_names(chosen)}): name the one to "
                    "lay out with --card"
                )
            return [
                (
                    _scaffold_design(popupcore, path, obj)
                    if "DesignFile" in obj.PropertiesList
                    else _card_design(path, obj, len(chosen) > 1, with_model)
                )
                for obj in chosen
            ]
        finally:
            FreeCAD.closeDocument(doc.Name)


def is_document(path):
    return path.lower().endswith(".fcstd")


def load_designs(path, card=None, one=False, with_model=False):
    """(popupcore, [Design]) for a .json path (one design) or an .FCStd path (each Scaffold and
    PopUpCard, or the one named `card`; with `one`, several are an InputError). `with_model`
    reads the model a card was designed from (Design.model, for the sheets' artwork)."""
    why = unreadable(path)
    if why:
        raise InputError(why)
    if card is not None and not is_document(path):
        raise InputError(f"--card {card}: only for FreeCAD documents (.FCStd), not {path}")
    popupcore = _import_core()
    if is_document(path):
        return popupcore, _load_fcstd_designs(popupcore, path, card, one, with_model)
    return popupcore, [Design(_load_json_design(popupcore, path, path), {})]


MAX_SAMPLES = 100000


def _check_options(args):
    if not 2 <= args.samples <= MAX_SAMPLES:  # the core's range (ValidityOptions)
        raise InputError(f"--samples {args.samples}: must be 2 to {MAX_SAMPLES}")
    if not math.isfinite(args.clearance) or args.clearance < 0:
        raise InputError(f"--clearance {args.clearance}: must be a finite length >= 0 mm")


def _check(popupcore, design, samples, clearance):
    """The validity report of one design as a dict, with the design's object fields."""
    with _stdout_to_stderr():
        report = popupcore.check_validity(design.scaffold, samples=samples, clearance=clearance)
    result = report.to_dict()
    rejected = [d for d in result["diagnostics"] if d["code"] == "bad_option"]
    if rejected:  # limits the core enforces beyond the checks above (they depend on the design)
        given = {"samples": samples, "clearance": clearance}
        d = rejected[0]
        flag = f"--{d['parameter']} {given[d['parameter']]:g}" if d["parameter"] in given else ""
        raise InputError(f"{flag}: {d['message']}" if flag else d["message"])
    add_titles(result, design.patch_titles)
    return {**result, **design.fields}


def _card_header(report):
    name, label = report["object"], report["label"]
    return f"== {label} ==" if label == name else f"== {label} ({name}) =="


def cmd_check(args):
    _check_options(args)
    popupcore, designs = load_designs(args.design, args.card)
    reports = [_check(popupcore, design, args.samples, args.clearance) for design in designs]
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
        print(printable_lines(_format_report(reports[0])))
    else:
        blocks = [f"{_card_header(r)}\n{_format_report(r)}" for r in reports]
        print(printable_lines("\n\n".join(blocks)))
        invalid = sum(1 for r in reports if not r["valid"])
        print(f"\n{len(reports)} cards checked: {len(reports) - invalid} valid, {invalid} invalid")
    return EXIT_VALID if valid else EXIT_INVALID


def _refuse_invalid(args, design, validity, not_valid):
    """Prints why the sheets of a rejected design are not written; returns the exit status."""
    if args.json:
        result = {"file": os.path.abspath(args.design), **design.fields}
        result.update(valid=False, written=False, validity=validity)
        print(json.dumps(result, indent=2))
    else:
        print(printable_lines(_format_report(validity)))
    print(
        f"popup: {args.design}: {not_valid.text()}; no sheets written "
        "(--force writes them stamped NOT VALID)",
        file=sys.stderr,
    )
    return EXIT_INVALID


def _print_sheet_summary(report, paths, choice, not_valid, titles):
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
    for d in report["errors"] + report["warnings"]:
        message = name_patches(d["message"], titles)
        print(printable(f"{d['severity']}: {d['code']}: {message}"))


def _preferences():
    """The maker's PopUp preferences (popupwb/preferences.py), read from FreeCAD's user.cfg; the
    built-in defaults when FreeCAD is not installed."""
    from popupwb import preferences

    with _stdout_to_stderr():
        try:
            _import_freecad()
        except InputError:
            pass
        try:
            return preferences.read()
        except preferences.PreferenceError as e:
            raise InputError(str(e))


def cmd_sheet(args):
    if args.paper is not None:  # before the slower steps: a typo should not wait for them
        try:
            _import_core().paper_size(args.paper)
        except ValueError as e:
            raise InputError(f"--paper {args.paper}: {_one_line(e)}")
    _check_sheet_options(sheet_options.from_cli(args))
    # The preferences are the defaults; each option given overrides its own.
    prefs = _preferences()
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
    validity = _check(popupcore, design, samples=181, clearance=0.0)
    not_valid = not_valid_of(validity)
    if not_valid is not None and not args.force:
        return _refuse_invalid(args, design, validity, not_valid)
    options = {**prefs.sheet_options, **sheet_options.from_cli(args)}
    if "printed_sides" not in options:  # the card's CuttingSheet says, as in the feature
        card_sides = _card_printed_sides(args, design)
        if card_sides:
            options["printed_sides"] = sheet_options.sides_text(card_sides)
    choice = None
    with _stdout_to_stderr():
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
            raise InputError(f"--out {args.out}: {_one_line(e)}")
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
        _print_sheet_summary(report, paths, choice, not_valid, design.patch_titles)
    return EXIT_INVALID if report["errors"] or not_valid is not None else EXIT_VALID


def _artwork(args, design, sheet_set):
    """The model's appearance on each laid-out patch, for a card designed from a model (its
    SourceModel) whose CuttingSheets print it (PrintArtwork, cutting_sheet.card_prints_artwork);
    None otherwise. The print layer of the PDF and SVG carries it, with registration marks."""
    if design.model is None:
        return None
    from popupwb.sheets.print_artwork import source_model_artwork

    try:
        return source_model_artwork(design.model, design.scaffold, sheet_set, args.design)
    except ValueError as e:
        raise InputError(_one_line(e))


VERIFY_ANGLES = 13  # fold angles verify_sheets samples by default
MAX_VERIFY_ANGLES = 361  # the core's limit


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
    return {**_card_printed_sides(args, design, flag_given=bool(given)), **given}


def _card_printed_sides(args, design, flag_given=False):
    """The printed sides the card's CuttingSheets give ({} for a .json design or a card without
    one); CuttingSheets that disagree need --printed-side."""
    features = design.printed_sides
    distinct = []
    for sides in features.values():
        if sides not in distinct:
            distinct.append(sides)
    if len(distinct) > 1 and not flag_given:
        described = "; ".join(
            f"{name}: {', '.join(f'{k}={v}' for k, v in sorted(sides.items())) or 'all front'}"
            for name, sides in features.items()
        )
        raise InputError(
            f"{args.design}: the card's CuttingSheets print different sides ({described}): say "
            "which to use, e.g. --printed-side P1=front"
        )
    base = distinct[0] if len(distinct) == 1 else {}
    for piece, side in base.items():
        if side not in ("front", "back"):
            names = ", ".join(features)
            raise InputError(
                f"{args.design}: {names}.PrintedSides: {piece}={side}, the side must be front or "
                "back"
            )
    return base


def _verify_failure(args, error):
    """A DesignError of verify_sheets as one line, led by the flag at fault when there is one."""
    findings = [d for d in getattr(error, "diagnostics", None) or [] if d["severity"] == "error"]
    flags = {"printed_sides": "--printed-side", "angles": "--angles", "kerf": "--kerf"}
    if findings and all(d["parameter"] in flags for d in findings):
        return "; ".join(f"{flags[d['parameter']]}: {d['message']}" for d in findings)
    text = "; ".join(d["message"] for d in findings) or _one_line(error)
    return f"{args.design}: cannot verify against this design: {text}"


def _finite_or_none(value):
    return value if isinstance(value, (int, float)) and math.isfinite(value) else None


def cmd_verify(args):
    if args.kerf is not None and (not math.isfinite(args.kerf) or args.kerf < 0):
        raise InputError(f"--kerf {args.kerf:g}: must be a finite length >= 0 mm")
    if not 2 <= args.angles <= MAX_VERIFY_ANGLES:
        raise InputError(f"--angles {args.angles}: must be 2 to {MAX_VERIFY_ANGLES}")
    from popupwb.sheets.dxf_reader import DxfReadError, read_dxf, sheets_path

    # The sheets first: reading them is quick, and a wrong path should not wait for FreeCAD.
    try:
        dxf = sheets_path(args.sheets)
        # The layers are those `popup sheet` writes: the names in the preferences.
        drawing = read_dxf(dxf, kerf=args.kerf, style=_preferences().style)
    except DxfReadError as e:
        raise InputError(str(e))
    popupcore, (design,) = load_designs(args.design, args.card, one=True)
    sides = _verify_sides(args, design)
    with _stdout_to_stderr():
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


def cmd_fit(args):
    from popupwb import cli_fit

    return cli_fit.run(args, sys.modules[__name__])


def cmd_animate(args):
    from popupwb import cli_animate

    return cli_animate.run(args, sys.modules[__name__])


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
    check.set_defaults(run=cmd_check)

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
    sheet.set_defaults(run=cmd_sheet)

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
    verify.set_defaults(run=cmd_verify)

    from popupwb import cli_fit
    from popupwb.fitting.fit_run import MAX_MECHANISMS

    cli_fit.add_parser(sub, MAX_MECHANISMS).set_defaults(run=cmd_fit)
    from popupwb import cli_animate

    cli_animate.add_parser(sub).set_defaults(run=cmd_animate)
    return parser


def main(argv=None):
    try:
        args = build_parser().parse_args(argv)
        return args.run(args)
    except InputError as e:
        print(f"popup: error: {printable(_one_line(e))}", file=sys.stderr)
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
