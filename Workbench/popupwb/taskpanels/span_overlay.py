"""SpanOverlay: the spans a mechanism and its siblings occupy along their host pair's hinge
(popupwb.model.placement), drawn in the 3D view while the mechanism's task panel is open.

Each span is a bracket on the hinge, posed with the host pair's ground patch at the card's
FoldAngle and moved with the card's Placement, labelled with its mechanism and range: orange for
the edited mechanism, grey-blue for its siblings, red where two overlap. An SoAnnotation draws it
over the paper. The panel adds it, refreshes it after each change and removes it on close.
"""

import FreeCAD
from pivy import coin

from popupwb.model import card_scaffold, placement
from popupwb.taskpanels import scene_overlay

NODE_NAME = "PopUpSpanOverlay"  # scripts and the GUI test find the overlay by this name
OWN = (1.0, 0.5, 0.0)
SIBLING = (0.35, 0.45, 0.6)
OVERLAP = (0.85, 0.0, 0.0)
TICK = 0.08  # bracket ends, as a share of the hinge length
STACK = 0.03  # each further span drawn this share of the hinge higher, so overlaps show


class SpanOverlay:
    def __init__(self, obj):
        self.obj = obj
        self.node = None
        self.spans = []  # (Span, colour) drawn last, for scripts and tests

    def _view_root(self):
        return scene_overlay.view_root(self.obj.Document.Name)

    def refresh(self):
        """Redraws the spans for the current parameters (nothing when the mechanism is in
        error: then it occupies no span)."""
        self.remove()
        drawn = self._spans()
        root = self._view_root()
        if not drawn or root is None:
            return
        self.node = coin.SoAnnotation()
        self.node.setName(NODE_NAME)
        for index, (span, colour, posed) in enumerate(drawn):
            self.node.addChild(_bracket(span, colour, posed, index))
        root.addChild(self.node)
        self.spans = [(span, colour) for span, colour, _ in drawn]

    def remove(self):
        scene_overlay.detach(self.node, self.obj.Document.Name)
        self.node = None
        self.spans = []

    def _spans(self):
        """[(Span, colour, posed(s, lift) -> FreeCAD.Vector)], the edited mechanism first."""
        found = placement.overlaps(self.obj)
        if found is None or found[2] is None:
            return []
        own, overlapping, pair = found
        card = card_scaffold.root_card(self.obj)
        built = card_scaffold.for_card(card)
        try:
            state = built.state_at(card.FoldAngle.Value)
        except ValueError:
            return []
        rotation = state.rotations[pair.ground]
        translation = state.translations[pair.ground]
        length = pair.length

        def posed(s, lift):
            local = pair.origin + pair.axis * s + pair.up * (lift * length)
            world = rotation @ local + translation
            return card.Placement.multVec(FreeCAD.Vector(*map(float, world)))

        hit = {s.label for s in overlapping}
        drawn = [(own, OVERLAP if hit else OWN, posed)]
        for span in placement.spans_on(built, pair.name, without=self.obj.Name):
            drawn.append((span, OVERLAP if span.label in hit else SIBLING, posed))
        return drawn


def _bracket(span, colour, posed, index):
    """A bracket from span.start to span.end lifted `index` steps off the hinge, with a label."""
    lift = STACK * index
    points = [
        posed(span.start, lift + TICK),
        posed(span.start, lift),
        posed(span.end, lift),
        posed(span.end, lift + TICK),
    ]
    group = coin.SoSeparator()
    material = coin.SoBaseColor()
    material.rgb = colour
    style = coin.SoDrawStyle()
    style.lineWidth = 4
    coords = coin.SoCoordinate3()
    coords.point.setValues(0, len(points), [tuple(p) for p in points])
    lines = coin.SoLineSet()
    lines.numVertices.setValue(len(points))
    group.addChild(material)
    group.addChild(style)
    group.addChild(coords)
    group.addChild(lines)
    middle = (points[1] + points[2]) * 0.5
    move = coin.SoTranslation()
    move.translation = tuple(middle)
    text = coin.SoText2()
    text.string = (
        # ASCII: SoText2's bitmap font has no en dash.
        f"{span.label} {placement.millimetres(span.start)}-{placement.millimetres(span.end)} mm"
    )
    group.addChild(move)
    group.addChild(text)
    return group
