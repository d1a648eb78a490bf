"""`python -m popupwb.cli`: the `popup` command line (tools/write_launcher.py writes the launcher)."""

import os
import sys

from popupwb.cli.parser import main

status = main()
# Every file is written and closed by now; tearing down the interpreter (ezdxf, matplotlib,
# FreeCAD, the core) took a third of a second after each command, so the process ends here.
sys.stdout.flush()
sys.stderr.flush()
os._exit(status if isinstance(status, int) else 1)
