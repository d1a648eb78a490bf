"""The `popup` command line: check a pop-up design without opening FreeCAD's GUI.

    popup check design.json [--json] [--samples N] [--clearance MM]
    popup check card.FCStd [--card NAME]    # every PopUpCard and Scaffold, or the one named
    popup sheet card.FCStd --out DIR [--card NAME] [--paper A4] [--kerf 0.1] [--force] [--json]
    popup verify card.FCStd DIR|sheets.dxf [--card NAME] [--printed-side P1=back] [--kerf MM]
    popup fit model.stl --out DIR [--max-mechanisms N] [--seed S] [--paper A4] [--up X,Y,Z]
              [--facing X,Y,Z] [--detail D]    # fit.py: the card designed from a 3D model
    popup animate walk.bvh --out DIR [--seed S] [--iterations N] [--first-frame F]
              [--last-frame L] [--view X,Y,Z] [--up X,Y,Z] [--scale MM] [--paper A4]
                                               # animate.py: motion from an animation
    popup --version

Exit status: 0 the design is valid (check; for a document every card checked), its sheets are
usable (sheet) or the cutting file makes the design (verify), 1 it is not or does not (the report
says why; sheet refuses a design the validity check rejects unless --force, and still writes every
file when only the layout reports errors; verify prints each finding), 2 the
input could not be used (missing file, bad JSON, bad design, no scaffold, unknown --card, bad
option, a piece larger than the paper), 3 an internal error. Errors are one line on stderr naming
the file and what is wrong.

One module per command (check.py, sheet.py, verify.py, fit.py, animate.py); common.py is what they
all share, designs.py the designs they read, design_steps.py the steps fit and animate share, and
parser.py the parser and main().
"""

from popupwb.cli.common import EXIT_BAD_INPUT, EXIT_INTERNAL, EXIT_INVALID, EXIT_VALID, InputError
from popupwb.cli.parser import build_parser, main

__all__ = [
    "EXIT_BAD_INPUT",
    "EXIT_INTERNAL",
    "EXIT_INVALID",
    "EXIT_VALID",
    "InputError",
    "build_parser",
    "main",
]
