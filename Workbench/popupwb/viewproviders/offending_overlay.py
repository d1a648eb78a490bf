"""Red outlines of an object's offending patches, in a Coin node of its own under the object's
root node. FreeCAD's selection colour covers a selected object's faces and edges (and so the red
DiffuseColor of its offending faces), never this node: the marks stay visible whatever is
selected. The node cannot be picked, and it is shown only while its object is."""

NODE_NAME = "PopUpOffendingOutlines"
COLOUR = (0.90, 0.10, 0.10)
LINE_WIDTH = 5.0  # pixels; FreeCAD draws edges 2 px wide, the mark shows around them
DEFLECTION = 0.05  # mm, for curved edges


def _find(vobj):
    # FreeCAD 1.0 hands out RootNode as a pivy object only once pivy is imported: without this,
    # a check that runs before any other Coin code gets a SwigPyObject with no getNumChildren.
    from pivy import coin  # noqa: F401

    root = vobj.RootNode
    for index in range(root.getNumChildren()):
        child = root.getChild(index)
        if child.getName() == NODE_NAME:
            return child
    return None


def _make(vobj):
    from pivy import coin

    switch = coin.SoSwitch()
    switch.setName(NODE_NAME)
    group = coin.SoSeparator()
    pick = coin.SoPickStyle()
    pick.style = coin.SoPickStyle.UNPICKABLE
    depth = coin.SoDepthBuffer()
    depth.function = coin.SoDepthBuffer.LEQUAL  # over FreeCAD's own edges at the same depth
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    colour = coin.SoBaseColor()
    colour.rgb = COLOUR
    style = coin.SoDrawStyle()
    style.lineWidth = LINE_WIDTH
    for node in (pick, depth, light, colour, style, coin.SoCoordinate3(), coin.SoLineSet()):
        group.addChild(node)
    switch.addChild(group)
    vobj.RootNode.addChild(switch)  # after the root's transform: it follows the Placement
    return switch


def show_outlines(vobj, shapes):
    """Outlines the edges of `shapes` (in the object's own coordinates, without its Placement);
    no shapes removes the marks."""
    polylines = []
    for shape in shapes:
        for edge in shape.Edges:
            points = edge.discretize(Deflection=DEFLECTION)
            if len(points) >= 2:
                polylines.append(points)
    switch = _find(vobj)
    if switch is None:
        if not polylines:
            return
        switch = _make(vobj)
    group = switch.getChild(0)
    coordinates, lines = group.getChild(5), group.getChild(6)
    coordinates.point.setValues(0, [tuple(p) for line in polylines for p in line])
    coordinates.point.setNum(sum(len(line) for line in polylines))
    lines.numVertices.setValues(0, [len(line) for line in polylines])
    lines.numVertices.setNum(len(polylines))
    follow_visibility(vobj, bool(polylines))


def follow_visibility(vobj, marked=None):
    """Shows the marks only while the object is shown (and has marks)."""
    from pivy import coin

    switch = _find(vobj)
    if switch is None:
        return
    if marked is None:
        marked = switch.getChild(0).getChild(6).numVertices.getNum() > 0
    shown = marked and vobj.Visibility
    switch.whichChild = coin.SO_SWITCH_ALL if shown else coin.SO_SWITCH_NONE


def outlined_edge_count(vobj):
    """Number of outlined edges (tests and the GUI checks)."""
    switch = _find(vobj)
    return 0 if switch is None else switch.getChild(0).getChild(6).numVertices.getNum()
