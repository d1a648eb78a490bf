"""`python -m popupwb.cli`: the `popup` command line (tools/write_launcher.py writes the launcher)."""

import sys

from popupwb.cli.parser import main

sys.exit(main())
