"""Writes the bad design files of tests/data/bad/ (issue 10's reproducers, bad_designs.sh): each is
one of the project's own test designs with one thing broken. expectations.json says what
`popup check` / `popup sheet` must answer for each; tests/python/test_bad_corpus.py runs them.

    /usr/bin/python3 tests/data/bad/make_bad_designs.py          # rewrite every file
    /usr/bin/python3 tests/data/bad/make_bad_designs.py --check  # fail if a file differs

The files are committed; run this only to add a case (a new entry in DESIGNS) or after changing
one. Designs too large to commit (the 100,000-vertex outline) are in GENERATED: the test writes
them into a temporary folder with generated(name).
"""

import copy
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.dirname(HERE)


def base(name):
    """A test design of tests/data (tent_fold.json, mechanisms/box.json, ...) as a dict."""
    with open(os.path.join(DATA, name), encoding="utf-8") as f:
        return json.load(f)


def changed(name, change):
    design = copy.deepcopy(base(name))
    change(design)
    return design


def _set(path, value):
    """A change that sets design[path...] = value."""

    def change(design):
        target = design
        for key in path[:-1]:
            target = target[key]
        target[path[-1]] = value

    return change


def _loose_patch(design):  # a square joined to nothing (bad_designs.sh C2)
    design["patches"].append(
        {"id": 50, "outline": [[100, 170, 0], [110, 170, 0], [110, 180, 0], [100, 180, 0]]}
    )


def _named_with_escapes(design):  # bad_designs.sh U4: the name lands in a finding
    design["hinges"].pop(1)
    design["patches"][2]["name"] = "x\x1b[31m\nVALID: fake"


def _hole(*holes):
    def change(design):
        design["patches"][0]["holes"] = [list(h) for h in holes]

    return change


# name -> (base design, change); every name becomes tests/data/bad/<name>.json
DESIGNS = {
    # C1: no hinge at all (crashed the solver with SIGSEGV)
    "no_hinges": ("tent_fold.json", _set(["hinges"], [])),
    "no_hinges_box": ("mechanisms/box.json", _set(["hinges"], [])),
    # C2: one patch attached to nothing (SIGSEGV in check and sheet)
    "detached_patch": ("mechanisms/box.json", _loose_patch),
    # C3: a ring closed by repeating its first point (accepted, the repeat dropped) and a vertex
    # repeated elsewhere (SIGSEGV in mesh_patch)
    "ring_closed_by_repeat": (
        "tent_fold.json",
        lambda d: d["patches"][0]["outline"].append([0, 0, 0]),
    ),
    "repeated_vertex": (
        "tent_fold.json",
        lambda d: d["patches"][0]["outline"].insert(1, [0, 0, 0]),
    ),
    # W1: an outline crossing itself (checked VALID, sheets cut something else)
    "self_crossing_outline": (
        "mechanisms/box.json",
        _set(
            ["patches", 0, "outline"],
            [
                [0, 0, 0], [140, 0, 0], [140, 200, 0], [0, 200, 0],
                [0, 170, 0], [200, 175, 0], [200, 185, 0], [0, 165, 0],
            ],
        ),
    ),  # fmt: skip
    "hole_outside_outline": (
        "mechanisms/box.json",
        _hole([[500, 500, 0], [500, 600, 0], [600, 600, 0]]),
    ),
    "hole_crossing_outline": (
        "mechanisms/box.json",
        _hole([[120, 180, 0], [160, 180, 0], [160, 160, 0], [120, 160, 0]]),
    ),
    # W3: ids beyond 32 bits (wrapped onto patch 0)
    "hinge_patch_beyond_32_bits": (
        "tent_fold.json",
        _set(["hinges", 1, "patches"], [4294967296, 2]),
    ),
    "ground_beyond_32_bits": ("tent_fold.json", _set(["ground"], 4294967296)),
    # U2: one coordinate 1e308 (blamed on the other patches)
    "far_coordinate": ("tent_fold.json", _set(["patches", 0, "outline", 1, 0], 1e308)),
    # U4: a patch name with a terminal escape and a newline (printed raw: a fake VALID line)
    "name_with_escapes": ("tent_fold.json", _named_with_escapes),
    # Holes (issue 10, "Holes"), in the tent's ground clear of its fold: overlapping holes, a hole
    # inside a hole, a counter-clockwise hole (the outline runs counter-clockwise seen from +z,
    # holes the other way)
    "overlapping_holes": (
        "tent_fold.json",
        _hole(
            [[90, 130, 0], [90, 150, 0], [110, 150, 0], [110, 130, 0]],
            [[100, 140, 0], [100, 160, 0], [120, 160, 0], [120, 140, 0]],
        ),
    ),
    "hole_inside_hole": (
        "tent_fold.json",
        _hole(
            [[80, 120, 0], [80, 180, 0], [130, 180, 0], [130, 120, 0]],
            [[90, 130, 0], [90, 150, 0], [110, 150, 0], [110, 130, 0]],
        ),
    ),
    "counter_clockwise_hole": (
        "tent_fold.json",
        _hole([[90, 130, 0], [110, 130, 0], [110, 150, 0], [90, 150, 0]]),
    ),
    # The baseline of the three above: one clockwise hole is a valid design
    "one_hole": (
        "tent_fold.json",
        _hole([[90, 130, 0], [90, 150, 0], [110, 150, 0], [110, 130, 0]]),
    ),
    # Base patches that do not match design_angle_deg (flat bases, a design angle of 90°)
    "bases_off_design_angle": ("tent_fold.json", _set(["design_angle_deg"], 90.0)),
}

# Files that are not JSON designs at all: name -> bytes
RAW = {
    "not_an_object": lambda: b"[]\n",
    # U1: UTF-16 (with its byte-order mark) and invalid UTF-8 (an empty message)
    "utf16": lambda: b"\xff\xfe" + json.dumps(base("tent_fold.json")).encode("utf-16-le"),
    "invalid_utf8": lambda: json.dumps(base("tent_fold.json"))
    .replace("ground", "gr\udcffound", 1)
    .encode("utf-8", "surrogateescape"),
}


def long_outline(vertices):
    """H1: tent_fold.json whose ground outline has `vertices` vertices (check_validity was
    quadratic: 100,000 took over 60 s)."""
    design = base("tent_fold.json")
    corners = [(0.0, 0.0), (140.0, 0.0), (140.0, 200.0), (0.0, 200.0)]
    per_side = vertices // 4
    outline = []
    for k in range(4):
        (a, b), (c, e) = corners[k], corners[(k + 1) % 4]
        outline += [
            [a + (c - a) * i / per_side, b + (e - b) * i / per_side, 0.0] for i in range(per_side)
        ]
    design["patches"][0]["outline"] = outline
    return design


GENERATED = {"long_outline_100k": lambda: long_outline(100000)}


def contents(name):
    """The bytes of tests/data/bad/<name>.json."""
    if name in RAW:
        return RAW[name]()
    if name in GENERATED:
        return json.dumps(GENERATED[name]()).encode()
    design_base, change = DESIGNS[name]
    return (json.dumps(changed(design_base, change), indent=1, sort_keys=True) + "\n").encode()


def generated(name, folder):
    """Writes the GENERATED design `name` into `folder`; returns its path."""
    path = os.path.join(folder, f"{name}.json")
    with open(path, "wb") as f:
        f.write(contents(name))
    return path


def main(argv):
    check = "--check" in argv
    stale = []
    for name in [*DESIGNS, *RAW]:
        path = os.path.join(HERE, f"{name}.json")
        data = contents(name)
        if check:
            with open(path, "rb") as f:
                if f.read() != data:
                    stale.append(path)
            continue
        with open(path, "wb") as f:
            f.write(data)
    if stale:
        print("differ from make_bad_designs.py:", *stale, sep="\n  ", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
