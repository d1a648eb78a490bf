"""The steps `popup fit` (fit.py) and `popup animate` (animate.py) share: their common
flags (--out, --seed, --paper), progress lines on stderr, the checks of the flags and the input
before any work, the design document built and checked, the report on a run that found no design,
the cutting sheets written through `popup sheet` itself, and the exit code: 0 a valid design with
usable sheets, 1 no valid design, 2 unusable input (InputError).
"""

import contextlib
import os
import sys

from popupwb import option_fields
from popupwb.cli import sheet
from popupwb.cli.common import (
    EXIT_INVALID,
    EXIT_VALID,
    InputError,
    import_freecad,
    one_line,
    read_preferences,
    stdout_to_stderr,
)
from popupwb.readable_file import unreadable

DESIGN_FILE = "design.FCStd"
REPORT_FILE = "report.json"
SHEETS_DIR = "sheets"
DEFAULT_PAPER = "A4"


# --- flags ----------------------------------------------------------------------------------


def add_out_flag(parser):
    parser.add_argument("--out", required=True, metavar="DIR", help="folder for the files")


def add_seed_flag(parser, field):
    """--seed S from the options' seed field (its doc, range and default are the core's)."""
    option_fields.add_flag(parser, "--seed", field, "S")


def add_paper_flag(parser):
    parser.add_argument(
        "--paper",
        help="paper of the sheets, A4, A3, Letter, Tabloid or WxH mm; the card is the largest "
        f"that fits on it (default: the PopUp preference, else {DEFAULT_PAPER})",
    )


class Say:
    """Progress lines on stderr, prefixed with the command: `popup fit: reading ...`."""

    def __init__(self, command):
        self.prefix = f"popup {command}: "

    def __call__(self, text):
        print(self.prefix + text, file=sys.stderr, flush=True)


# --- checks before any work -----------------------------------------------------------------


def flags_given(args, names):
    """{option name: "--flag VALUE"} of the flags given among `names` {option name: argument
    name}, for option_fields.raise_if_bad to lead the core's messages with."""
    given = {}
    for option, name in names.items():
        value = getattr(args, name)
        if value is not None:
            given[option] = f"--{name.replace('_', '-')} {option_fields.value_text(value)}"
    return given


def directions(args, direction, flags):
    """The X,Y,Z text of each flag (an attribute of `args`, None when not given) as a direction,
    in the order of `flags`; InputError naming the flag when one is not a direction."""
    try:
        return [
            None if getattr(args, name) is None else direction(getattr(args, name), f"--{name}")
            for name in flags
        ]
    except ValueError as e:
        raise InputError(str(e))


def paper_and_card_size(args, card_size_for_paper):
    """The paper (--paper, else the preference, else DEFAULT_PAPER) and the largest card on it."""
    paper = args.paper or read_preferences().sheet_paper or DEFAULT_PAPER
    try:
        return paper, card_size_for_paper(paper)
    except ValueError as e:
        raise InputError(f"--paper {paper}: {one_line(e)}")


@contextlib.contextmanager
def core_range_checks():
    """The core's own range checks of the flags' values, as InputError."""
    try:
        yield
    except ValueError as e:
        raise InputError(one_line(e))


def require_core(popupcore, needed):
    """A module built without what the command calls: stopped before anything else."""
    for name in needed:
        if not hasattr(popupcore, name):
            raise RuntimeError(f"popupcore.{name} is missing: rebuild (make build)")


def check_out_and_input(args, input_path):
    """An --out that is a file, an input that cannot be read: stopped before any work."""
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        raise InputError(f"--out {args.out}: is a file, not a folder")
    why = unreadable(input_path)
    if why:
        raise InputError(why)


def named(path, error):
    """The error's one line, led by `path` unless it names the file already."""
    text = one_line(error)
    return text if path in text or os.path.basename(path) in text else f"{path}: {text}"


# --- the design -----------------------------------------------------------------------------


def raise_unless_no_design(error, input_path):
    """The core's DesignError `no_design_found` is an outcome (exit 1, with a report); any other
    DesignError is the input's fault: InputError naming the file."""
    codes = [d.get("code") for d in getattr(error, "diagnostics", None) or []]
    if "no_design_found" not in codes:
        raise InputError(named(input_path, error))


def report_no_design(args, input_path, error, report, files, say):
    """The run's end when the core found no design: the report with the core's diagnostics;
    exit 1."""
    say(f"no valid design: {one_line(error)}")
    report["diagnostics"] = list(getattr(error, "diagnostics", None) or [])
    write_report(args.out, report, files, say)
    print(f"no valid design found for {input_path}; see {files['report']}")
    return EXIT_INVALID


@contextlib.contextmanager
def design_document(name):
    """A new FreeCAD document (FreeCAD's chatter sent to stderr), closed at the end."""
    with stdout_to_stderr():
        FreeCAD = import_freecad()
        doc = FreeCAD.newDocument(name)
        try:
            yield doc
        finally:
            FreeCAD.closeDocument(doc.Name)


def build_and_check(stages, build):
    """build() (a design with a .card) timed as `document`, its card checked as `check`;
    returns (design, the check's dict)."""
    from popupwb.validity.check import run_check

    with stages.stage("document", "building the card's features"):
        design = build()
    with stages.stage("check", "checking the card's validity"):
        checked = run_check(design.card)
    return design, checked


def save_design(doc, out, files):
    files["design"] = os.path.join(out, DESIGN_FILE)
    doc.saveAs(os.path.abspath(files["design"]))
    return files["design"]


# --- sheets, report, exit code --------------------------------------------------------------

# What the sheet writers import (half a second): third-party only, so the thread that imports
# them meanwhile never waits on a module of PopUp the main thread is importing.
SHEET_LIBRARIES = (
    "ezdxf",
    "reportlab.platypus",
    "reportlab.pdfgen.canvas",
    "svgwrite",
    "PIL.Image",
)


def import_sheet_libraries_meanwhile():
    """Imports SHEET_LIBRARIES on a thread, to be called before a long core call that releases
    the GIL (the fit, the motion design): the sheets stage then finds them loaded."""
    import importlib
    import threading

    def load():
        for name in SHEET_LIBRARIES:
            try:
                importlib.import_module(name)
            except ImportError:
                pass  # the sheets stage says so, where it needs the library

    threading.Thread(target=load, name="sheet-libraries").start()


def write_sheets(args, paper, report, files, stages, say):
    """`popup sheet DIR/design.FCStd --out DIR/sheets --paper PAPER`, through cmd_sheet itself.
    Sheets that cannot be laid out (a piece larger than the paper) are the sheets' error, not
    the run's: said, kept in the report as `sheets_error`, exit 1, the report still written."""
    sheets = os.path.join(args.out, SHEETS_DIR)
    with stages.stage("sheets", f"laying out the cutting sheets on {paper}"):
        sheet_args = sheet.parse_args([files["design"], "--out", sheets, "--paper", paper])
        try:
            status = sheet_args.run(sheet_args)
        except InputError as e:
            report["sheets_error"] = one_line(e)
            say(f"error: no cutting sheets: {report['sheets_error']}")
            return EXIT_INVALID
    files["sheets"] = sheets
    return status


def sheets_of_valid_design(args, paper, report, valid, files, stages, say):
    """The sheets' exit code when the design is `valid`; else 1, with the report's diagnostics
    said on stderr."""
    if valid:
        return write_sheets(args, paper, report, files, stages, say)
    for d in report.get("diagnostics") or []:
        say(f"{d.get('severity', 'error')}: {d.get('code')}: {d.get('message')}")
    say("no valid design found: no sheets written")
    return EXIT_INVALID


def write_report(out, report, files, say):
    from popupwb.fitting.fit_report import write_report as write_json

    files["report"] = os.path.join(out, REPORT_FILE)
    report["files"] = dict(files)
    write_json(report, files["report"])
    say(f"wrote {files['report']}")


def finish(args, report, status, files, stages, say, print_summary):
    """The report completed (timings, sheets_ok) and written, the summary printed on stdout;
    returns the exit code: the sheets' for a valid design, else 1."""
    from popupwb.fitting.fit_report import timings

    report["timings_s"] = timings(stages.timings, stages.total())
    report["sheets_ok"] = bool(report["valid"] and status == EXIT_VALID)
    write_report(args.out, report, files, say)
    print_summary(report, files)
    if report["valid"] and status != EXIT_VALID and "sheets" in files:
        print(
            "but its cutting sheets have errors (listed above; "
            f"{os.path.join(files['sheets'], 'report.json')})"
        )
    elif report["valid"] and report.get("sheets_error"):
        print(f"but no cutting sheets could be laid out: {report['sheets_error']}")
    return status if report["valid"] else EXIT_INVALID


def print_written(files, roles):
    for role in roles:
        if role in files:
            print(f"wrote {files[role]}")


def g(value):
    """A report number for people: 4 significant digits, n/a when missing."""
    return "n/a" if value is None else f"{value:.4g}"
