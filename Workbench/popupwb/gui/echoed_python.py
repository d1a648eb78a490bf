"""Running a command's change as Python lines through FreeCADGui.doCommand, as Draft's commands do:
each line is shown in the Python console and recorded by the macro recorder, so what a toolbar
button did can be read, copied and replayed (`popupwb.make.make_tent_fold(...)`).
"""

import FreeCADGui


def object_expression(obj):
    """Python that finds `obj` again in the active document, also when a macro replays it."""
    return f"FreeCAD.ActiveDocument.getObject({obj.Name!r})"


def import_echoed(module):
    """Echoes `import <module>` every time: FreeCADGui.addModule echoes an import only the first
    time in a session, so a macro recorded later would lack it and fail on replay."""
    FreeCADGui.doCommand(f"import {module}")


def run_echoed(doc, transaction, lines, modules=("popupwb.make",)):
    """Imports `modules` and runs `lines` through FreeCADGui.doCommand as one undo transaction
    named `transaction` of `doc` (the active document), then recomputes (also echoed). Returns
    the objects the lines added to `doc`, in document order. An exception of a line aborts the
    transaction and propagates (the console shows the line that failed)."""
    for module in modules:
        import_echoed(module)
    before = {o.Name for o in doc.Objects}
    doc.openTransaction(transaction)
    try:
        for line in lines:
            FreeCADGui.doCommand(line)
        FreeCADGui.doCommand("FreeCAD.ActiveDocument.recompute()")
    except Exception:
        doc.abortTransaction()
        raise
    doc.commitTransaction()
    return [o for o in doc.Objects if o.Name not in before]
