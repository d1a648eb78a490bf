"""Why a path given on the command line cannot be read, in one line (or None when it can)."""

import os


def unreadable(path):
    """'<path>: no such file' and the like, or None for a readable regular file."""
    if not os.path.exists(path):
        return f"{path}: no such file"
    if not os.path.isfile(path):
        return f"{path}: not a file"
    if not os.access(path, os.R_OK):
        return f"{path}: not readable (permission denied)"
    return None
