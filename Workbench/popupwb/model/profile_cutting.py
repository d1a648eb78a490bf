"""Profiles cut into a mechanism's patches: card_scaffold.build applies them right after each
generator call, so validity, the shown shape and the cutting sheets all use the profiled patches
(profile_storage.py says what a mechanism stores; Scale mode scales from each part's size as generated).
"""

from popupwb.model.profile_storage import profiles_of


def part_size(scaffold, patch_id):
    """(width along u, height along v) of a patch in its profile frame (mm)."""
    from popupwb.core import popupcore

    frame = popupcore.profile_frame(scaffold, patch_id)
    patch = next(p for p in scaffold.patches if p.id == patch_id)
    us, vs = [], []
    for x in patch.outer:
        d = x - frame.origin
        us.append(float(d @ frame.u))
        vs.append(float(d @ frame.v))
    return (max(us) - min(us), max(vs) - min(vs))


def part_sizes(scaffold, label, patch_ids):
    """{part: (w, h)} of a mechanism's patches (named "<label>.<part>"), as generated."""
    sizes = {}
    for patch in scaffold.patches:
        if patch.id in patch_ids and patch.name.startswith(label + "."):
            try:
                sizes[patch.name[len(label) + 1 :]] = part_size(scaffold, patch.id)
            except ValueError:
                pass  # a patch without folds takes no profile
    return sizes


def fitted_outline(profile, mode, size):
    """(outer, holes) for a part now `size` (w, h): as stored for Clip; for Scale, u and v
    multiplied by the new size over the reference size."""
    outer, holes = profile["outer"], profile.get("holes", [])
    reference = profile.get("reference")
    if mode != "Scale" or reference is None:
        return outer, holes
    su, sv = size[0] / reference[0], size[1] / reference[1]

    def scaled(loop):
        return [(u * su, v * sv) for u, v in loop]

    return scaled(outer), [scaled(h) for h in holes]


def apply_profiles(obj, scaffold, sizes):
    """Cuts obj's parts to its profiles in `scaffold` (just generated; `sizes` from part_sizes).
    ValueError names the feature, the part and the profile."""
    import FreeCAD

    from popupwb.core import popupcore

    for part, profile in sorted(profiles_of(obj).items()):
        if part not in sizes:
            choices = ", ".join(sorted(sizes)) or "none"
            raise ValueError(
                f"{obj.Label}: profile part = '{part}', must be one of its parts ({choices})"
            )
        outer, holes = fitted_outline(profile, obj.ProfileMode, sizes[part])
        loops = [outer] + list(holes)
        short = next((i for i, loop in enumerate(loops) if len(loop) < 3), None)
        if short is not None:
            which = "outer loop" if short == 0 else f"hole {short}"
            raise ValueError(
                f"{obj.Label}: profile of {part}: its {which} has {len(loops[short])} points, "
                "needs 3 or more"
            )
        # Lists of (u, v) pairs convert to the core's Nx2 arrays.
        core_profile = popupcore.Profile(
            [list(q) for q in outer], [[list(q) for q in h] for h in holes], profile["name"]
        )
        try:
            applied = popupcore.apply_profile(scaffold, obj.Label, part, core_profile)
        except ValueError as error:  # DesignError: names the patch, the fold and the profile
            raise ValueError(f"{obj.Label}: {error}") from None
        for warning in applied.warnings:
            FreeCAD.Console.PrintWarning(f"{obj.Label}: {warning['message']}\n")
