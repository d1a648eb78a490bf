"""Checks the tests of PopUp objects in headless FreeCAD documents share (test_freecad_*.py,
test_profiles.py, test_mechanism_placement.py); the `popup` fixture of conftest.py gives them the
workbench's modules."""

import numpy as np


def recompute_ok(doc, *objects):
    """Recomputes `doc`; every one of `objects` must come out neither Invalid nor in Error."""
    doc.recompute()
    for obj in objects:
        assert "Invalid" not in obj.State and "Error" not in obj.State, obj.getStatusString()


def in_error(obj):
    return "Invalid" in obj.State or "Error" in obj.State


def assert_same_points(actual, expected, tolerance):
    """Same number of points, and every expected point has an actual one within `tolerance`."""
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    assert actual.shape == expected.shape
    distances = np.linalg.norm(actual[None, :, :] - expected[:, None, :], axis=2)
    assert distances.min(axis=1).max() < tolerance
