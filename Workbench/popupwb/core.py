"""Imports the compiled `popupcore` module, finding the build tree when it is not on sys.path.

Search order: sys.path as it is; $POPUP_BUILD_DIR/python; <addon>/lib, where `make install` puts
the module (<addon> holds package.xml and Workbench/); <repo>/build/python, where <repo> is two
levels above the real location of this package (the Mod folder is usually a symlink to
<repo>/Workbench, hence realpath). The module's file name carries its Python ABI tag
(popupcore.cpython-311-…so): one built for another Python is named, not silently skipped.
"""

import glob
import os
import re
import sys
import sysconfig

import popupwb


def _candidate_dirs():
    build_dir = os.environ.get("POPUP_BUILD_DIR")
    if build_dir:
        yield os.path.join(build_dir, "python")
    yield os.path.join(os.path.dirname(os.path.dirname(popupwb.PACKAGE_DIR)), "lib")
    yield os.path.join(popupwb.REPO_DIR, "build", "python")


def _python_of(module_file):
    """ "3.11" from popupcore.cpython-311-x86_64-linux-gnu.so, or the file name."""
    tag = re.search(r"cpython-(\d)(\d+)", os.path.basename(module_file))
    return f"{tag.group(1)}.{tag.group(2)}" if tag else os.path.basename(module_file)


def _other_python_error(directory, builds):
    running = f"{sys.version_info.major}.{sys.version_info.minor}"
    built = ", ".join(sorted({_python_of(path) for path in builds}))
    return ImportError(
        f"PopUp's core was built for Python {built}; this FreeCAD runs {running}: run make install "
        f"with it (in the PopUp source tree, on this machine; module in {directory})"
    )


def _import_popupcore():
    try:
        import popupcore

        return popupcore
    except ImportError:
        pass
    tried, other_python = [], None
    for directory in _candidate_dirs():
        tried.append(directory)
        builds = glob.glob(os.path.join(directory, "popupcore*"))
        if not builds:
            continue
        suffix = sysconfig.get_config_var("EXT_SUFFIX") or ".so"
        if not any(path.endswith(suffix) or path.endswith("popupcore.so") for path in builds):
            other_python = other_python or _other_python_error(directory, builds)
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
    if other_python is not None:
        raise other_python
    raise ImportError(
        "PopUp: the compiled module 'popupcore' was not found (looked on sys.path and in "
        + ", ".join(tried)
        + "); run `make build` in the PopUp source tree or set POPUP_BUILD_DIR"
    )


popupcore = _import_popupcore()
