"""The `popup` command line's parser (each command adds its own, one module per command) and its
entry point, main(): the exit status, and every error as one line on stderr."""

import os
import sys

from popupwb.cli import animate, check, fit, sheet, verify
from popupwb.cli.common import EXIT_BAD_INPUT, EXIT_INTERNAL, VERSION, InputError, Parser, one_line
from popupwb.printable import printable


def _version():
    try:
        import popupwb

        return getattr(popupwb, "__version__", VERSION)
    except ImportError:
        return VERSION


def build_parser():
    """The parser of every command; each parsed command's `run(args)` is args.run."""
    parser = Parser(
        prog="popup",
        description="PopUp: precise paper pop-up design (FreeCAD workbench) from the shell.",
        epilog="Exit status: 0 valid, 1 invalid, 2 unusable input, 3 internal error.",
    )
    parser.add_argument("--version", action="version", version=f"popup {_version()}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    sub.required = True
    for command in (check, sheet, verify, fit, animate):
        command.add_parser(sub)
    return parser


def main(argv=None):
    try:
        args = build_parser().parse_args(argv)
        return args.run(args)
    except InputError as e:
        print(f"popup: error: {printable(one_line(e))}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except BrokenPipeError:  # stdout closed early (popup check ... | head): not an error of ours
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141
    except KeyboardInterrupt:
        print("popup: interrupted", file=sys.stderr)
        return 130
    except Exception as e:  # never a traceback on the terminal
        print(f"popup: internal error: {type(e).__name__}: {one_line(e)}", file=sys.stderr)
        return EXIT_INTERNAL
