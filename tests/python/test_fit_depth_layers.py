"""Depth layers (thesis §5.1.3) through the bindings, the FreeCAD document and `popup fit`: a
"stepped-front truck" made here (a cab box with a bonnet standing 25 proud of its front, a load
bed 25 deep behind it and a beacon 12 high on its roof) fitted with one primitive, the cab, so the
bonnet, the bed and the beacon can only come from the cab's depth layers. Known answers come from
the construction: the bonnet's front is a 40 x 20 rectangle with two 6 x 6 chamfers (764)."""

import json
import os

import numpy as np
import pytest

from test_cli import popup

BONNET_AREA = 40 * 20 - 2 * (6 * 6 / 2)


def _box(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = [[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
    # Corner index 4x + 2y + z; faces counter-clockwise seen from outside.
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return v, [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]


def _extruded_along_x(polygon_yz, x0, x1):
    """A convex polygon (counter-clockwise in (y, z)) extruded from x0 to x1, closed."""
    n = len(polygon_yz)
    v = [[x0, y, z] for y, z in polygon_yz] + [[x1, y, z] for y, z in polygon_yz]
    t = [(0, k + 1, k) for k in range(1, n - 1)]  # the x0 cap faces -x
    t += [(n, n + k, n + k + 1) for k in range(1, n - 1)]  # the x1 cap faces +x
    for k in range(n):
        j = (k + 1) % n
        t += [(k, j, n + j), (k, n + j, n + k)]
    return v, t


def stepped_truck_parts():
    chamfer = 6
    bonnet = [
        (10, 0),
        (50, 0),
        (50, 20 - chamfer),
        (50 - chamfer, 20),
        (10 + chamfer, 20),
        (10, 20 - chamfer),
    ]
    return [
        _box((-20, 0, 0), (20, 60, 40)),  # cab
        _extruded_along_x(bonnet, 20, 45),  # bonnet, 25 proud of the cab's front
        _box((-45, 5, 0), (-20, 55, 30)),  # load bed, 25 behind
        _box((-12, 20, 40), (12, 40, 52)),  # beacon, 12 over the roof
    ]


def _joined():
    vertices, triangles = [], []
    for v, t in stepped_truck_parts():
        base = len(vertices)
        vertices += v
        triangles += [(a + base, b + base, c + base) for a, b, c in t]
    return np.array(vertices, dtype=float), np.array(triangles, dtype=np.int32)


def _outward_normals_agree():
    """Each part's triangles wind outward: the signed volume of each part is positive."""
    for v, t in stepped_truck_parts():
        p = np.asarray(v, dtype=float)
        volume = sum(np.dot(p[a], np.cross(p[b], p[c])) for a, b, c in t) / 6
        assert volume > 0


@pytest.fixture(scope="module")
def core():
    from popupwb.core import popupcore

    return popupcore


def _options(core, depth_layers=True):
    o = core.FitOptions()
    o.up, o.facing = (0, 0, 1), (1, 0, 0)
    o.max_mechanisms = 1
    o.depth_layers = depth_layers
    return o


@pytest.fixture(scope="module")
def fitted(core):
    _outward_normals_agree()
    v, t = _joined()
    model = core.ModelMesh(v, t, "stepped truck")
    return model, core.fit_design(model, _options(core))


def test_the_bonnet_bed_and_beacon_are_nested_on_the_cab(fitted):
    _, r = fitted
    assert r.valid
    assert [(m.type, m.host) for m in r.mechanisms] == [
        ("box_fold", "central fold"),
        ("step_fold", "B1.side_ground"),
        ("step_fold", "B1.side_backdrop"),
        ("box_fold", "B1.top"),
    ]
    s = np.linalg.norm(np.asarray(r.model_to_card)[:3, 0])
    bonnet, bed, beacon = r.mechanisms[1:]
    assert bonnet.parameters["run_ground"] == pytest.approx(25 * s, abs=0.02 * 90 * s)
    assert bed.parameters["run_backdrop"] == pytest.approx(25 * s, abs=0.02 * 90 * s)
    assert beacon.parameters["height"] == pytest.approx(12 * s, abs=0.02 * 52 * s)
    riser = [p for p in r.profiles if (p.mechanism, p.part) == (bonnet.name, "riser")]
    assert len(riser) == 1
    assert riser[0].area == pytest.approx(BONNET_AREA * s * s, rel=0.02)
    layers = {(x.face, x.mechanism): x for x in r.depth_layers if x.kept}
    assert set(layers) == {("front", bonnet.name), ("back", bed.name), ("top", beacon.name)}
    assert all(x.mean_after_mm < x.mean_before_mm for x in layers.values())
    assert [x.action for x in r.repairs].count("layer kept") == 3


def test_without_depth_layers_only_the_cab_is_left(fitted, core):
    model, _ = fitted
    r = core.fit_design(model, _options(core, depth_layers=False))
    assert r.valid and [m.name for m in r.mechanisms] == ["B1"] and not r.depth_layers


def test_the_freecad_document_builds_every_nested_mechanism(fitted, freecad):
    from popupwb import validity
    from popupwb.fitting.design_from_fit import build_design

    model, r = fitted
    doc = freecad.newDocument("SteppedTruck")
    try:
        design = build_design(doc, r, model)
        assert [(m.Label, m.HostPair) for m in design.mechanisms] == [
            ("B1", "central fold"),
            ("S1", "B1.side_ground"),
            ("S2", "B1.side_backdrop"),
            ("B2", "B1.top"),
        ]
        for feature in design.mechanisms:
            feature.touch()
        doc.recompute()
        for feature in design.mechanisms:
            assert feature.isValid(), feature.Label
            assert "Invalid" not in feature.State, feature.Label
            assert not feature.Shape.isNull(), feature.Label
        # The bonnet's riser is cut to the chamfered front: its paper has the bonnet's area.
        s = np.linalg.norm(np.asarray(r.model_to_card)[:3, 0])
        bonnet = design.mechanisms[1]
        riser_area = max(f.Area for f in bonnet.Shape.Faces if abs(f.normalAt(0, 0).x) > 0.999)
        assert riser_area == pytest.approx(BONNET_AREA * s * s, rel=0.02)
        report = validity.run_check(design.card)
        assert report["valid"], report["diagnostics"]
    finally:
        freecad.closeDocument(doc.Name)


def _write_stl(path):
    v, t = _joined()
    with open(path, "w") as f:
        f.write("solid stepped_truck\n")
        for a, b, c in t:
            n = np.cross(v[b] - v[a], v[c] - v[a])
            n = n / np.linalg.norm(n)
            f.write(f"facet normal {n[0]:.6f} {n[1]:.6f} {n[2]:.6f}\n outer loop\n")
            for p in (v[a], v[b], v[c]):
                f.write(f"  vertex {p[0]:.6f} {p[1]:.6f} {p[2]:.6f}\n")
            f.write(" endloop\nendfacet\n")
        f.write("endsolid stepped_truck\n")


def _mean(report):
    return report["metrics"]["hausdorff_mm"]["model_to_popup"]["mean"]


def test_popup_fit_reports_the_kept_layers(tmp_path):
    model = tmp_path / "stepped_truck.stl"
    _write_stl(model)
    out = tmp_path / "out"
    args = ("--up", "0,0,1", "--facing", "1,0,0", "--max-mechanisms", "1")
    proc = popup("fit", str(model), "--out", str(out), *args, home=str(tmp_path / "home"))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    assert report["valid"] is True and report["options"]["depth_layers"] is True
    kept = [x for x in report["depth_layers"] if x["kept"]]
    assert sorted(x["face"] for x in kept) == ["back", "front", "top"]
    front = next(x for x in kept if x["face"] == "front")
    s = np.linalg.norm(np.asarray(report["model_to_card"])[:3, 0])
    assert front["depth_mm"] == pytest.approx(25 * s, abs=0.02 * 90 * s)
    assert report["number_of_mechanisms"] == 4
    # --no-depth-layers: the cab alone, farther from the model.
    flat = tmp_path / "flat"
    proc = popup(
        "fit",
        str(model),
        "--out",
        str(flat),
        *args,
        "--no-depth-layers",
        home=str(tmp_path / "home"),
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr
    with open(os.path.join(flat, "report.json")) as f:
        without = json.load(f)
    assert without["number_of_mechanisms"] == 1 and without["depth_layers"] == []
    assert _mean(report) < _mean(without)
