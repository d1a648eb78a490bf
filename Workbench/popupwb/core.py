"""Imports the compiled `popupcore` module, finding the build tree when it is not on sys.path.

Search order: sys.path as it is; $POPUP_BUILD_DIR/python; <repo>/build/python, where <repo> is two
levels above the real location of this package (the Mod folder is usually a symlink to
<repo>/Workbench, hence realpath).
"""

import glob
import os
import sys

import popupwb


def _candidate_dirs():
    build_dir = os.environ.get("POPUP_BUILD_DIR")
    if build_dir:
        yield os.path.join(build_dir, "python")
    yield os.path.join(popupwb.REPO_DIR, "build", "python")


def _import_popupcore():
    try:
        import popupcore

        return popupcore
    except ImportError:
        pass
    tried = []
    for directory in _candidate_dirs():
        tried.append(directory)
        if not glob.glob(os.path.join(directory, "popupcore*")):
            continue
        sys.path.append(directory)
        try:
            import popupcore

            return popupcore
        except ImportError as error:
            # The module is there but does not load (wrong Python, missing library): say so.
            sys.path.remove(directory)
            raise ImportError(
                f"PopUp: {directory} holds popupcore but it does not import ({error}); "
                "run `make build` again with /usr/bin/python3"
            ) from error
    raise ImportError(
        "PopUp: the compiled module 'popupcore' was not found (looked on sys.path and in "
        + ", ".join(tried)
        + "); run `make build` in the PopUp source tree or set POPUP_BUILD_DIR"
    )


popupcore = _import_popupcore()
