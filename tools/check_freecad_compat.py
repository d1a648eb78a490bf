#!/usr/bin/python3
"""The fast static check for what breaks PopUp on FreeCAD 1.x, run by .ci/run beside Debian 12's
suite (the full check on 1.0 and 1.1 is `make test-matrix`, README "Platforms").

It reads every tracked Python file (and the Makefile) for:
- a direct PySide2 or PySide6 import: FreeCAD 1.1 is Qt 6, 0.20 and 1.0 are Qt 5; only FreeCAD's
  own `PySide` shim names the right one;
- QRegExp (gone in Qt 6) and `exec_` (renamed `exec`; PySide6 drops the old name);
- Part.makeCompound, which crashes FreeCAD 1.0 imported as a Python module;
- a hard-coded FreeCAD user folder: 1.1 keeps Mod in a versioned folder (…/FreeCAD/v1-1/Mod), so
  only FreeCAD.getUserAppDataDir() knows it;
- a document object or view provider proxy without `dumps`/`loads`: FreeCAD 1.0 and later save
  and restore proxies through them (stateless_proxy.StatelessProxy has both).

Usage: check_freecad_compat.py [FILE ...]   (default: git ls-files)
Exit 0 when clean, 1 with one line per finding: file:line: what, and what to use instead.
"""

import ast
import os
import re
import subprocess
import sys

LINE_RULES = [
    (
        re.compile(r"^\s*(from|import)\s+PySide[26]\b"),
        "imports PySide2/PySide6 directly: use FreeCAD's shim, `from PySide import QtCore, QtGui`",
    ),
    (re.compile(r"\bQRegExp\b"), "QRegExp is gone in Qt 6 (FreeCAD 1.1): use QRegularExpression"),
    (re.compile(r"\bexec_\s*\("), "exec_() is gone in PySide6 (FreeCAD 1.1): call exec()"),
    (
        re.compile(r"\bPart\.makeCompound\("),
        "Part.makeCompound crashes FreeCAD 1.0 imported as a module: use freecad_version.compound",
    ),
    (
        re.compile(
            r"\.local/share/FreeCAD|\.FreeCAD/Mod|[\"']FreeCAD/Mod|join\([^)]*[\"']Mod[\"']"
        ),
        "hard-coded FreeCAD user folder (1.1 versions it): use FreeCAD.getUserAppDataDir()",
    ),
]
# Methods only a FreeCAD proxy has: a class defining one is a document object or view provider.
PROXY_METHODS = {"execute", "attach", "updateData", "getIcon", "onDocumentRestored"}
STATE_METHODS = {"dumps", "loads"}


def tracked_files(root):
    listed = subprocess.run(
        ["git", "ls-files", "*.py", "Makefile"],
        cwd=root,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    return [os.path.join(root, path) for path in listed]


def line_findings(path, text):
    for number, line in enumerate(text.splitlines(), 1):
        if line.lstrip().startswith("#") or path.endswith("check_freecad_compat.py"):
            continue
        for pattern, message in LINE_RULES:
            if pattern.search(line):
                yield f"{path}:{number}: {message}"


def classes_of(trees):
    """name -> (path, ClassDef) over every parsed file (names are unique enough in one tree)."""
    found = {}
    for path, tree in trees:
        for node in ast.walk(tree):
            if isinstance(node, ast.ClassDef):
                found.setdefault(node.name, (path, node))
    return found


def methods(node):
    return {item.name for item in node.body if isinstance(item, ast.FunctionDef)}


def has_state_protocol(name, classes, seen=()):
    if name not in classes or name in seen:
        return False
    _, node = classes[name]
    if STATE_METHODS <= methods(node):
        return True
    bases = [b.id if isinstance(b, ast.Name) else getattr(b, "attr", "") for b in node.bases]
    return any(has_state_protocol(base, classes, seen + (name,)) for base in bases)


def proxy_findings(trees):
    classes = classes_of(trees)
    for name, (path, node) in sorted(classes.items()):
        if methods(node) & PROXY_METHODS and not has_state_protocol(name, classes):
            yield (
                f"{path}:{node.lineno}: proxy class {name} has no dumps/loads (FreeCAD 1.0+ "
                "saves proxies through them): derive it from stateless_proxy.StatelessProxy"
            )


def main(argv):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    paths = argv or tracked_files(root)
    findings, trees = [], []
    for path in paths:
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
        findings += line_findings(os.path.relpath(path, root), text)
        if path.endswith(".py"):
            trees.append((os.path.relpath(path, root), ast.parse(text, filename=path)))
    findings += proxy_findings([(p, t) for p, t in trees if p.startswith("Workbench")] or trees)
    for finding in findings:
        print(finding)
    print(f"check_freecad_compat: {len(paths)} files, {len(findings)} findings", file=sys.stderr)
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
