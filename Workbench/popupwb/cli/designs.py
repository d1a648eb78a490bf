"""The designs a `popup` command reads: a .json design, or the Scaffold and PopUpCard objects of a
FreeCAD document (each card's scaffold as built, its patch titles, the sides its CuttingSheets
print and the model it was designed from); anything that cannot be used is an InputError naming
the file and what is wrong.
"""

import collections
import os

from popupwb.cli.common import InputError, import_core, import_freecad, one_line, stdout_to_stderr
from popupwb.readable_file import unreadable


# A design to check, lay out or verify, and what the reports say about where it came from (object
# Name, Label, design file; empty for a .json design). `printed_sides` is what the card's
# CuttingSheet features say ({CuttingSheet Name: {piece: side}}), empty for anything else.
# `patch_titles` ({patch id: maker title}, patch_titles.py) names a card's patches in findings.
# `model` is the ModelMesh (card mm) a card was designed from (card.SourceModel, `popup fit`), whose
# appearance the sheets print as artwork; None for anything else. `limbs` are an animated
# character's limbs (model_source.card_limbs), each printed on its mechanism's moving parts alone;
# None when the card is not animated.
Design = collections.namedtuple(
    "Design",
    "scaffold fields printed_sides patch_titles model limbs",
    defaults=({}, {}, None, None),
)


def _design_objects(doc):
    """The Scaffold and PopUpCard objects of `doc`, in document order."""
    from popupwb.model.card_scaffold import is_card
    from popupwb.features.scaffold_feature import is_scaffold

    return [obj for obj in doc.Objects if is_scaffold(obj) or is_card(obj)]


def _object_names(objects):
    return ", ".join(o.Name if o.Label == o.Name else f"{o.Name} ('{o.Label}')" for o in objects)


def _select_cards(path, objects, card):
    """All of `objects`, or the one whose Name (else Label) is `card`."""
    if card is None:
        return objects
    chosen = [o for o in objects if o.Name == card] or [o for o in objects if o.Label == card]
    if not chosen:
        raise InputError(
            f"{path}: --card {card}: no PopUpCard or Scaffold has this Name or Label; "
            f"the document has: {_object_names(objects)}"
        )
    return chosen[:1]


def _card_design(path, card, several, with_model=False):
    """The assembled scaffold of a PopUpCard and its mechanisms; a part that does not build makes
    the input unusable (the message is the feature's error)."""
    from popupwb.model.card_scaffold import for_card, stray_features
    from popupwb.features.cutting_sheet import card_prints_artwork
    from popupwb.validity.card_titles import titles_of_card

    built = for_card(card)
    problems = ([built.card_error] if built.card_error else []) + list(built.errors.values())
    problems += stray_features(card.Document)
    if problems:
        # Several cards: say which one, and that the others can still be checked alone.
        where = f"{path}: card {card.Label}" if several else path
        hint = " (--card checks another card alone)" if several else ""
        raise InputError(f"{where}: {problems[0]}{hint}")
    prints = with_model and card_prints_artwork(card)
    return Design(
        built.scaffold.copy(),
        {"object": card.Name, "label": card.Label},
        _cutting_sides(card),
        titles_of_card(card, built),
        _source_model(path, card) if prints else None,
        _limbs(path, card) if prints else None,
    )


def _source_model(path, card):
    """The model the card was designed from, in card mm, or None (popupwb.model.model_source)."""
    from popupwb.model.model_source import card_model

    try:
        return card_model(card)
    except ValueError as e:
        raise InputError(f"{path}: {card.Label}.SourceModel: {one_line(e)}")


def _limbs(path, card):
    """The limbs of an animated card's character (popupwb.model.model_source.card_limbs)."""
    from popupwb.model.model_source import card_limbs

    try:
        return card_limbs(card)
    except ValueError as e:
        raise InputError(f"{path}: {card.Label}: a limb's mesh: {one_line(e)}")


def _cutting_sides(card):
    """{CuttingSheet Name: {piece: side}} of the CuttingSheets laying out `card`."""
    from popupwb.features.cutting_sheet import is_cutting_sheet
    from popupwb.sheets.sheet_options import parse_sides

    sides = {}
    for obj in card.Document.Objects:
        if is_cutting_sheet(obj) and obj.Card is not None and obj.Card.Name == card.Name:
            try:
                sides[obj.Name] = parse_sides(list(getattr(obj, "PrintedSides", [])))
            except ValueError as e:
                raise InputError(f"{card.Document.FileName}: {obj.Label}.PrintedSides: {e}")
    return sides


def _scaffold_design(popupcore, path, obj):
    design = str(obj.DesignFile)
    what = f"{path}: {obj.Label}.DesignFile"
    if not design:
        raise InputError(f"{what} is empty")
    if not os.path.isabs(design):
        design = os.path.join(os.path.dirname(os.path.abspath(path)), design)
    if not os.path.isfile(design):
        raise InputError(f"{what} = '{obj.DesignFile}': no such file")
    # Load now: a PropertyFileIncluded path lies in the document's transient folder, which goes
    # away when the document closes.
    scaffold = _load_json_design(popupcore, design, f"{what} = '{obj.DesignFile}'")
    # The folder of an embedded design is the document's temporary one: name only.
    fields = {"object": obj.Name, "label": obj.Label, "design_file": os.path.basename(design)}
    return Design(scaffold, fields)


def _load_json_design(popupcore, path, label):
    try:
        return popupcore.load_scaffold(path)
    except (ValueError, RuntimeError, OSError) as e:
        raise InputError(f"{label}: {one_line(e)}")


def _load_fcstd_designs(popupcore, path, card, one, with_model=False):
    """The designs of the Scaffold and PopUpCard objects of an .FCStd file (or of the one named
    `card`); with `one`, several of them make the input unusable."""
    from popupwb.document_precheck import check_fcstd

    try:
        check_fcstd(path)
    except ValueError as e:
        raise InputError(f"{path}: {e}")
    with stdout_to_stderr():
        FreeCAD = import_freecad()
        try:
            doc = FreeCAD.openDocument(os.path.abspath(path))
        except Exception as e:  # FreeCAD raises plain Exception/OSError/ValueError on bad files
            raise InputError(f"{path}: cannot open as a FreeCAD document ({one_line(e)})")
        try:
            objects = _design_objects(doc)
            if not objects:
                orphans = [o.Label for o in doc.Objects if "DesignFile" in o.PropertiesList]
                if orphans:
                    raise InputError(
                        f"{path}: object '{orphans[0]}' looks like a PopUp Scaffold but its "
                        "proxy did not load (install the workbench: make install-dev)"
                    )
                raise InputError(f"{path}: no PopUp Scaffold or PopUpCard object in this document")
            chosen = _select_cards(path, objects, card)
            if one and len(chosen) > 1:
                raise InputError(
                    f"{path}: {len(chosen)} cards ({_object_names(chosen)}): name the one to "
                    "lay out with --card"
                )
            return [
                (
                    _scaffold_design(popupcore, path, obj)
                    if "DesignFile" in obj.PropertiesList
                    else _card_design(path, obj, len(chosen) > 1, with_model)
                )
                for obj in chosen
            ]
        finally:
            FreeCAD.closeDocument(doc.Name)


def is_document(path):
    return path.lower().endswith(".fcstd")


def load_designs(path, card=None, one=False, with_model=False):
    """(popupcore, [Design]) for a .json path (one design) or an .FCStd path (each Scaffold and
    PopUpCard, or the one named `card`; with `one`, several are an InputError). `with_model`
    reads the model a card was designed from (Design.model, for the sheets' artwork)."""
    why = unreadable(path)
    if why:
        raise InputError(why)
    if card is not None and not is_document(path):
        raise InputError(f"--card {card}: only for FreeCAD documents (.FCStd), not {path}")
    popupcore = import_core()
    if is_document(path):
        return popupcore, _load_fcstd_designs(popupcore, path, card, one, with_model)
    return popupcore, [Design(_load_json_design(popupcore, path, path), {})]


def card_printed_sides(args, design, flag_given=False):
    """The printed sides the card's CuttingSheets give ({} for a .json design or a card without
    one); CuttingSheets that disagree need --printed-side."""
    features = design.printed_sides
    distinct = []
    for sides in features.values():
        if sides not in distinct:
            distinct.append(sides)
    if len(distinct) > 1 and not flag_given:
        described = "; ".join(
            f"{name}: {', '.join(f'{k}={v}' for k, v in sorted(sides.items())) or 'all front'}"
            for name, sides in features.items()
        )
        raise InputError(
            f"{args.design}: the card's CuttingSheets print different sides ({described}): say "
            "which to use, e.g. --printed-side P1=front"
        )
    base = distinct[0] if len(distinct) == 1 else {}
    for piece, side in base.items():
        if side not in ("front", "back"):
            names = ", ".join(features)
            raise InputError(
                f"{args.design}: {names}.PrintedSides: {piece}={side}, the side must be front or "
                "back"
            )
    return base
