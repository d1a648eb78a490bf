"""A model file read by popupcore.load_model, kept for the next read of the same unchanged file in
this process: `popup fit` reads its model, then its cutting sheets read the same file again for
the artwork (model_source.card_model). Only the last file read is kept; every caller gets its own
copy (with the .warnings load_model hangs on it), so changing one changes no other.
"""

import os

_last = None  # ((real path, size, modification time), ModelMesh as load_model read it)


def _identity(path):
    stat = os.stat(path)
    return (os.path.realpath(path), stat.st_size, stat.st_mtime_ns)


def _copy(model):
    copied = model.copy()
    for name, value in vars(model).items():  # .warnings
        setattr(copied, name, list(value) if isinstance(value, list) else value)
    return copied


def load_model(path):
    """popupcore.load_model(path), or a copy of what it gave for this unchanged file last time.
    Raises what load_model raises (ValueError naming the file and what is wrong)."""
    global _last
    from popupwb.core import popupcore

    try:
        identity = _identity(path)
    except OSError:
        return popupcore.load_model(path)  # load_model names what is wrong with the path
    if _last is None or _last[0] != identity:
        _last = (identity, popupcore.load_model(path))
    return _copy(_last[1])
