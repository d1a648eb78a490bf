"""Headless: what PopUp_SetProfile calls (profiles.set_profile_sketch) and what PopUp_ExportSheets
writes for a card designed from a model (CuttingSheet.PrintArtwork).

Known answers: the outlines' areas by the shoelace formula on the coordinates drawn here; the
registration marks where docs/DESIGN.md (Artwork) puts them, read back from the written SVG.
The GUI side (the picker, the command, one undo step) is tests/gui/run_gui_profile_picker.py.
"""

import xml.etree.ElementTree as ElementTree

import pytest

from cli_runner import load_tool

SVG = "{http://www.w3.org/2000/svg}"
LABEL = "{http://www.inkscape.org/namespaces/inkscape}label"
# A tree on a 60 x 20 riser: trunk 8 x 6 mm on the ground fold, crown a trapezoid 40 mm wide at
# its foot and 4 mm at the top, which runs along the riser's top fold (a profile must keep paper
# along every fold).
TREE = [(-4, 0), (4, 0), (4, 6), (20, 6), (2, 20), (-2, 20), (-20, 6), (-4, 6)]
TREE_AREA = 8 * 6 + (40 + 4) / 2 * 14


def shoelace(loop):
    return 0.5 * abs(
        sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(loop, loop[1:] + loop[:1]))
    )


def line_sketch(doc, name, points, closed=True):
    import FreeCAD
    import Part

    sketch = doc.addObject("Sketcher::SketchObject", name)
    pairs = list(zip(points, points[1:] + (points[:1] if closed else [])))
    for a, b in pairs:
        sketch.addGeometry(
            Part.LineSegment(FreeCAD.Vector(a[0], a[1], 0), FreeCAD.Vector(b[0], b[1], 0))
        )
    return sketch


@pytest.fixture
def step_card(doc):
    from popupwb import make

    card = make.make_card(doc, width=200, depth=140, fold_angle=90.0, name="Card")
    step = make.make_step_fold(
        card, name="Step", offset=70, width=60, run_ground=30, run_backdrop=20
    )
    doc.recompute()
    return card, step


def riser_area(step):
    # The riser is the step's first face (its patches in generator order), posed at 90°.
    return step.Shape.Faces[0].Area


def test_an_open_sketch_is_refused_in_one_line_naming_it(doc, step_card):
    from popupwb import profiles

    _, step = step_card
    open_tree = line_sketch(doc, "OpenTree", TREE, closed=False)
    doc.recompute()
    with pytest.raises(ValueError) as refused:
        profiles.set_profile_sketch(step, open_tree, "riser")
    message = str(refused.value)
    assert "OpenTree" in message and "open" in message and "\n" not in message
    assert step.ProfileSketch is None and step.ProfilePart == "" and step.Profiles == ""


def test_an_unknown_part_or_mode_is_refused_with_the_choices(doc, step_card):
    from popupwb import profiles

    _, step = step_card
    tree = line_sketch(doc, "Tree", TREE)
    doc.recompute()
    with pytest.raises(
        ValueError, match=r"ProfilePart = 'roof', must be one of its parts \(riser, tread\)"
    ):
        profiles.set_profile_sketch(step, tree, "roof")
    with pytest.raises(ValueError, match="ProfileMode = 'Stretch', must be one of Clip, Scale"):
        profiles.set_profile_sketch(step, tree, "riser", "Stretch")
    assert step.ProfileSketch is None


def test_the_sketch_outlines_the_riser_and_scale_follows_a_height_edit(doc, step_card):
    from popupwb import profiles

    _, step = step_card
    assert riser_area(step) == pytest.approx(60 * 20, rel=1e-9)
    tree = line_sketch(doc, "Tree", TREE)
    doc.recompute()
    assert shoelace(TREE) == pytest.approx(TREE_AREA, rel=1e-12)
    profiles.set_profile_sketch(step, tree, "riser", "Scale")
    doc.recompute()
    assert step.getStatusString() == "Valid"
    assert profiles.stored(step)["riser"]["reference"] == (60.0, 20.0)  # recorded when set
    assert riser_area(step) == pytest.approx(TREE_AREA, rel=1e-6)
    # Scale: twice the height, the outline twice as high (v scaled 40/20, u unchanged).
    step.RunBackdrop = 40
    doc.recompute()
    assert riser_area(step) == pytest.approx(2 * TREE_AREA, rel=1e-6)
    # Clip: the outline stays in mm; a wider riser leaves it as drawn.
    step.RunBackdrop = 20
    profiles.set_profile_sketch(step, tree, "riser", "Clip")
    step.Width = 80
    doc.recompute()
    assert step.getStatusString() == "Valid"
    assert riser_area(step) == pytest.approx(TREE_AREA, rel=1e-6)
    # Scale again: from the size recorded when Clip was set (60 x 20), u scaled 80/60.
    step.ProfileMode = "Scale"
    doc.recompute()
    assert riser_area(step) == pytest.approx(TREE_AREA * 80 / 60, rel=1e-6)
    profiles.clear_profile_sketch(step)
    doc.recompute()
    assert riser_area(step) == pytest.approx(80 * 20, rel=1e-9)  # the plain riser again


# --- artwork on the exported sheets -----------------------------------------------------------


def _house(tmp_path):
    return load_tool("make_models").write_model("house", str(tmp_path / "house.stl"))


@pytest.fixture
def fitted_sheet(doc, tmp_path):
    """A card fitted to a house STL (as PopUp_FromModel on the file does) and its CuttingSheet."""
    from popupwb import make
    from popupwb.core import popupcore
    from popupwb.fitting import fit_run
    from popupwb.fitting.design_from_fit import build_design

    path = _house(tmp_path)
    model, _ = fit_run.clean_model(popupcore.load_model(path))
    options = fit_run.fit_options(6, 2, up=(0, 0, 1), facing=(0, -1, 0))
    result = fit_run.fit(model, options)
    design = build_design(doc, result, model, source_file=path)
    sheet = make.make_cutting_sheet(design.card, paper="A3", name="Sheets", make_pages=False)
    doc.recompute()
    assert sheet.getStatusString() == "Valid", sheet.getStatusString()
    return design.card, sheet


def print_layer(svg_path):
    root = ElementTree.parse(svg_path).getroot()
    width, height = (float(v) for v in root.get("viewBox").split()[2:])
    layers = [g for g in root.iter(SVG + "g") if g.get(LABEL) == "PRINT"]
    return layers, width, height


def test_export_prints_the_fitted_model_with_registration_marks(fitted_sheet, tmp_path):
    from popupwb.features.cutting_sheet import export_cutting_sheet

    _, sheet = fitted_sheet
    assert sheet.PrintArtwork is True
    paths = export_cutting_sheet(sheet, str(tmp_path / "with"))
    margin = sheet.Margin.Value
    for svg in paths["svg"]:
        layers, width, height = print_layer(svg)
        assert len(layers) == 1
        marks = {
            (float(r.get("x")), height - float(r.get("y")) - 5.0)
            for r in layers[0].findall(SVG + "rect")
        }
        inset = (margin - 5.0) / 2
        assert marks == {
            (inset, inset),
            (inset, height - inset - 5.0),
            (width - inset - 5.0, height - inset - 5.0),
        }
    images = [i for svg in paths["svg"] for i in print_layer(svg)[0][0].iter(SVG + "image")]
    assert images and all("data:image/png;base64," in str(i.attrib) for i in images)


def test_print_artwork_off_and_a_hand_made_card_print_nothing(fitted_sheet, doc, tmp_path):
    from popupwb import make
    from popupwb.features.cutting_sheet import export_cutting_sheet

    _, sheet = fitted_sheet
    sheet.PrintArtwork = False
    doc.recompute()
    for svg in export_cutting_sheet(sheet, str(tmp_path / "off"))["svg"]:
        assert print_layer(svg)[0] == []
    card = make.make_card(doc, width=150, depth=100, name="HandMade")
    make.make_tent_fold(card, name="Tent")
    hand = make.make_cutting_sheet(card, paper="A4", name="HandSheets", make_pages=False)
    doc.recompute()
    assert hand.PrintArtwork is True
    for svg in export_cutting_sheet(hand, str(tmp_path / "hand"))["svg"]:
        assert print_layer(svg)[0] == []


def test_a_margin_too_narrow_for_the_marks_is_named(fitted_sheet, doc, tmp_path):
    from popupwb.features.cutting_sheet import export_cutting_sheet

    _, sheet = fitted_sheet
    sheet.Margin = 4.0  # a mark is 5 mm, with 0.5 mm clear on each side
    doc.recompute()
    with pytest.raises(ValueError) as refused:
        export_cutting_sheet(sheet, str(tmp_path / "narrow"))
    message = str(refused.value)
    assert message.startswith("Sheets: Margin: ") and "at least 6 mm" in message
    assert "PrintArtwork" in message
    sheet.PrintArtwork = False  # a plain cut file needs no marks
    export_cutting_sheet(sheet, str(tmp_path / "plain"))


def test_an_out_of_date_layout_is_not_printed(fitted_sheet, doc, tmp_path):
    from popupwb.features.cutting_sheet import export_cutting_sheet

    card, sheet = fitted_sheet
    mechanism = next(o for o in doc.Objects if getattr(o, "Host", None) is card)
    mechanism.Width = mechanism.Width.Value - 1.0  # not recomputed: the layout is stale
    with pytest.raises(ValueError, match="Sheets: the card or the sheet's settings changed"):
        export_cutting_sheet(sheet, str(tmp_path / "stale"))
