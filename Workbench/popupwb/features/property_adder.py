"""Adding FreeCAD properties once, so documents written by older versions upgrade on restore."""


def property_adder(obj, group):
    """A function add(kind, name, doc, value=None, mode=0, output=False) that adds the property
    `name` to `obj` in `group` unless it exists. mode 1 is read-only, 2 hidden; `output`
    properties are written by commands and do not trigger a recompute."""
    have = set(obj.PropertiesList)

    def add(kind, name, doc, value=None, mode=0, output=False):
        if name in have:
            return
        obj.addProperty(kind, name, group, doc)
        if value is not None:
            setattr(obj, name, value)
        if mode:
            obj.setEditorMode(name, mode)
        if output:
            obj.setPropertyStatus(name, "Output")

    return add


def add_validity_outputs(add, valid_doc):
    """The read-only Diagnostics and Valid properties the validity check writes."""
    add(
        "App::PropertyStringList",
        "Diagnostics",
        "Findings of the last validity check (code: message)",
        mode=1,
        output=True,
    )
    add("App::PropertyBool", "Valid", valid_doc, False, mode=1, output=True)
