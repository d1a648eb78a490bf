"""A model file read once per process while it is unchanged (popupwb/model/model_file.py): the
second read is a copy equal to the first, each caller's copy is its own (moving one moves no
other, the load warnings come along), and a file changed since is read again."""

import os

import numpy as np

from popupwb.model import model_file

TETRAHEDRON = """v 0 0 0
v 10 0 0
v 0 10 0
v 0 0 10
f 1 3 2
f 1 2 4
f 1 4 3
f 2 3 4
"""


def _write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return str(path)


def test_a_second_read_is_an_equal_copy_of_its_own(tmp_path):
    path = _write(tmp_path / "tetra.obj", TETRAHEDRON)
    first = model_file.load_model(path)
    second = model_file.load_model(path)
    assert first is not second
    np.testing.assert_array_equal(first.vertices, second.vertices)
    np.testing.assert_array_equal(first.triangles, second.triangles)
    assert first.source == second.source
    assert getattr(first, "warnings", None) == getattr(second, "warnings", None)
    second.vertices = second.vertices + 5.0  # as model_source.in_card_frame moves its copy
    np.testing.assert_array_equal(model_file.load_model(path).vertices, first.vertices)


def test_a_changed_file_is_read_again(tmp_path):
    path = _write(tmp_path / "tetra.obj", TETRAHEDRON)
    before = model_file.load_model(path)
    _write(path, TETRAHEDRON.replace("v 10 0 0", "v 20 0 0"))
    stat = os.stat(path)
    os.utime(
        path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9)
    )  # a new time, whatever the clock
    after = model_file.load_model(path)
    assert before.vertices[:, 0].max() == 10.0
    assert after.vertices[:, 0].max() == 20.0
