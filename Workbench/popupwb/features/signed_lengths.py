"""Lengths the user types are signed properties (App::PropertyDistance), so that a wrong value
such as -1 mm reaches the core's range check and is reported with its range. FreeCAD's
App::PropertyLength would store it as 0 without a word. Files written before this kept
PropertyLength: they are converted on load, keeping the value and any expression bound to it.
"""

SIGNED = "App::PropertyDistance"
UNSIGNED = "App::PropertyLength"


def make_signed(obj, names):
    """Turns each of `names` that is still an App::PropertyLength on `obj` into a signed
    App::PropertyDistance with the same value, group, tooltip and expression."""
    for name in names:
        if name not in obj.PropertiesList or obj.getTypeIdOfProperty(name) != UNSIGNED:
            continue
        value = getattr(obj, name).Value
        group = obj.getGroupOfProperty(name)
        doc = obj.getDocumentationOfProperty(name)
        expressions = [(path, text) for path, text in obj.ExpressionEngine if path == name]
        obj.removeProperty(name)
        obj.addProperty(SIGNED, name, group, doc)
        setattr(obj, name, value)
        for path, text in expressions:
            obj.setExpression(path, text)
