"""report.json of `popup animate` (documented in docs/MOTION_REPORT.md): per chain the mapping
chosen, its motion error E_m (eq 6.6, divided by the character's projected bounding-box diagonal
on the card), weight, status (animated, merged or stationary) and why, with its target and
achieved paths; the vertex-weighted total; validity; the mechanisms; stage timings. Plain JSON
through popup fit's report helpers: non-finite numbers become null, arrays nested lists.
"""

import numpy as np

from popupwb.fitting.fit_report import plain, timings, write_report  # noqa: F401

FORMAT = "popup-motion-report"
VERSION = 1


def chain_entry(chain):
    """One ChainReport: {name, mechanism (the mapping), mechanisms, error, error_mm, floor,
    floor_mm, bound, bound_mm, bound_mechanism, weight, status, reason, s, target, achieved}."""
    return {
        "name": chain.name,
        "mechanism": chain.mapping,
        "mechanisms": list(chain.mechanisms),
        "error": float(chain.error),
        "error_mm": float(chain.error_mm),
        "floor": float(chain.floor),
        "floor_mm": float(chain.floor_mm),
        "bound": float(chain.bound),
        "bound_mm": float(chain.bound_mm),
        "bound_mechanism": str(chain.bound_mechanism),
        "weight": float(chain.weight),
        "status": chain.status,
        "reason": chain.reason,
        "s": np.asarray(chain.s, dtype=float).reshape(-1),
        "target": np.asarray(chain.target, dtype=float).reshape(-1, 2),
        "achieved": np.asarray(chain.achieved, dtype=float).reshape(-1, 2),
    }


def mechanism_entry(fitted):
    return {
        "type": fitted.type,
        "name": fitted.name,
        "host": fitted.host,
        "parameters": {k: float(v) for k, v in sorted(dict(fitted.parameters).items())},
    }


def _animation_entry(animation_file, animation):
    mesh = animation.mesh if animation is not None else None
    return {
        "file": animation_file,
        "bones": [{"name": n, "parent": int(p)} for n, p in animation.bones] if animation else [],
        "frames": int(animation.frames) if animation is not None else 0,
        "mesh_vertices": int(len(mesh.vertices)) if mesh is not None else 0,
    }


def _targets_entry(targets):
    return {
        "first_frame": int(targets.first_frame),
        "last_frame": int(targets.last_frame),
        "diagonal_mm": float(targets.diagonal_mm),
        "travel_removed_mm": float(targets.travel_removed_mm),
        "window": dict(targets.window),
        "animation_to_card": np.asarray(targets.animation_to_card, dtype=float),
        "chains": [
            {
                "name": c.name,
                "bones": [int(b) for b in c.bones],
                "parent_chain": int(c.parent_chain),
                "weight": float(c.weight),
                "pruned": list(c.pruned),
                "reach": float(c.reach),
            }
            for c in targets.chains
        ],
    }


def build_report(*, animation_file, animation, options, result, validity, stages, total_s, files):
    """The report dict. `result` is the popupcore.MotionResult (None when no design was found),
    `validity` the check of the built card (popupwb.validity.run_check's dict, or None), `stages`
    [(stage, seconds)] of every stage run, `files` {role: path} written."""
    chains = [chain_entry(c) for c in result.chains] if result is not None else []
    valid = bool(result is not None and result.valid and validity is not None and validity["valid"])
    report = {
        "format": FORMAT,
        "version": VERSION,
        "animation": _animation_entry(animation_file, animation),
        "valid": valid,
        "chains": chains,
        "weighted_error": float(result.weighted_error) if result is not None else None,
        "weighted_floor": float(result.weighted_floor) if result is not None else None,
        "weighted_bound": (float(result.weighted_bound) if result is not None else None),
        "iterations": int(result.iterations) if result is not None else 0,
        "cost": float(result.cost) if result is not None else None,
        "timings_s": timings(stages, total_s),
        "mechanisms": [mechanism_entry(m) for m in result.mechanisms] if result else [],
        "number_of_mechanisms": len(result.mechanisms) if result is not None else 0,
        "merged": [c["name"] for c in chains if c["status"] == "merged"],
        "stationary": [c["name"] for c in chains if c["status"] == "stationary"],
        "card": (
            {"width_mm": float(result.card.width), "depth_mm": float(result.card.depth)}
            if result is not None
            else None
        ),
        "targets": _targets_entry(result.targets) if result is not None else None,
        "core_valid": bool(result.valid) if result is not None else False,
        "validity": (
            {"valid": bool(validity["valid"]), "diagnostics": list(validity["diagnostics"])}
            if validity is not None
            else None
        ),
        "diagnostics": list(getattr(result, "diagnostics", None) or []) if result else [],
        "options": options,
        "files": files,
    }
    return plain(report)
