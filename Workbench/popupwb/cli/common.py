"""What every `popup` command shares: the exit codes, the one-line InputError and the parser that
raises it, output kept apart from FreeCAD's and the core's chatter, the imports of popupcore and
FreeCAD, the maker's preferences and the validity report as text.
"""

import argparse
import contextlib
import os
import re
import sys

from popupwb import freecad_version

EXIT_VALID = 0
EXIT_INVALID = 1
EXIT_BAD_INPUT = 2
EXIT_INTERNAL = 3

FREECAD_LIB = freecad_version.freecad_lib_dir()
VERSION = "0.1.0"


class InputError(Exception):
    """Input the command cannot use; the message is the whole explanation (one line)."""


# What argparse takes for a negative number, hence an option's value rather than an option: its own
# pattern (-1, -.5) misses -1e-3, -inf and -nan, so `--kerf -inf` got "expected one argument"
# instead of the option's range check.
_NEGATIVE_NUMBER = re.compile(
    r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$", re.IGNORECASE
)


class Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # A private attribute of argparse (the same from Python 3.2 to 3.13); test_cli checks
        # that negative values reach every float option.
        self._negative_number_matcher = _NEGATIVE_NUMBER

    # argparse prints the usage and exits on a bad option; we want one line and our exit code.
    def error(self, message):
        raise InputError(f"{message} (see '{self.prog} --help')")


def one_line(text):
    return "; ".join(line.strip() for line in str(text).splitlines() if line.strip())


@contextlib.contextmanager
def stdout_to_stderr():
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


def import_core():
    try:
        import popupcore
    except ImportError:
        try:
            import popupwb.core  # noqa: F401  (puts build/python on sys.path when run from source)
            import popupcore
        except ImportError as e:  # popupwb.core's message says where it looked and what to do
            raise InputError(str(e))
    return popupcore


def import_freecad():
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
            # this file is Workbench/popupwb/cli/common.py
            workbench_dir = os.path.dirname(os.path.dirname(os.path.dirname(resolve(__file__))))
            if workbench_dir not in mod_dirs:
                mod_dirs.append(workbench_dir)
    return FreeCAD


def format_report(report_dict):
    """The validity report as text (popupwb.validity.report_text), FreeCAD imported first."""
    # popupwb.validity is FreeCAD-side (it also checks Scaffold objects): it imports FreeCAD.
    with stdout_to_stderr():
        import_freecad()
        try:
            from popupwb.validity import report_text
        except ImportError as e:
            raise InputError(f"cannot import popupwb.validity ({e}); use --json")
    return report_text.format_report(report_dict)


def read_preferences():
    """The maker's PopUp preferences (popupwb/preferences.py), read from FreeCAD's user.cfg; the
    built-in defaults when FreeCAD is not installed."""
    from popupwb import preferences

    with stdout_to_stderr():
        try:
            import_freecad()
        except InputError:
            pass
        try:
            return preferences.read()
        except preferences.PreferenceError as e:
            raise InputError(str(e))
