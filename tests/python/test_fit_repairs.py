"""`popup fit` repairs a mechanism before it drops it (issue 25 item 4, docs/DESIGN.md "Repairs:
repair before dropping"): report.json's repairs say what a shrunk, trimmed or re-hosted mechanism
became, in the FreeCAD properties a maker sees, and the mechanisms delivered are exactly that.
Corpus models whose fitted designs need repairs (tools/make_corpus.py), with the seeds that
give them."""

import json
import os
import re

import pytest

import popupcore
from cli_runner import load_tool, popup

make_corpus = load_tool("make_corpus")

REPAIRED = ("shrunk", "trimmed", "re-hosted")
# Fits (model, seed) whose designs the validity repair changes: the engine's third box loses
# its end panels facing the second, the vehicle's wheel boxes shrink (the search of issue 25
# item 2 no longer needs repairs on the chair and the shed with seed 1).
REPAIRED_FITS = (("engine", "2"), ("vehicle", "3"))
# "Width 45.7 mm → 25.09 mm", "Front yes → no": property, before, after.
CHANGE = re.compile(r"(\w+) ([^,()→]+?) → ([^,()]+)")


@pytest.fixture(scope="module")
def reports(tmp_path_factory):
    folder = tmp_path_factory.mktemp("repairs")
    out = {}
    for name, seed in REPAIRED_FITS:
        model = make_corpus.write_corpus_model(
            name, str(folder / f"{name}.{make_corpus.CORPUS[name]['file']}")
        )
        proc = popup("fit", model, "--out", str(folder / name), "--seed", seed)
        assert proc.returncode == 0, proc.stdout + proc.stderr
        with open(os.path.join(folder / name, "report.json"), encoding="utf-8") as f:
            out[name] = json.load(f)
    return out


def value_of(text, unit):
    text = text.strip()
    if unit == "flag":
        return {"yes": 1.0, "no": 0.0}[text]
    number = float(text.split()[0].rstrip("°"))
    return number * 3.141592653589793 / 180 if unit == "angle" else number


def test_repaired_mechanisms_are_delivered_as_their_repairs_say(reports):
    checked = 0
    for name, report in reports.items():
        assert report["valid"] is True, name
        mechanisms = {m["name"]: m for m in report["mechanisms"]}
        dropped = {r["mechanism"] for r in report["repairs"] if r["action"] == "dropped"}
        for repair in report["repairs"]:
            if repair["action"] not in REPAIRED or ", because " not in repair["reason"]:
                continue  # the §4.2.2 refit's trims before the build say no "because"
            who = repair["mechanism"]
            assert who in mechanisms and who not in dropped, (name, repair)
            m = mechanisms[who]
            units = {
                f.property: (f.name, f.unit) for f in popupcore.catalogue_entry(m["type"]).fields
            }
            said = repair["reason"].split(", because ")[0]
            for prop, _, after in CHANGE.findall(said):
                field, unit = units[prop]
                assert m["parameters"][field] == pytest.approx(
                    value_of(after, unit), rel=1e-3, abs=1e-3
                ), (name, repair)
                checked += 1
            if repair["action"] == "re-hosted":
                onto = re.search(r"onto (the central fold|\S+)", said).group(1)
                assert m["host"] == onto.replace("the central fold", "central fold"), repair
    # The engine's box loses its facing end panels, the vehicle's boxes shrink (issue 25 item 4:
    # before, such a mechanism was dropped).
    assert checked >= 2


def test_a_dropped_mechanism_says_what_was_tried_and_warns(reports):
    for name, report in reports.items():
        warned = {
            d["message"].split(" ")[0]
            for d in report["diagnostics"]
            if d["code"] == "mechanism_dropped"
        }
        for repair in report["repairs"]:
            if repair["action"] == "dropped" and not repair["mechanism"].startswith("primitive"):
                assert repair["mechanism"] in warned, (name, repair)
                assert (
                    "did not help" in repair["reason"]
                    or "no repair" in repair["reason"]
                    or ("could not be" in repair["reason"] or "no other pair" in repair["reason"])
                ), (name, repair)
