"""What differs between the FreeCAD releases PopUp runs on, in one place (README, "Platforms"):

- 0.20.2, Debian 12: Python 3.11, Qt 5 / PySide2, OCCT 7.6;
- 1.0.0, Debian 13: Python 3.13, Qt 5 / PySide2, OCCT 7.8;
- 1.1.3, Debian sid: Qt 6 / PySide6, and a user folder per minor version (…/FreeCAD/v1-1/Mod).

Importable without FreeCAD: the tests, the demo and `make install` ask it where FreeCAD's modules
and its user Mod folder are before FreeCAD is imported.
"""

import os
import subprocess
import uuid

# Debian's freecad-python3 package puts FreeCAD.so here on every release tested; the second is
# where upstream's own builds install it.
FREECAD_LIB_CANDIDATES = ("/usr/lib/freecad-python3/lib", "/usr/lib/freecad/lib")
# FreeCAD runs Debian's interpreter, whatever python3 comes first on PATH.
FREECAD_PYTHON = "/usr/bin/python3"


def freecad_lib_dir():
    """The folder holding FreeCAD.so (the first candidate when none does: errors name it)."""
    for directory in FREECAD_LIB_CANDIDATES:
        if os.path.exists(os.path.join(directory, "FreeCAD.so")):
            return directory
    return FREECAD_LIB_CANDIDATES[0]


def running_version():
    """(major, minor, patch) of the FreeCAD imported in this process."""
    import FreeCAD

    return tuple(int(part) for part in FreeCAD.Version()[:3])


def user_mod_dir():
    """The Mod folder FreeCAD (imported here) loads add-ons from; versioned from 1.1 on."""
    import FreeCAD

    return os.path.join(FreeCAD.getUserAppDataDir(), "Mod")


def user_mod_dir_for(env):
    """user_mod_dir() of a FreeCAD started with `env` (FREECAD_USER_HOME, HOME), asked in a
    child process: the folder must exist before FreeCAD is imported, and only FreeCAD knows it."""
    # FreeCAD 0.20 ignores a FREECAD_USER_HOME that does not exist yet (and falls back to
    # ~/.local/share/FreeCAD): make it first, as FreeCAD's own start would find it.
    if env.get("FREECAD_USER_HOME"):
        os.makedirs(env["FREECAD_USER_HOME"], exist_ok=True)
    probe = (
        f"import sys; sys.path.append({freecad_lib_dir()!r}); import FreeCAD; "
        "print(FreeCAD.getUserAppDataDir())"
    )
    done = subprocess.run(
        [FREECAD_PYTHON, "-c", probe], env=env, capture_output=True, text=True, timeout=120
    )
    lines = done.stdout.strip().splitlines()
    if done.returncode != 0 or not lines:
        raise RuntimeError(f"cannot ask FreeCAD for its user folder: {done.stderr.strip()[-300:]}")
    return os.path.join(lines[-1].strip(), "Mod")


def link_into(mod_dir, target, name="PopUp"):
    """<mod_dir>/<name> -> target, replaced atomically (tests create it side by side)."""
    os.makedirs(mod_dir, exist_ok=True)
    link = os.path.join(mod_dir, name)
    if os.path.islink(link) and os.path.realpath(link) == os.path.realpath(target):
        return link
    if os.path.exists(link) and not os.path.islink(link):
        raise RuntimeError(f"{link} exists and is not a link to {target}; remove it")
    temporary = f"{link}.{uuid.uuid4().hex}"
    os.symlink(target, temporary)
    os.replace(temporary, link)
    return link


def compound(shapes):
    """A Part compound of `shapes`. FreeCAD 1.0 (Debian 13) crashes in Part.makeCompound when it
    is imported as a Python module (the command line, the tests), not in freecadcmd or the GUI;
    the Part.Compound constructor builds the same compound on every version."""
    import Part

    return Part.Compound(list(shapes))
