"""Profiles of mechanism features: outlines cut into their patches (docs/DESIGN.md, Profiles).
editing.py the maker's edits; what a mechanism stores (model/profile_storage.py) and the profiles
cut into the card's scaffold (model/profile_cutting.py) are the model's, below the features. `popupwb.profiles.set_profile(...)` and `set_profile_sketch(...)` are
the calls the commands echo and macros use."""

from popupwb.model.profile_cutting import apply_profiles, fitted_outline, part_size, part_sizes
from popupwb.profiles.editing import clear_profile_sketch, outline_area, profile_parts
from popupwb.profiles.editing import record_reference, set_profile, set_profile_sketch
from popupwb.profiles.editing import sketches_of
from popupwb.model.profile_storage import DEFLECTION, MODES, PROPERTIES, add_properties, key_of
from popupwb.model.profile_storage import profiles_of, sketch_loops, stored, write_stored

__all__ = [
    "apply_profiles",
    "fitted_outline",
    "part_size",
    "part_sizes",
    "clear_profile_sketch",
    "outline_area",
    "profile_parts",
    "record_reference",
    "set_profile",
    "set_profile_sketch",
    "sketches_of",
    "DEFLECTION",
    "MODES",
    "PROPERTIES",
    "add_properties",
    "key_of",
    "profiles_of",
    "sketch_loops",
    "stored",
    "write_stored",
]
