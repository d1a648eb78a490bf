"""A feature in error shows nothing rather than its last good shape."""

import functools


def clears_shape_on_error(execute):
    """Decorates a proxy's execute(self, obj): when it raises, obj.Shape is emptied (keeping
    obj.Placement, which assigning a shape resets) and the error goes on to FreeCAD, which marks
    the object in error in the tree. Without it a mechanism whose parameter the core refuses
    would keep showing patches of a design that no longer exists."""

    @functools.wraps(execute)
    def wrapped(self, obj):
        try:
            return execute(self, obj)
        except Exception:
            import Part

            placement = obj.Placement
            obj.Shape = Part.Shape()
            obj.Placement = placement
            raise

    return wrapped
