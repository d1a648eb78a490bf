"""CuttingSheet in headless FreeCAD: an A4 card with a tent and a box fold laid out on paper, its
exact flat faces against the core's patches, the TechDraw pages (one per sheet, folds as cosmetic
lines, glue areas and labels in one symbol view, a template of the paper's size with legend and
title block), errors that name the option and leave the document recomputable,
no second layout when only FoldAngle changes, the export, and save and reopen in a fresh
process."""

import json
import os
import xml.etree.ElementTree as ElementTree

import ezdxf
import pytest

from freecad_documents import in_error, recompute_ok

# An "A4" card opens to 210 x 297 mm: it fits A3 paper, not A4 within its 10 mm margins.
TENT = dict(offset=20.0, width=50.0, foot=20.0, foot_backdrop=20.0, slope=30.0)
BOX = dict(offset=110.0, width=60.0, depth_ground=30.0, depth_backdrop=30.0, height=30.0)
# The card's pages are one piece, the tent another; the box's strip, C, front and back panels
# four more.
PIECES = 6
# Printable 212 x 300 mm: the card's pages fill the first sheet, the rest go on a second.
TWO_SHEETS = dict(paper_width=232.0, paper_height=320.0)
SHEET_GAP = 20.0  # mm between sheets, as in sheets.dxf


def build_card(doc, popup, **sheet_options):
    """The test card with a CuttingSheet on A3 (or `sheet_options`), recomputed: dict of objects."""
    make = popup.make
    card = make.make_card(doc, preset="A4")
    tent = make.make_tent_fold(card, name="Tent", **TENT)
    box = make.make_box_fold(card, name="Box", **BOX)
    sheet = make.make_cutting_sheet(card, **({"paper": "A3"} | sheet_options))
    objects = {"Card": card, "Tent": tent, "Box": box, "Sheet": sheet}
    recompute_ok(doc, *objects.values())
    return objects


@pytest.fixture
def card(doc, popup):
    return build_card(doc, popup)


def sheet_set_of(sheet):
    return json.loads(sheet.SheetSetJson)


SVG = "{http://www.w3.org/2000/svg}"


def line_format(edge):
    """(style, RGB) of a cosmetic edge: its Format is a tuple on FreeCAD 0.20, a dict on 1.x."""
    form = edge.Format
    if isinstance(form, dict):
        return form["style"], tuple(form["color"][:3])
    style, _, colour, _ = form
    return style, tuple(colour[:3])


def page_parts(page):
    """The page's part view and its symbol view (glue areas and labels)."""
    (view,) = [v for v in page.Views if v.TypeId == "TechDraw::DrawViewPart"]
    (marks,) = [v for v in page.Views if v.TypeId == "TechDraw::DrawViewSymbol"]
    return view, marks


def layer_of(marks, name):
    """The <g> of layer `name` in the symbol view's SVG."""
    root = ElementTree.fromstring(marks.Symbol)
    return next((g for g in root.iter(SVG + "g") if g.get("id") == name), None)


def symbol_texts(marks):
    return [t.text for t in layer_of(marks, "LABEL").iter(SVG + "text")]


def pieces_on(sheet_set, index):
    return [p for p in sheet_set["pieces"] if p["sheet"] == index]


def page_objects_count(doc):
    """Pages, templates, views, annotations and outlines in `doc`."""
    return sum(
        1 for o in doc.Objects if o.TypeId.startswith("TechDraw::") or o.TypeId == "Part::Feature"
    )


def test_flat_faces_are_the_patches_exactly(doc, popup, card):
    sheet = card["Sheet"]
    scaffold = popup.card_scaffold.for_card(card["Card"]).scaffold
    sheet_set = sheet_set_of(sheet)
    assert sheet.SheetCount >= 1 and sheet.SheetCount == len(sheet_set["sheets"])
    assert sheet.ShelfSheetCount == sheet_set["shelf_sheet_count"]
    assert sheet.PieceCount == PIECES == len(popup.core.cut_pieces(scaffold))
    assert sheet.TabCount == sum(len(p["tabs"]) for p in sheet_set["pieces"]) > 0
    assert sheet.CutLength.Value == pytest.approx(sheet_set["cut_length"])
    assert sheet.StackHeight.Value == pytest.approx(sheet_set["stack_height"])
    assert sheet.RoundTripOk is True
    assert sheet.RoundTripError.Value < 1e-6 * scaffold.size()
    assert all(not line.startswith("error") for line in sheet.Diagnostics)
    assert len(popup.pages.pages_of(sheet)) == sheet.SheetCount

    shape = sheet.Shape
    assert shape.isValid()
    assert len(shape.Faces) == len(scaffold.patches)
    patch_area = sum(p.area() for p in scaffold.patches)
    assert shape.Area == pytest.approx(patch_area, rel=1e-6)
    flat = [patch for piece in sheet_set["pieces"] for patch in piece["patches"]]
    assert sorted(p["id"] for p in flat) == list(range(len(scaffold.patches)))
    assert shape.BoundBox.ZLength == 0.0
    # One sub-compound per sheet: its patches' faces, then its folds and tabs as wires.
    sheets = shape.childShapes()
    assert len(sheets) == sheet.SheetCount
    for index, sub in enumerate(sheets):
        pieces = pieces_on(sheet_set, index)
        assert sub.isValid()
        faces = [patch for piece in pieces for patch in piece["patches"]]
        folds = sum(len(piece["folds"]) for piece in pieces)
        tabs = sum(len(piece["tabs"]) for piece in pieces)
        assert len(sub.childShapes()) == len(faces) + folds + tabs
        for face, patch in zip(sub.Faces, faces):
            assert face.Area == pytest.approx(scaffold.patches[patch["id"]].area(), rel=1e-9)


def test_each_sheet_is_offset_like_the_dxf(doc, popup):
    sheet = build_card(doc, popup, **TWO_SHEETS)["Sheet"]
    assert sheet.SheetCount == 2 and sheet.Paper == "Custom"
    sheet_set = sheet_set_of(sheet)
    assert sheet_set["paper"]["width"] == 232.0
    pitch = 232.0 + SHEET_GAP
    for index, sub in enumerate(sheet.Shape.childShapes()):
        box = sub.BoundBox
        assert index * pitch <= box.XMin and box.XMax <= index * pitch + 232.0
        assert 0.0 <= box.YMin and box.YMax <= 320.0


def test_pages_draw_every_sheet_at_full_size(doc, popup):
    sheet = build_card(doc, popup, **TWO_SHEETS)["Sheet"]
    sheet_set = sheet_set_of(sheet)
    pages = popup.pages.pages_of(sheet)
    assert [p.SheetIndex for p in pages] == list(range(sheet.SheetCount))
    for index, page in enumerate(pages):
        pieces = pieces_on(sheet_set, index)
        view, annotations = page_parts(page)
        view, marks = page_parts(page)
        # The template is the paper (232 x 320 mm, custom), with the title block's texts.
        template = ElementTree.parse(page.Template.PageResult).getroot()
        assert (template.get("width"), template.get("height")) == ("232mm", "320mm")
        assert dict(page.Template.EditableTexts) == {
            "CardName": "Card",
            "Paper": "232 x 320 mm",
            "Sheet": f"{index + 1} of 2",
            "Scale": "1:1",
        }
        assert (view.ScaleType, view.Scale, view.CoarseView) == ("Custom", 1.0, True)
        assert tuple(view.Direction) == (0, 0, 1) and tuple(view.XDirection) == (1, 0, 0)
        # Page coordinates are sheet coordinates: the drawn outline spans the cut outline.
        outline = view.Source[0].Shape.BoundBox
        points = [
            (view.X.Value + v.X, view.Y.Value - v.Y)  # TechDraw's view y points down
            for e in view.getVisibleEdges()
            for v in e.Vertexes
        ]
        assert min(x for x, _ in points) == pytest.approx(outline.XMin, abs=1e-3)
        assert max(y for _, y in points) == pytest.approx(outline.YMax, abs=1e-3)
        # Folds: cosmetic lines, mountain dash-dot blue, valley dash green, at their places.
        folds = [fold for piece in pieces for fold in piece["folds"]]
        edges = view.CosmeticEdges
        assert len(edges) == len(folds) > 0
        for edge, fold in zip(edges, folds):
            expected = {"mountain": (4, (0, 0, 1)), "valley": (2, (0, 1, 0))}[fold["direction"]]
            assert line_format(edge) == expected
            # Cosmetic edges keep y up (TechDraw flips them when drawing) and 4 decimals.
            start = (view.X.Value + edge.Start.x, view.Y.Value + edge.Start.y)
            assert start == pytest.approx(tuple(fold["from"]), abs=1e-3)
        # Glue areas and labels: the symbol, 3.78 px per mm as TechDraw reads it, viewBox in mm.
        root = ElementTree.fromstring(marks.Symbol)
        assert (
            float(root.get("width")) == pytest.approx(232 * 3.78)
            and root.get("viewBox") == "0 0 232 320"
        )
        assert (marks.X.Value, marks.Y.Value, marks.Scale) == (116.0, 160.0, 1.0)
        glue = [area for piece in pieces for area in piece["glue"]]
        paths = list(layer_of(marks, "GLUE").iter(SVG + "path"))
        assert len(paths) == len(glue) > 0
        assert {p.get("fill") for p in paths} == {"rgb(217,217,217)"}
        first = paths[0].get("d").split()[1].split(",")  # "M x,y ...": SVG y points down
        x, y = glue[0]["polygon"][0]
        assert (float(first[0]), 320.0 - float(first[1])) == pytest.approx((x, y), abs=1e-5)
        labels = [label["text"] for piece in pieces for label in piece["labels"]]
        assert symbol_texts(marks) == labels
        assert [layer_of(marks, name) for name in ("CUT", "MOUNTAIN", "VALLEY")] == [None] * 3
    assert not any("Touched" in o.State or in_error(o) for o in doc.Objects)


def test_pages_follow_the_sheet_count_and_make_pages(doc, popup):
    objects = build_card(doc, popup, **TWO_SHEETS)
    sheet = objects["Sheet"]
    two_pages = page_objects_count(doc)
    sheet.Paper = "A3"  # everything on one sheet: the second page goes, with what it brought
    recompute_ok(doc, *objects.values())
    assert sheet.SheetCount == 1 and len(popup.pages.pages_of(sheet)) == 1
    page = popup.pages.pages_of(sheet)[0]
    assert page.Template.EditableTexts["Sheet"] == "1 of 1"
    one_page = page_objects_count(doc)
    assert one_page < two_pages
    # The page, its template, the symbol, the part view and its outline: however many labels.
    assert one_page == len(popup.pages.page_objects(page)) == 5
    labels = len(symbol_texts(page_parts(page)[1]))
    sheet.FoldHints = True  # more labels, not more objects
    recompute_ok(doc, *objects.values())
    more = sum(len(p["labels"]) for p in sheet_set_of(sheet)["pieces"])
    assert len(symbol_texts(page_parts(page)[1])) == more > labels
    assert page_objects_count(doc) == one_page
    sheet.FoldHints = False
    recompute_ok(doc, *objects.values())
    assert len(symbol_texts(page_parts(page)[1])) == labels
    sheet.MakePages = False
    recompute_ok(doc, *objects.values())
    assert page_objects_count(doc) == 0
    sheet.MakePages = True  # new pages survive (FreeCAD 0.20 re-removes names removed before)
    recompute_ok(doc, *objects.values())
    doc.recompute()
    assert page_objects_count(doc) == one_page
    assert not any("Touched" in o.State for o in doc.Objects)


def test_templates_are_the_paper_with_legend_and_title_block(popup):
    from popupwb.sheets.page_template import TitleBlock, template_svg

    title = TitleBlock("Birthday card", "A4 210 x 297 mm", 2, 3)
    root = ElementTree.fromstring(template_svg(210.0, 297.0, 10.0, title))
    assert (root.get("width"), root.get("height"), root.get("viewBox")) == (
        "210mm",
        "297mm",
        "0 0 210 297",
    )
    editable = "{http://www.freecadweb.org/wiki/index.php?title=Svg_Namespace}editable"
    texts = list(root.iter(SVG + "text"))
    fields = {t.get(editable): "".join(t.itertext()) for t in texts if t.get(editable)}
    assert fields == {
        "CardName": "Birthday card",
        "Paper": "A4 210 x 297 mm",
        "Sheet": "2 of 3",
        "Scale": "1:1",
    }
    legend = [t.text for t in texts if not t.get(editable) and not t.text.endswith(":")]
    assert legend == ["cut", "mountain fold", "valley fold", "glue"]
    # Everything sits in the bottom margin band (SVG y down: 287..297 mm), inside the margins,
    # legend left of the title block.
    xs = [float(t.get("x")) for t in texts]
    assert all(287.0 < float(t.get("y")) < 297.0 for t in texts)
    first_sample = next(root.iter(SVG + "line"))
    assert float(first_sample.get("x1")) == pytest.approx(10.0) and max(xs) < 200.0
    assert xs == sorted(xs)
    lines = {line.get("stroke"): line.get("stroke-dasharray") for line in root.iter(SVG + "line")}
    assert lines == {"#ff0000": None, "#0000ff": "3 1 0.5 1", "#00ff00": "3 1.5"}
    (glue,) = root.iter(SVG + "rect")
    assert glue.get("fill") == "#d9d9d9"


def test_a4_card_does_not_fit_a4_paper(doc, popup, card):
    sheet = card["Sheet"]
    sheet.Paper = "A4"
    doc.recompute()
    assert in_error(sheet)
    message = sheet.getStatusString()
    assert (
        message.startswith("CuttingSheet: Paper: piece P1")
        and "does not fit the printable area" in message
    )
    assert list(sheet.Diagnostics) == [f"error: {message}"]
    assert sheet.SheetSetJson == "" and sheet.RoundTripOk is False
    with pytest.raises(ValueError, match="no layout to export"):
        popup.cutting_sheet.export_cutting_sheet(sheet, "/nonexistent")
    assert not in_error(card["Card"]) and not in_error(card["Box"])
    sheet.Paper = "A3"
    recompute_ok(doc, *card.values())
    assert sheet.SheetSetJson and sheet.RoundTripOk


@pytest.mark.parametrize(
    "prop, value, expected",
    [
        ("TabAngle", 0.0, "TabAngle: tab_angle = 0, must be more than 0, at most 90°"),
        ("Kerf", 5.0, "Kerf: kerf = 5, must be 0 to 2 mm"),
        ("Margin", -1.0, "Margin: margin = -1"),
        ("MountainStyle", 9, "MountainStyle = 9, must be 1 to 5 (1 continuous, 2 dash"),
    ],
)
def test_a_bad_option_names_itself_and_can_be_fixed(doc, popup, card, prop, value, expected):
    sheet = card["Sheet"]
    good = getattr(sheet, prop)
    setattr(sheet, prop, value)
    doc.recompute()
    assert in_error(sheet)
    assert expected in sheet.getStatusString()
    assert sheet.Diagnostics[0].startswith("error: CuttingSheet: ")
    assert not any(in_error(card[name]) for name in ("Card", "Tent", "Box"))
    setattr(sheet, prop, good)
    recompute_ok(doc, *card.values())
    assert sheet.RoundTripOk and sheet.PieceCount == PIECES


def test_a_card_or_mechanism_in_error_stops_the_layout(doc, popup, card):
    sheet = card["Sheet"]
    card["Tent"].Foot = -3.0
    doc.recompute()
    assert in_error(sheet)
    assert "CuttingSheet: Tent of Card is in error, fix it first: Tent: Foot = -3 mm" in (
        sheet.getStatusString()
    )
    card["Tent"].Foot = TENT["foot"]
    card["Card"].Depth = 0.0
    doc.recompute()
    assert in_error(sheet)  # FreeCAD does not run a feature whose link is in error
    with pytest.raises(ValueError, match="CuttingSheet: the card Card is in error, fix it first"):
        sheet.Proxy.execute(sheet)  # as a recompute of the sheet alone does
    card["Card"].Preset = "A4"
    recompute_ok(doc, *card.values())
    sheet.Card = None
    doc.recompute()
    assert "CuttingSheet: Card = empty, must be a PopUpCard" in sheet.getStatusString()
    sheet.Card = card["Card"]
    recompute_ok(doc, *card.values())


def test_a_new_fold_angle_does_not_lay_out_again(doc, popup, card, monkeypatch):
    calls = []
    layout = popup.core.layout_sheets

    def counting(*args, **kwargs):
        calls.append(args[1])  # the SheetOptions
        return layout(*args, **kwargs)

    monkeypatch.setattr(popup.core, "layout_sheets", counting)
    card["Card"].FoldAngle = 70.0
    recompute_ok(doc, *card.values())
    assert calls == []
    card["Sheet"].Margin = 12.0
    recompute_ok(doc, *card.values())
    assert len(calls) == 1 and calls[0].margin == 12.0
    card["Box"].Height = 35.0  # another design: laid out again
    recompute_ok(doc, *card.values())
    assert len(calls) == 2


def test_export_writes_the_production_files(doc, popup, card, tmp_path):
    sheet = card["Sheet"]
    paths = popup.cutting_sheet.export_cutting_sheet(sheet, str(tmp_path / "out"))
    names = {"sheets.dxf", "sheets.svg", "sheets.pdf", "instructions.pdf", "report.json"}
    assert names <= set(os.listdir(tmp_path / "out"))
    for name in names:
        assert os.path.getsize(tmp_path / "out" / name) > 0
    with open(paths["report"]) as f:
        report = json.load(f)
    assert report["round_trip"]["ok"] is True
    assert len(report["pieces"]) == PIECES and report["sheets"] == sheet.SheetCount
    assert report["errors"] == [] and report["dxf_check"]["audit_errors"] == 0


def test_make_cutting_sheet_checks_its_arguments(doc, popup, card):
    make = popup.make
    with pytest.raises(ValueError, match="must be a PopUpCard"):
        make.make_cutting_sheet(card["Tent"])
    with pytest.raises(ValueError, match=r"paper = 'B5', must be one of"):
        make.make_cutting_sheet(card["Card"], paper="B5")
    with pytest.raises(TypeError, match="unknown option"):
        make.make_cutting_sheet(card["Card"], bleed=3)
    sheet = make.make_cutting_sheet(
        card["Card"], paper_width=300, paper_height=450, kerf=0.2, TabAngle=60, make_pages=False
    )
    assert (sheet.Paper, sheet.PaperWidth.Value, sheet.PaperHeight.Value) == ("Custom", 300, 450)
    assert (sheet.Kerf.Value, sheet.TabAngle.Value, sheet.MakePages) == (0.2, 60.0, False)
    recompute_ok(doc, sheet)
    assert popup.pages.pages_of(sheet) == [] and sheet.RoundTripOk
    assert sheet_set_of(sheet)["paper"]["name"] == "300.0x450.0"


def test_proxy_keeps_no_state_and_outputs_are_read_only(doc, popup, card):
    sheet = card["Sheet"]
    assert sheet.Proxy.TYPE == "PopUp::CuttingSheet" and sheet.Version == "1"
    json.dumps(sheet.Proxy.__getstate__())
    json.dumps(sheet.Proxy.dumps())
    for name in ("SheetCount", "PieceCount", "RoundTripOk", "Diagnostics", "CutLength"):
        assert sheet.getEditorMode(name) == ["ReadOnly"], name
    for name in ("NotValid", "ValidityFindings"):
        assert sheet.getEditorMode(name) == ["ReadOnly"], name
    assert sheet.Force is False and sheet.NotValid == "" and sheet.ValidityFindings == []
    assert sheet.getEditorMode("SheetSetJson") == ["Hidden"]
    assert sheet.getGroupOfProperty("Kerf") == "Sheets"
    assert sheet.getGroupOfProperty("RoundTripOk") == "Report"
    assert (sheet.MountainStyle, sheet.ValleyStyle, sheet.MakePages) == (4, 2, True)


# An A5 card (pages 105 mm deep) whose tent ends foot 30 + slope 80 = 110 mm from the fold: closed,
# it sticks out by 5 mm; the validity check finds it not enclosed, and nothing else.
TALL_TENT = dict(offset=40.0, width=60.0, foot=30.0, foot_backdrop=30.0, slope=80.0)
STAMP = "NOT VALID: not enclosed"


def stamps_on(page):
    """The stamp's <text> elements in the page's symbol view."""
    _, marks = page_parts(page)
    return [t for t in layer_of(marks, "LABEL").iter(SVG + "text") if t.text == STAMP]


def test_a_rejected_card_is_laid_out_only_when_forced(doc, popup, tmp_path):
    make = popup.make
    card = make.make_card(doc, preset="A5")
    tent = make.make_tent_fold(card, name="TallTent", **TALL_TENT)
    sheet = make.make_cutting_sheet(card, paper="A4")
    doc.recompute()
    assert in_error(sheet)
    status = sheet.getStatusString()
    assert f"CuttingSheet: the card Card is {STAMP}: not_enclosed: " in status
    assert "sticks out of the closed card by 5 mm" in status and "set Force" in status
    assert sheet.SheetSetJson == "" and popup.pages.pages_of(sheet) == []
    assert not popup.cutting_sheet.has_layout(sheet)  # PopUp_ExportSheets is disabled
    with pytest.raises(ValueError, match="no layout to export"):
        popup.cutting_sheet.export_cutting_sheet(sheet, str(tmp_path / "refused"))

    sheet.Force = True
    recompute_ok(doc, card, tent, sheet)
    assert sheet.NotValid == STAMP and popup.cutting_sheet.has_layout(sheet)
    assert sheet.Diagnostics[0] == f"warning: {STAMP} (laid out because Force is set)"
    assert any("by 5 mm" in finding for finding in sheet.ValidityFindings)
    pages = popup.pages.pages_of(sheet)
    assert len(pages) == sheet.SheetCount == 1
    (stamp,) = stamps_on(pages[0])
    # Centred across the A4 page (210 mm wide) in its 10 mm top margin band (SVG y down).
    assert float(stamp.get("x")) == pytest.approx(105.0) and 0.0 < float(stamp.get("y")) < 10.0
    paths = popup.cutting_sheet.export_cutting_sheet(sheet, str(tmp_path / "forced"))
    modelspace = ezdxf.readfile(paths["dxf"]).modelspace()
    texts = [text.dxf.text for text in modelspace.query("TEXT[layer=='LABEL']")]
    assert texts.count(STAMP) == sheet.SheetCount
    with open(paths["report"]) as f:
        assert json.load(f)["not_valid"] == STAMP

    sheet.Force = False
    doc.recompute()
    assert in_error(sheet) and sheet.NotValid == ""
    tent.Slope = 50.0  # 30 + 50 = 80 mm: inside the page
    recompute_ok(doc, card, tent, sheet)
    assert sheet.NotValid == "" and not any(STAMP in line for line in sheet.Diagnostics)
    assert [stamps_on(page) for page in popup.pages.pages_of(sheet)] == [[]]


REOPEN_SCRIPT = """
import json
doc = FreeCAD.openDocument({path!r})
sheet = doc.getObject("CuttingSheet")
from popupwb.sheets.techdraw_pages import pages_of
out = {{"proxy": sheet.Proxy is not None, "version": sheet.Version, "paper": sheet.Paper,
        "kerf": sheet.Kerf.Value, "tab_angle": sheet.TabAngle.Value, "pieces": sheet.PieceCount,
        "sheets": sheet.SheetCount, "ok": sheet.RoundTripOk, "json": sheet.SheetSetJson,
        "pages": len(pages_of(sheet))}}
for obj in doc.Objects:
    obj.touch()
doc.recompute()
sheet.Margin = 12.0  # a real layout in this process
doc.recompute()
out["states"] = sorted({{s for o in doc.Objects for s in o.State}})
out["after"] = {{"valid": sheet.Shape.isValid(), "faces": len(sheet.Shape.Faces),
                 "margin": json.loads(sheet.SheetSetJson)["options"]["margin"],
                 "pages": len(pages_of(sheet)), "sheets": sheet.SheetCount,
                 "ok": sheet.RoundTripOk}}
print(json.dumps(out))
"""


def test_survives_save_and_reopen(doc, popup, card, tmp_path, run_fresh_freecad):
    sheet = card["Sheet"]
    sheet.Kerf = 0.15
    recompute_ok(doc, *card.values())
    path = str(tmp_path / "cutting_sheet.FCStd")
    doc.saveAs(path)
    reopened = run_fresh_freecad(REOPEN_SCRIPT.format(path=path))
    assert reopened["proxy"], "proxy not restored (sandbox Mod/PopUp symlink?)"
    assert reopened["version"] == "1" and reopened["paper"] == "A3"
    assert (reopened["kerf"], reopened["tab_angle"]) == (0.15, 45.0)
    assert (reopened["pieces"], reopened["sheets"], reopened["ok"]) == (PIECES, 1, True)
    assert reopened["json"] == sheet.SheetSetJson
    assert reopened["pages"] == 1
    assert reopened["states"] == ["Up-to-date"]
    assert reopened["after"] == {
        "valid": True,
        "faces": len(sheet.Shape.Faces),
        "margin": 12.0,
        "pages": 1,
        "sheets": 1,
        "ok": True,
    }


def label_box(label):
    """The axis-aligned box of a label's text (its cap height by its Helvetica width), turned."""
    import math

    from reportlab.pdfbase.pdfmetrics import stringWidth

    width = stringWidth(label["text"], "Helvetica", label["height"] / 0.716)
    turn = math.radians(label["angle"])
    half_x = (abs(width * math.cos(turn)) + abs(label["height"] * math.sin(turn))) / 2.0
    half_y = (abs(width * math.sin(turn)) + abs(label["height"] * math.cos(turn))) / 2.0
    x, y = label["position"]
    return (x - half_x, y - half_y, x + half_x, y + half_y)


def test_page_labels_are_legible_and_apart(doc, popup):
    """What the page's symbol draws: every label at least 1.5 mm high (legible on a laser print
    at 1:1) and no two labels on a sheet overlapping."""
    sheet = build_card(doc, popup, **TWO_SHEETS)["Sheet"]
    sheet_set = sheet_set_of(sheet)
    for index, page in enumerate(popup.pages.pages_of(sheet)):
        labels = [label for piece in pieces_on(sheet_set, index) for label in piece["labels"]]
        assert symbol_texts(page_parts(page)[1]) == [label["text"] for label in labels]
        assert min(label["height"] for label in labels) >= 1.5
        boxes = [label_box(label) for label in labels]
        for a in range(len(boxes)):
            for b in range(a + 1, len(boxes)):
                (ax0, ay0, ax1, ay1), (bx0, by0, bx1, by1) = boxes[a], boxes[b]
                apart = ax1 <= bx0 or bx1 <= ax0 or ay1 <= by0 or by1 <= ay0
                assert apart, (labels[a], labels[b])
