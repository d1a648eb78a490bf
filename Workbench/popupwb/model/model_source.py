"""Where a model comes from and where it goes: a popupcore.ModelMesh from a FreeCAD object (a
Mesh::Feature, or a Part shape tessellated) or from an .FCStd file, and the source model placed on
the fitted card as a Mesh::Feature.

Model files (STL, OBJ, PLY, OFF, glTF, ...) are read by popupcore.load_model (assimp); this module
covers what lives in FreeCAD. Errors are ValueError naming the object or file and what is wrong.
"""

import collections
import os

import numpy as np

# Tessellation tolerance of a Part shape, as a fraction of its bounding-box diagonal: fine enough
# that the fit sees the solid (0.1 % of a 100 mm model is 0.1 mm), coarse enough to stay small.
TESSELLATION = 0.001


def is_mesh_object(obj):
    return obj.isDerivedFrom("Mesh::Feature")


def is_shape_object(obj):
    shape = getattr(obj, "Shape", None)
    return (
        obj.isDerivedFrom("Part::Feature")
        and shape is not None
        and not shape.isNull()
        and len(shape.Faces) > 0
    )


def _is_popup_object(obj):
    from popupwb.model import card_scaffold

    return card_scaffold.is_card(obj) or card_scaffold.is_mechanism(obj)


def is_model_object(obj):
    """A Mesh::Feature or a Part object with faces that is not itself a PopUp card or mechanism."""
    return (is_mesh_object(obj) or is_shape_object(obj)) and not _is_popup_object(obj)


def _triangles_of(obj):
    """(points Nx3, triangles Mx3) of `obj` in document coordinates (its Placement applied)."""
    if is_mesh_object(obj):
        points, facets = obj.Mesh.Topology  # placement applied
    else:
        shape = obj.Shape
        diagonal = shape.BoundBox.DiagonalLength
        if not diagonal > 0:
            raise ValueError(f"{obj.Label}: the shape has no extent")
        points, facets = shape.tessellate(TESSELLATION * diagonal)
    vertices = np.array([[p.x, p.y, p.z] for p in points], dtype=float).reshape(-1, 3)
    triangles = np.array(facets, dtype=np.int64).reshape(-1, 3)
    return vertices, triangles


def model_of_objects(objects, source):
    """One popupcore.ModelMesh of every object in `objects` (meshes and Part shapes)."""
    from popupwb.core import popupcore

    if not objects:
        raise ValueError(f"{source}: no mesh or Part shape to fit")
    all_vertices, all_triangles, offset = [], [], 0
    for obj in objects:
        if not is_model_object(obj):
            raise ValueError(f"{obj.Label}: is neither a mesh nor a Part shape with faces")
        vertices, triangles = _triangles_of(obj)
        if len(triangles) == 0:
            raise ValueError(f"{obj.Label}: has no triangles")
        all_vertices.append(vertices)
        all_triangles.append(triangles + offset)
        offset += len(vertices)
    return popupcore.ModelMesh(np.vstack(all_vertices), np.vstack(all_triangles), source=source)


def model_of_object(obj):
    """The ModelMesh of one selected object (the PopUp_FromModel command's input)."""
    return model_of_objects([obj], obj.Label)


def top_level_models(doc):
    """The model objects of `doc` no other object uses (a Fusion, not the boxes fused in it)."""
    return [
        obj
        for obj in doc.Objects
        if is_model_object(obj) and not [user for user in obj.InList if is_model_object(user)]
    ]


def model_of_document(path):
    """The ModelMesh of an .FCStd file's top-level meshes and Part shapes, and their Labels."""
    import FreeCAD

    from popupwb.document_precheck import check_fcstd

    try:
        check_fcstd(path)
    except ValueError as e:
        raise ValueError(f"{path}: {e}")
    wanted = os.path.realpath(path)
    already = [
        d
        for d in FreeCAD.listDocuments().values()
        if d.FileName and os.path.realpath(d.FileName) == wanted
    ]
    if already:  # open in this session: read it, and leave it open
        doc = already[0]
    else:
        try:
            doc = FreeCAD.openDocument(os.path.abspath(path))
        except Exception as e:  # FreeCAD raises plain Exception/OSError on a damaged file
            raise ValueError(f"{path}: cannot open as a FreeCAD document ({e})")
    try:
        objects = top_level_models(doc)
        if not objects:
            raise ValueError(f"{path}: no Mesh or Part object with faces in this document")
        return model_of_objects(objects, path), [obj.Label for obj in objects]
    finally:
        if not already:
            FreeCAD.closeDocument(doc.Name)


def transformed(vertices, matrix):
    """Rows of `vertices` (Nx3) mapped by the 4x4 `matrix` (points, w = 1)."""
    vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
    matrix = np.asarray(matrix, dtype=float)
    return vertices @ matrix[:3, :3].T + matrix[:3, 3]


def add_source_model(doc, model, model_to_card, placement=None, name="SourceModel"):
    """A Mesh::Feature holding `model` (a ModelMesh) in the card's frame (model_to_card applied),
    at `placement` (the card's), so it stands where the pop-up does."""
    import FreeCAD
    import Mesh

    points = [FreeCAD.Vector(*p) for p in transformed(model.vertices, model_to_card)]
    triangles = np.asarray(model.triangles).reshape(-1, 3)
    if np.linalg.det(np.asarray(model_to_card, dtype=float)[:3, :3]) < 0:
        triangles = triangles[:, ::-1]  # a mirroring matrix turns the faces inside out: undo it
    facets = list(map(tuple, triangles.tolist()))  # Mesh takes tuples of ints, not arrays
    obj = doc.addObject("Mesh::Feature", name)
    obj.Mesh = Mesh.Mesh((points, facets))
    if placement is not None:
        obj.Placement = placement
    if model.source:
        obj.Label = f"{name} ({os.path.basename(model.source)})"
    return obj


def in_card_frame(model, model_to_card):
    """`model` (a ModelMesh, changed in place and returned) moved into the card's frame: its
    vertices through `model_to_card`, its faces turned back outward if the matrix mirrors."""
    matrix = np.asarray(model_to_card, dtype=float)
    model.vertices = transformed(model.vertices, matrix)
    if np.linalg.det(matrix[:3, :3]) < 0:
        model.triangles = np.asarray(model.triangles)[:, ::-1].copy()
    return model


def has_source_model(card):
    """True for a card designed from a model (it links the mesh it keeps)."""
    source = getattr(card, "SourceModel", None)
    return source is not None and is_mesh_object(source)


def card_model(card):
    """The ModelMesh of the model `card` was designed from, in the card's frame (mm), or None
    for a card made by hand. The model file itself when it is still there (its texture and vertex
    colours are what artwork prints), else the mesh kept in the document (its shape only)."""
    from popupwb.core import popupcore
    from popupwb.model import model_file

    source = getattr(card, "SourceModel", None)
    if source is None or not is_mesh_object(source):
        return None
    matrix = np.array(card.ModelToCard.A, dtype=float).reshape(4, 4)
    path = getattr(card, "SourceFile", "")
    if path and os.path.isfile(path) and not path.lower().endswith(".fcstd"):
        try:
            return in_card_frame(model_file.load_model(path), matrix)
        except (ValueError, RuntimeError, OSError, AttributeError):
            pass  # changed or unreadable since: the kept mesh still has the shape
    return _kept_mesh(source, card)


def _kept_mesh(source, card):
    """The ModelMesh a Mesh feature `source` keeps, in `card`'s frame (it stands where the card
    is placed)."""
    from popupwb.core import popupcore

    points, facets = source.Mesh.Topology
    to_card = card.Placement.inverse().toMatrix()
    local = [to_card.multVec(p) for p in points]
    vertices = np.array([[p.x, p.y, p.z] for p in local], dtype=float).reshape(-1, 3)
    return popupcore.ModelMesh(
        vertices, np.array(facets, dtype=np.int64).reshape(-1, 3), source=source.Label
    )


# A limb of an animated character (popupwb.motion.design_from_motion): its mesh in the card's
# frame and the names of the patches it is printed on ("<mechanism Name>.<part>").
PrintedLimb = collections.namedtuple("PrintedLimb", "mesh patches")


def card_limbs(card):
    """The limbs `card`'s mechanisms carry (each mechanism's LimbModel, printed on its
    LimbParts alone; thesis Fig 6.9), in the card's frame: [] for an animated card without any,
    None for a card not designed from an animation (its model prints as a fitted model's)."""
    from popupwb.model.card_scaffold import mechanisms_of

    if "SourceAnimation" not in card.PropertiesList:
        return None
    limbs = []
    for mechanism in mechanisms_of(card):
        limb = getattr(mechanism, "LimbModel", None)
        if limb is None or not is_mesh_object(limb):
            continue
        patches = frozenset(f"{mechanism.Name}.{part}" for part in mechanism.LimbParts)
        limbs.append(PrintedLimb(_kept_mesh(limb, card), patches))
    return limbs
