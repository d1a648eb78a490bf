"""PrimitiveOverlay: the prisms popupcore.fit_design fitted, drawn over the model in the 3D view
while the PopUp_FromModel panel waits for the maker to accept them.

The prisms come in the card's frame (mm); the overlay maps them back through the inverse of the
fit's model_to_card so that they sit on the selected model where it stands (its own Placement is
already in the model's coordinates). Faces are translucent orange, edges dark: the model shows
through. An SoSeparator under the view's scene graph, removed when the panel closes.
"""

import numpy as np
from pivy import coin

from popupwb.fitting.prism_hull import hull_faces
from popupwb.taskpanels import scene_overlay

NODE_NAME = "PopUpPrimitiveOverlay"  # scripts and the GUI test find the overlay by this name
FACE_COLOUR = (1.0, 0.55, 0.1)
EDGE_COLOUR = (0.25, 0.1, 0.0)
TRANSPARENCY = 0.45


def to_model(corners, model_to_card):
    """Corners (card mm) back in the model's coordinates."""
    inverse = np.linalg.inv(np.asarray(model_to_card, dtype=float))
    c = np.asarray(corners, dtype=float).reshape(-1, 3)
    return c @ inverse[:3, :3].T + inverse[:3, 3]


class PrimitiveOverlay:
    def __init__(self, doc):
        self.doc = doc
        self.node = None
        self.prisms = []  # corners in model coordinates, as drawn last

    def _view_root(self):
        return scene_overlay.view_root(self.doc.Name)

    def show(self, primitives, model_to_card):
        """Draws the fitted `primitives` (each with .corners in card mm)."""
        self.remove()
        self.prisms = [to_model(p.corners, model_to_card) for p in primitives]
        root = self._view_root()
        if not self.prisms or root is None:
            return
        self.node = coin.SoSeparator()
        self.node.setName(NODE_NAME)
        for corners in self.prisms:
            self.node.addChild(_prism_node(corners))
        root.addChild(self.node)

    def remove(self):
        scene_overlay.detach(self.node, self.doc.Name)
        self.node = None
        self.prisms = []


def _prism_node(corners):
    faces_of_hull = hull_faces(corners)
    group = coin.SoSeparator()
    coords = coin.SoCoordinate3()
    coords.point.setValues(0, len(corners), [tuple(map(float, c)) for c in corners])
    group.addChild(coords)

    faces = coin.SoSeparator()
    # A prism fitted well shares its faces with the model's: pulled toward the viewer, they do
    # not flicker through the model's (z-fighting).
    offset = coin.SoPolygonOffset()
    offset.factor = -1.0
    offset.units = -1.0
    faces.addChild(offset)
    material = coin.SoMaterial()
    material.diffuseColor = FACE_COLOUR
    material.transparency = TRANSPARENCY
    faces.addChild(material)
    face_set = coin.SoIndexedFaceSet()
    indices = []
    for face in faces_of_hull:
        indices.extend([int(i) for i in face] + [-1])
    face_set.coordIndex.setValues(0, len(indices), indices)
    faces.addChild(face_set)
    group.addChild(faces)

    edges = coin.SoSeparator()
    colour = coin.SoBaseColor()
    colour.rgb = EDGE_COLOUR
    style = coin.SoDrawStyle()
    style.lineWidth = 2
    edges.addChild(colour)
    edges.addChild(style)
    line_set = coin.SoIndexedLineSet()
    indices = []
    for face in faces_of_hull:
        indices.extend([int(i) for i in face] + [int(face[0]), -1])
    line_set.coordIndex.setValues(0, len(indices), indices)
    edges.addChild(line_set)
    group.addChild(edges)
    return group
