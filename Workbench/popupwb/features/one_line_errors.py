"""One line in the report view for a feature's expected error, a traceback only for a real bug.

FreeCAD 0.20.2 reports every exception leaving a FeaturePython's execute() the same way
(App/FeaturePython.cpp: Base::PyException::ThrowException): it formats the Python traceback with
PyTraceBack_Print, writes "<traceback><str(type)>: <message>" to the console, then marks the object
Invalid with the message as its status string. No exception type is exempt, and Python cannot set
an object's error state without raising.

PyTraceBack_Print prints nothing when sys.tracebacklimit is 0. So an expected error (a ValueError:
a bad property value, a DesignError of the core naming the property and its range) is re-raised as
InputError, which sets sys.tracebacklimit to 0 while it exists; FreeCAD drops its last reference
right after formatting the traceback, and the limit is restored then. Its class prints as "PopUp",
so the report view shows "PopUp: <object>: <property> = <value>, must be <range>". Any other
exception type keeps its traceback.
"""

import functools
import sys

from popupwb.progress import Cancelled

_UNSET = object()
_live = 0  # InputError instances alive (the limit is 0 while there is one)
_saved_limit = _UNSET


class _PrintsAsPopUp(type):
    # str(type) is what FreeCAD prints before the message.
    def __str__(cls):
        return "PopUp"


class InputError(ValueError, metaclass=_PrintsAsPopUp):
    """A ValueError whose message names the object, property, value and range; raise it at once
    (while it exists, Python prints tracebacks without their frames)."""

    def __init__(self, message):
        global _live, _saved_limit
        super().__init__(message)
        if _live == 0:
            _saved_limit = sys.__dict__.get("tracebacklimit", _UNSET)
            sys.tracebacklimit = 0
        _live += 1

    def __del__(self):
        global _live
        _live -= 1
        if _live == 0:
            if _saved_limit is _UNSET:
                sys.__dict__.pop("tracebacklimit", None)
            else:
                sys.tracebacklimit = _saved_limit


def one_line_errors(execute):
    """Decorates a proxy's execute(self, obj): a ValueError, or Cancel pressed in a progress
    dialog, leaves it as InputError (one line, object still marked Invalid with the message);
    other exceptions are untouched."""

    @functools.wraps(execute)
    def reporting_briefly(self, obj):
        try:
            return execute(self, obj)
        except InputError:
            raise
        except (ValueError, Cancelled) as error:
            message = str(error)
            del error  # no reference may outlive the raise (see InputError)
            raise InputError(message) from None

    return reporting_briefly
