#!/usr/bin/python3
"""Draw PopUp's layers from the code's own includes and imports, and say what breaks them.

Usage: tools/layers.py [--png FILE] [--quiet] [--root DIR]   (`make layers` writes out/layers.png)

Every C++ file of core/ and bindings/ belongs to an area (core/src/<area>/, core/include/popup/
<area>/) and every module of Workbench/popupwb to a package; CORE_FLOORS and WORKBENCH_FLOORS
below give each its floor (docs/DESIGN.md, "Layers"). An include or import is an arrow; an arrow
from a lower floor to a higher one "runs back up". Files that include or import each other in a
loop form a circle (a header and its source are one node, as are a package's __init__.py and the
package). Imports inside functions count: a deferred import is still a dependency.

Prints every arrow that runs back up and every circle; exits 1 when there is any, 0 otherwise.
tests/python/test_layers.py runs it on every `make test`.
"""

import argparse
import ast
import collections
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Lower floors never include higher ones; areas on one floor do not include each other.
CORE_FLOORS = {
    "geometry": 1,
    "model": 2,
    "mechanisms": 3,
    "simulation": 3,
    "input": 4,
    "sheets": 5,
    "io": 6,
    "fitting": 7,
    "motion": 8,
    "bindings": 9,
}

# The workbench's packages and loose modules (by dotted name under popupwb), lowest first. A module
# not listed takes its package's floor; the longest listed prefix wins.
WORKBENCH_FLOORS = {
    "popupwb": 1,
    "popupwb.core": 1,
    "popupwb.freecad_version": 1,
    "popupwb.stateless_proxy": 1,
    "popupwb.readable_file": 1,
    "popupwb.view_provider_by_name": 1,
    "popupwb.document_precheck": 1,
    "popupwb.printable": 1,
    "popupwb.patch_titles": 1,
    "popupwb.mechanism_catalogue": 2,
    "popupwb.model": 2,
    "popupwb.progress": 2,
    "popupwb.option_fields": 2,
    "popupwb.validity.report_text": 2,
    "popupwb.profiles": 3,
    "popupwb.sheets": 3,
    "popupwb.features": 4,
    "popupwb.mechanism_registry": 5,
    "popupwb.validity": 6,
    # The cutting sheet is a feature over the sheets pipeline and the check (its module path is
    # stored in files, so it stays in features/): it and its make_* sit above both.
    "popupwb.features.cutting_sheet": 7,
    "popupwb.make": 8,
    "popupwb.fitting": 9,
    "popupwb.motion": 10,
    "popupwb.preferences": 11,
    "popupwb.cli": 12,
    "popupwb.gui": 13,
    "popupwb.taskpanels": 14,
    "popupwb.viewproviders": 15,
    "popupwb.commands": 16,
}


def set_root(root):
    """Reads another checkout (the tests plant a bad include in a copy)."""
    global ROOT
    ROOT = os.path.abspath(root)


# Arrows known to run back up, {(from, to): why it is still there}. The check fails on any arrow
# not listed, and on a listed arrow that is gone (then delete its line): the list only shrinks.
# Empty: every arrow runs down.
STILL_OPEN = {}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def core_area(path):
    """The area of a repository-relative C++ path, or None outside core/ and bindings/."""
    parts = path.split("/")
    if parts[0] == "bindings":
        return "bindings"
    if parts[:2] == ["core", "src"] and len(parts) > 3:
        return parts[2]
    if parts[:3] == ["core", "include", "popup"] and len(parts) > 4:
        return parts[3]
    return None


def cpp_node(path):
    """One node per concept: core/include/popup/a/x.hpp, core/src/a/x.hpp and x.cpp are a/x."""
    parts = path.split("/")
    stem = os.path.splitext(parts[-1])[0]
    area = core_area(path)
    if area == "bindings":
        return "bindings/" + stem
    inner = parts[3:-1] if parts[1] == "src" else parts[4:-1]
    return "/".join([area] + inner + [stem])


def cpp_files():
    for top in ("core", "bindings"):
        for folder, _, names in os.walk(os.path.join(ROOT, top)):
            for name in names:
                if name.endswith((".cpp", ".hpp")):
                    yield os.path.relpath(os.path.join(folder, name), ROOT)


def resolve_include(source, text):
    """Repository-relative path of an include written in `source`, or None (system, Eigen...)."""
    if text.startswith("popup/"):
        candidate = os.path.join("core/include", text)
    else:
        candidate = os.path.normpath(os.path.join(os.path.dirname(source), text))
    return candidate if os.path.exists(os.path.join(ROOT, candidate)) else None


def cpp_arrows():
    """[(from node, to node)] for every include between two different nodes."""
    arrows = []
    for path in cpp_files():
        with open(os.path.join(ROOT, path), encoding="utf-8") as f:
            text = f.read()
        for written in INCLUDE.findall(text):
            target = resolve_include(path, written)
            if target and core_area(target) and cpp_node(target) != cpp_node(path):
                arrows.append((cpp_node(path), cpp_node(target)))
    return arrows


def python_modules():
    """{dotted name: path} of every module under Workbench/popupwb."""
    base = os.path.join(ROOT, "Workbench")
    modules = {}
    for folder, _, names in os.walk(os.path.join(base, "popupwb")):
        for name in names:
            if not name.endswith(".py"):
                continue
            rel = os.path.relpath(os.path.join(folder, name), base)[: -len(".py")]
            dotted = rel.replace(os.sep, ".")
            if dotted.endswith(".__init__"):
                dotted = dotted[: -len(".__init__")]
            modules[dotted] = os.path.join(folder, name)
    return modules


def imported_names(path, dotted, is_package):
    """Dotted names a module imports (absolute, relative resolved), anywhere in its body."""
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read(), path)
    package = dotted if is_package else dotted.rpartition(".")[0]
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                anchor = package.split(".")
                anchor = anchor[: len(anchor) - (node.level - 1)]
                base = ".".join(anchor + ([node.module] if node.module else []))
            else:
                base = node.module or ""
            names.append(base)
            names += [base + "." + alias.name for alias in node.names]
    return names


def python_arrows():
    modules = python_modules()
    arrows = []
    for dotted, path in modules.items():
        is_package = path.endswith("__init__.py")
        for name in imported_names(path, dotted, is_package):
            # the longest module the name reaches ("popupwb.make.make_card" -> popupwb.make...)
            while name and name not in modules:
                name = name.rpartition(".")[0]
            if name and name != dotted and not dotted.startswith(name + "."):
                arrows.append((dotted, name))
    return arrows


def listed_prefix(node, floors, separator):
    """The longest prefix of `node` listed in `floors` (a top package only for itself), or None."""
    name = node
    while name:
        if name in floors and (name == node or separator in name or separator == "/"):
            return name
        name = name.rpartition(separator)[0]
    return None


def floor_of(node, floors, separator):
    """Floor of a node by its longest listed prefix."""
    prefix = listed_prefix(node, floors, separator)
    return floors[prefix] if prefix else None


def circles(arrows):
    """Strongly connected groups of more than one node (Tarjan, iterative)."""
    graph = collections.defaultdict(set)
    for a, b in arrows:
        graph[a].add(b)
    index, low, on_stack, stack, found = {}, {}, set(), [], []
    counter = [0]

    def visit(root):
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter[0]
                    counter[0] += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                group = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    group.append(member)
                    if member == node:
                        break
                if len(group) > 1:
                    found.append(sorted(group))

    for node in sorted(set(graph) | {b for _, b in arrows}):
        if node not in index:
            visit(node)
    return found


def group_of(node, floors, separator):
    """The drawn box of a node: its longest listed prefix."""
    return listed_prefix(node, floors, separator) or node


class Wing:
    """One side of the house (the core or the workbench): its arrows, floors and findings."""

    def __init__(self, title, arrows, floors, separator):
        self.title = title
        self.arrows = arrows
        self.floors = floors
        self.separator = separator
        self.unplaced = sorted(
            {n for arrow in arrows for n in arrow if floor_of(n, floors, separator) is None}
        )
        self.upward = sorted(
            {
                (a, b)
                for a, b in arrows
                if None not in (floor_of(a, floors, separator), floor_of(b, floors, separator))
                and floor_of(a, floors, separator) < floor_of(b, floors, separator)
            }
        )
        self.sideways = sorted(
            {
                (a, b)
                for a, b in arrows
                if group_of(a, floors, separator) != group_of(b, floors, separator)
                and floor_of(a, floors, separator) == floor_of(b, floors, separator)
            }
        )
        self.circles = circles(arrows)

    def box_arrows(self):
        """{(from box, to box): count} between the drawn boxes."""
        counts = collections.Counter()
        for a, b in self.arrows:
            ga, gb = group_of(a, self.floors, self.separator), group_of(
                b, self.floors, self.separator
            )
            if ga != gb:
                counts[(ga, gb)] += 1
        return counts

    def problems(self):
        lines = [
            f"{self.title}: arrow runs back up: {a} -> {b}"
            for a, b in self.upward
            if (a, b) not in STILL_OPEN
        ]
        lines += [
            f"{self.title}: arrow between areas of one floor: {a} -> {b}" for a, b in self.sideways
        ]
        lines += [f"{self.title}: circle: {' <-> '.join(c)}" for c in self.circles]
        lines += [f"{self.title}: no floor for {n} (add it to the table)" for n in self.unplaced]
        return lines


def draw(wings, png):
    """Each wing's boxes on their floors, arrows between boxes (red when they run back up)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(wings), figsize=(9 * len(wings), 10))
    for ax, wing in zip(axes, wings):
        boxes = sorted({group_of(n, wing.floors, wing.separator) for a in wing.arrows for n in a})
        by_floor = collections.defaultdict(list)
        for box in boxes:
            by_floor[floor_of(box, wing.floors, wing.separator) or 0].append(box)
        where = {}
        for floor, members in by_floor.items():
            for i, box in enumerate(sorted(members)):
                where[box] = ((i + 0.5) / len(members), floor)
        for (a, b), n in wing.box_arrows().items():
            (xa, ya), (xb, yb) = where[a], where[b]
            colour = "red" if ya <= yb else "0.55"
            ax.annotate(
                "",
                xy=(xb, yb),
                xytext=(xa, ya),
                arrowprops=dict(arrowstyle="->", color=colour, lw=0.6 + 0.15 * min(n, 10)),
            )
        for box, (x, y) in where.items():
            label = box.replace("popupwb.", "") if box != "popupwb" else "popupwb/__init__"
            ax.text(
                x,
                y,
                label,
                ha="center",
                va="center",
                fontsize=8,
                bbox=dict(boxstyle="round", fc="white", ec="0.3"),
            )
        top = max(y for _, y in where.values()) if where else 1
        ax.set_ylim(0.3, top + 0.7)
        ax.set_xlim(-0.05, 1.05)
        ax.set_yticks(range(1, top + 1))
        ax.set_ylabel("floor")
        ax.set_xticks([])
        still_open = sum(1 for arrow in wing.upward if arrow in STILL_OPEN)
        verdict = (
            "no arrow back up, no circle"
            if not wing.problems()
            else (
                f"{len(wing.upward)} back up, {len(wing.sideways)} sideways, {len(wing.circles)} circles"
            )
        )
        if still_open and not wing.problems():
            verdict += f" (but {still_open} listed as still open, in red)"
        ax.set_title(f"{wing.title}: {verdict}")
    fig.tight_layout()
    fig.savefig(png, dpi=90)


def stale_exceptions(house):
    """Listed arrows that no longer run back up: the list must lose them."""
    upward = {arrow for wing in house for arrow in wing.upward}
    return [
        f"fixed, remove from STILL_OPEN: {a} -> {b}" for a, b in STILL_OPEN if (a, b) not in upward
    ]


def wings():
    return [
        Wing("core + bindings (includes)", cpp_arrows(), CORE_FLOORS, "/"),
        Wing("Workbench (imports)", python_arrows(), WORKBENCH_FLOORS, "."),
    ]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--png", help="write the drawing here")
    parser.add_argument("--quiet", action="store_true", help="print only the problems")
    parser.add_argument("--root", default=ROOT, help="the checkout to read (default: this one)")
    args = parser.parse_args(argv)
    set_root(args.root)
    house = wings()
    problems = [line for wing in house for line in wing.problems()] + stale_exceptions(house)
    if not args.quiet:
        for wing in house:
            print(
                f"{wing.title}: {len(wing.arrows)} arrows, {len(wing.upward)} back up, "
                f"{len(wing.circles)} circles"
            )
        for (a, b), why in STILL_OPEN.items():
            print(f"still open: {a} -> {b}: {why}")
    for line in problems:
        print(line)
    if args.png:
        os.makedirs(os.path.dirname(os.path.abspath(args.png)), exist_ok=True)
        draw(house, args.png)
        print(f"drawing: {args.png}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
