#!/usr/bin/python3
"""Check that everything the build used under /usr, /lib or /opt comes from a Debian package.

A fresh machine has only what the Makefile installs: a header, library or Python module placed
there by hand makes the build pass here and fail there. The files the build used are read from
the compiler's dependency files (*.o.d), `ldd` of every ELF file built, and the Python modules
(and their shared libraries) that popupcore and the workbench's command line import. A file
counts as packaged when dpkg lists it, or its real path, among some installed package's files.

Usage: check_unpackaged_deps.py BUILD_DIR [--pythonpath DIRS]
Exit 1 when unpackaged files are found and CI=true, or when nothing could be read; otherwise
exit 0, printing a warning that names the files.
"""

import argparse
import glob
import json
import os
import subprocess
import sys

SYSTEM_PREFIXES = ("/usr/", "/lib/", "/lib64/", "/opt/")
DPKG_INFO = "/var/lib/dpkg/info"

# Imports the project's Python side needs at run time (FreeCAD's own modules come with freecad).
PYTHON_PROBE = """
import json, sys
import popupcore, popupwb.cli, popupwb.sheets.export
print(json.dumps(sorted({getattr(m, "__file__", None) or "" for m in list(sys.modules.values())})))
"""


def merged_usr_spellings(path):
    """/lib/x and /usr/lib/x name one file on merged-/usr Debian; dpkg records either."""
    spellings = {path}
    for short in ("/lib/", "/lib64/", "/bin/", "/sbin/"):
        if path.startswith(short):
            spellings.add("/usr" + path)
        if path.startswith("/usr" + short):
            spellings.add(path[len("/usr") :])
    return spellings


def packaged_files():
    owned = set()
    for listing in glob.glob(os.path.join(DPKG_INFO, "*.list")):
        with open(listing, errors="replace") as f:
            owned.update(line.rstrip("\n") for line in f)
    return owned


def is_packaged(path, owned):
    for candidate in (path, os.path.realpath(path)):
        if merged_usr_spellings(candidate) & owned:
            return True
    return False


def files_under(build):
    """Every file of the build folder. make test-matrix's chroots (<build>/matrix) are other
    systems' files, with /proc and the source tree mounted in them: never walked, nor any mount."""
    for folder, subfolders, files in os.walk(build):
        subfolders[:] = [
            name
            for name in subfolders
            if not (folder == build and name == "matrix")
            and not os.path.ismount(os.path.join(folder, name))
        ]
        for name in files:
            yield os.path.join(folder, name)


def depfile_paths(build):
    """System files named by the compiler's dependency files."""
    depfiles = [p for p in files_under(os.path.normpath(build)) if p.endswith(".o.d")]
    used = set()
    for depfile in depfiles:
        with open(depfile, errors="replace") as f:
            for token in f.read().replace("\\\n", " ").split():
                if token.startswith(SYSTEM_PREFIXES):
                    used.add(os.path.normpath(token))
    return depfiles, used


def is_elf(path):
    try:
        with open(path, "rb") as f:
            return f.read(4) == b"\x7fELF"
    except OSError:
        return False


def shared_libraries(binary):
    """(resolved libraries, names ldd could not find) of one ELF file."""
    out = subprocess.run(["ldd", binary], capture_output=True, text=True).stdout
    found, unresolved = set(), set()
    for line in out.splitlines():
        if "=>" not in line:
            continue
        name, target = (part.strip() for part in line.split("=>", 1))
        if target.startswith("not found"):
            unresolved.add(name)
        elif target.startswith("/"):
            found.add(os.path.normpath(target.split()[0]))
    return found, unresolved


def built_elf_files(build):
    return [
        p
        for p in files_under(os.path.normpath(build))
        if os.path.isfile(p) and not os.path.islink(p) and is_elf(p)
    ]


def python_module_files(pythonpath):
    """System files of the modules the project's Python side imports; None if it cannot."""
    env = dict(os.environ, PYTHONPATH=pythonpath)
    probe = subprocess.run(
        ["/usr/bin/python3", "-c", PYTHON_PROBE], capture_output=True, text=True, env=env
    )
    if probe.returncode != 0:
        return None, probe.stderr.strip().splitlines()[-1:]
    files = {os.path.normpath(f) for f in json.loads(probe.stdout) if f.startswith(SYSTEM_PREFIXES)}
    return files, []


def collect(build, pythonpath):
    depfiles, used = depfile_paths(build)
    elves = built_elf_files(build)
    problems = []
    if not depfiles:
        problems.append(f"no compiler dependency files (*.o.d) under {build}: build first")
    if not elves:
        problems.append(f"no built ELF files under {build}: build first")
    unresolved = {}
    modules, errors = python_module_files(pythonpath)
    if modules is None:
        problems.append("the project's Python modules do not import: " + " ".join(errors))
        modules = set()
    used |= modules
    for binary in elves + [m for m in modules if m.endswith(".so")]:
        libs, missing = shared_libraries(binary)
        used |= {lib for lib in libs if lib.startswith(SYSTEM_PREFIXES)}
        for name in missing:
            unresolved.setdefault(name, binary)
    problems += [f"ldd finds no {name} (needed by {who})" for name, who in unresolved.items()]
    return len(depfiles), len(elves), used, problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build", help="the CMake build folder")
    parser.add_argument(
        "--pythonpath", default="", help="PYTHONPATH under which popupcore and popupwb import"
    )
    args = parser.parse_args()
    ci = os.environ.get("CI", "").lower() == "true"
    n_depfiles, n_elves, used, problems = collect(args.build, args.pythonpath)
    owned = packaged_files()
    unpackaged = sorted(p for p in used if os.path.exists(p) and not is_packaged(p, owned))
    for problem in problems:
        print(f"unpackaged-deps: cannot check: {problem}")
    if problems:
        return 1
    if unpackaged:
        level = "error" if ci else "warning"
        print(
            f"unpackaged-deps {level}: {len(unpackaged)} file(s) used by the build belong to no "
            "Debian package, so a fresh machine will not have them; install them from the "
            "Makefile's package list or stop using them:"
        )
        for path in unpackaged:
            print(f"  {path}")
        if not ci:
            print("(a warning outside CI; with CI=true this fails)")
        return 1 if ci else 0
    print(
        f"unpackaged-deps: all {len(used)} system files used by the build ({n_depfiles} "
        f"dependency files, {n_elves} built ELF files, Python imports) come from Debian packages"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
