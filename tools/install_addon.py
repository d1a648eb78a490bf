#!/usr/bin/python3
"""`make install` / `make install-dev`: PopUp into the user Mod folder of the FreeCAD installed here.

FreeCAD names that folder (FreeCAD.getUserAppDataDir()/Mod: FreeCAD's folder under ~/.local/share
on 0.20 and 1.0, its v1-1 subfolder on 1.1), so it is asked, never assumed.

- install: a copy laid out as FreeCAD's Addon Manager lays one out: <Mod>/PopUp/package.xml,
  LICENSE, Workbench/ (package.xml's <subdirectory>) and lib/popupcore.<ABI tag>.so, the core
  built for this machine's /usr/bin/python3 (popupwb/core.py names a core built for another
  Python); and ~/.local/bin/popup, the command line run from that copy.
- install-dev (--link): <Mod>/PopUp is a link to the source tree's Workbench/, and the core is
  found in <repo>/build/python: edits show at FreeCAD's next start.

Usage: install_addon.py --build build [--link]
"""

import argparse
import glob
import os
import shutil
import sys
import sysconfig

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.append(os.path.join(REPO, "Workbench"))
sys.path.append(os.path.join(REPO, "tools"))
from popupwb import freecad_version  # noqa: E402  (importable before FreeCAD)
from write_launcher import write_launcher_file  # noqa: E402

ADDON_NAME = "PopUp"
ADDON_FILES = ("package.xml", "LICENSE")


def built_core(build):
    """The core built for this Python (its ABI tag in the name), or exit with what to run."""
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    path = os.path.join(build, "python", "popupcore" + suffix)
    if not os.path.exists(path):
        others = glob.glob(os.path.join(build, "python", "popupcore*"))
        sys.exit(
            f"install: no {os.path.basename(path)} in {build}/python "
            f"(found: {', '.join(map(os.path.basename, others)) or 'none'}); run make build"
        )
    return path


def remove_previous(addon):
    """A previous install (a link from install-dev, or a copy holding our package.xml)."""
    if os.path.islink(addon):
        os.unlink(addon)
    elif os.path.exists(addon):
        if not os.path.exists(os.path.join(addon, "package.xml")):
            sys.exit(f"install: {addon} exists and is not a PopUp install; move it away first")
        shutil.rmtree(addon)


def copy_addon(build, mod_dir):
    addon = os.path.join(mod_dir, ADDON_NAME)
    staging = f"{addon}.installing"
    shutil.rmtree(staging, ignore_errors=True)
    shutil.copytree(
        os.path.join(REPO, "Workbench"),
        os.path.join(staging, "Workbench"),
        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"),
    )
    for name in ADDON_FILES:
        shutil.copy2(os.path.join(REPO, name), staging)
    os.makedirs(os.path.join(staging, "lib"))
    shutil.copy2(built_core(build), os.path.join(staging, "lib"))
    remove_previous(addon)
    os.replace(staging, addon)
    return addon


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--link", action="store_true", help="link the source tree (install-dev)")
    args = parser.parse_args()
    build = os.path.abspath(args.build)
    try:
        mod_dir = freecad_version.user_mod_dir_for(dict(os.environ))
    except RuntimeError as error:
        sys.exit(f"install: {error}; is freecad installed (make deps)?")
    os.makedirs(mod_dir, exist_ok=True)
    if args.link:
        addon = os.path.join(mod_dir, ADDON_NAME)
        if os.path.exists(addon) and not os.path.islink(addon):
            remove_previous(addon)
        freecad_version.link_into(mod_dir, os.path.join(REPO, "Workbench"), ADDON_NAME)
        print(f"install-dev: {addon} -> {REPO}/Workbench")
        return 0
    addon = copy_addon(build, mod_dir)
    launcher = write_launcher_file(
        os.path.join(os.path.expanduser("~"), ".local", "bin", "popup"),
        [
            os.path.join(addon, "lib"),
            os.path.join(addon, "Workbench"),
            freecad_version.freecad_lib_dir(),
        ],
    )
    print(f"install: {addon} (core {os.path.basename(built_core(build))}), command line {launcher}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
