"""Documents saved by one FreeCAD open and recompute identically on the others (README
"Platforms"): tests/data/golden/freecad-<version>/ holds a card of mechanism features, a fitted
design and an animated design as `make demo` wrote them with that FreeCAD, and figures.json, what
that FreeCAD read from them (tools/golden_documents.py).

Here the FreeCAD running the test opens each file, reads the same figures as saved and again
after every object is recomputed and every card checked, and both must equal the writer's:
shapes (area, bound box, face and edge counts, BRep validity), the PopUp parameters and the
verdicts. A file of a newer FreeCAD than this one is tried too; FreeCAD does not promise that an
older release reads it, so there a failure to open is a skip that says so.
"""

import glob
import json
import math
import os
import subprocess

import pytest

from conftest import SOURCE_DIR

GOLDEN = os.path.join(SOURCE_DIR, "tests", "data", "golden")
TOOL = os.path.join(SOURCE_DIR, "tools", "golden_documents.py")
RELATIVE = 1e-7  # OCCT 7.6 and 7.8 sum areas in another order; paper needs far less


def golden_files():
    for figures_path in sorted(glob.glob(os.path.join(GOLDEN, "freecad-*", "figures.json"))):
        with open(figures_path) as handle:
            figures = json.load(handle)
        for name in sorted(figures["documents"]):
            yield pytest.param(
                figures["freecad"],
                os.path.join(os.path.dirname(figures_path), name),
                figures["documents"][name],
                id=f"{figures['freecad']}-{name}",
            )


def version_tuple(text):
    return tuple(int(part) for part in text.split(".")[:3])


def differences(expected, got, path=""):
    """Every place where `got` differs from `expected`, floats within RELATIVE."""
    if isinstance(expected, dict) and isinstance(got, dict):
        for key in sorted(set(expected) | set(got)):
            yield from differences(expected.get(key), got.get(key), f"{path}/{key}")
    elif isinstance(expected, list) and isinstance(got, list) and len(expected) == len(got):
        for index, (a, b) in enumerate(zip(expected, got)):
            yield from differences(a, b, f"{path}[{index}]")
    elif isinstance(expected, float) and isinstance(got, (float, int)):
        if not math.isclose(expected, got, rel_tol=RELATIVE, abs_tol=1e-9):
            yield f"{path}: {expected} -> {got}"
    elif expected != got:
        yield f"{path}: {expected!r} -> {got!r}"


@pytest.mark.parametrize("writer, path, expected", list(golden_files()))
def test_a_saved_document_opens_and_recomputes_as_its_writer_read_it(
    freecad, writer, path, expected
):
    running = ".".join(freecad.Version()[:3])
    done = subprocess.run(
        ["/usr/bin/python3", TOOL, "figures", path], capture_output=True, text=True, timeout=300
    )
    newer = version_tuple(writer) > version_tuple(running)
    if done.returncode != 0 and newer:
        pytest.skip(f"FreeCAD {running} cannot read a file of {writer}: {done.stderr[-300:]}")
    assert done.returncode == 0, done.stderr[-2000:]
    got = json.loads(done.stdout.strip().splitlines()[-1])
    assert got["errors"] == {}
    assert sorted(got["saved"]) == sorted(expected), "PopUp objects (and their proxies) restored"
    assert list(differences(expected, got["saved"])) == [], "as saved"
    assert list(differences(expected, got["recomputed"])) == [], "recomputed and checked again"
    card = expected["Card"]["properties"]
    assert card["Validity"] == "Valid" and got["recomputed"]["Card"]["properties"]["Validity"] == (
        "Valid"
    )


def test_every_kind_of_design_is_golden_for_this_machines_freecad(freecad):
    """Debian 12's 0.20.2 wrote the first set; each platform adds its own (README)."""
    written = {os.path.basename(os.path.dirname(p)) for p in glob.glob(f"{GOLDEN}/*/figures.json")}
    assert "freecad-0.20.2" in written
    with open(os.path.join(GOLDEN, "freecad-0.20.2", "figures.json")) as handle:
        documents = json.load(handle)["documents"]
    assert sorted(documents) == ["animated.FCStd", "card.FCStd", "fitted.FCStd"]
    proxies = {o["proxy"].rsplit(".", 1)[1] for d in documents.values() for o in d.values()}
    assert {"PopUpCard", "BoxFold", "TentFold", "RotationArm", "FloatingLayer"} <= proxies
