"""report.json of `popup fit` (documented in docs/FIT_REPORT.md): what was fitted, whether it is
valid, how close it is to the model, how the model was placed on the card, and what each stage
took. Plain JSON: non-finite numbers become null, matrices nested lists, in a fixed key order.
"""

import json
import math

import numpy as np

FORMAT = "popup-fit-report"
VERSION = 1


def plain(value):
    """`value` with numpy arrays and scalars as lists and numbers, NaN and infinities as None."""
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return plain(value.tolist())
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else None
    return value


def mechanism_entry(fitted):
    """One FittedMechanism as {type, name, host, parameters, primitive, coverage_error}."""
    return {
        "type": fitted.type,
        "name": fitted.name,
        "host": fitted.host,
        "parameters": {k: float(v) for k, v in sorted(dict(fitted.parameters).items())},
        "primitive": fitted.primitive,
        "coverage_error": float(fitted.coverage_error),
    }


def primitive_entry(primitive):
    return {
        "kind": primitive.kind,
        "host": primitive.host,
        "inliers": int(primitive.inliers),
        "corners": np.asarray(primitive.corners, dtype=float).reshape(-1, 3),
    }


def timings(stages, total):
    """{stage: seconds, ..., "total": total}; a stage met twice adds up."""
    table = {}
    for stage, seconds in stages:
        table[stage] = table.get(stage, 0.0) + float(seconds)
    table["total"] = float(total)
    return table


def profile_entry(profile):
    """{mechanism, part, area_mm2, area_before_mm2, points, holes} of a FittedProfile."""
    return {
        "mechanism": profile.mechanism,
        "part": profile.part,
        "area_mm2": float(profile.area),
        "area_before_mm2": float(profile.area_before),
        "points": int(len(profile.outer)),
        "holes": int(len(profile.holes)),
    }


def depth_layer_entry(layer):
    """{box, face, depth_mm, area_mm2, kept, mechanism, reason, mean_before_mm, mean_after_mm}
    of a FittedDepthLayer (the means are 0 when the layer was dropped before measuring)."""
    return {
        "box": layer.box,
        "face": layer.face,
        "depth_mm": float(layer.depth),
        "area_mm2": float(layer.area),
        "kept": bool(layer.kept),
        "mechanism": layer.mechanism,
        "reason": layer.reason,
        "mean_before_mm": float(layer.mean_before_mm),
        "mean_after_mm": float(layer.mean_after_mm),
    }


def plate_entry(plate):
    """The plate that became the page (model units along the model's up), or None."""
    if plate is None:
        return None
    return {
        "up": list(plate.up),
        "top": float(plate.top),
        "thickness": float(plate.thickness),
        "top_area": float(plate.top_area),
    }


def build_report(
    *,
    model_file,
    model,
    model_repairs,
    options,
    model_warnings=(),
    result,
    validity,
    metrics,
    patches,
    stages,
    total_s,
    files,
):
    """The report dict. `result` is the popupcore.FitResult (None when the fit found no design),
    `validity` the check of the built card (popupwb.validity.run_check's dict, or None),
    `metrics` popupcore.fit_metrics' dict (or None), `patches` the card's patch count, `stages`
    [(stage, seconds)] of every stage run, `files` {role: path} written, `model_warnings` the
    diagnostic dicts of reading the model (load_model's .warnings: an unreadable texture)."""
    mechanisms = [mechanism_entry(m) for m in result.mechanisms] if result is not None else []
    valid = bool(result is not None and result.valid and validity is not None and validity["valid"])
    report = {
        "format": FORMAT,
        "version": VERSION,
        "model": {
            "file": model_file,
            "vertices": int(len(model.vertices)) if model is not None else 0,
            "triangles": int(len(model.triangles)) if model is not None else 0,
            "warnings": [
                {key: d[key] for key in ("severity", "code", "message")} for d in model_warnings
            ],
        },
        "valid": valid,
        "mechanisms": mechanisms,
        "number_of_mechanisms": len(mechanisms),
        "number_of_patches": int(patches),
        "metrics": metrics,
        "model_to_card": np.asarray(result.model_to_card) if result is not None else None,
        "timings_s": timings(stages, total_s),
        "repairs": (
            [
                {"mechanism": r.mechanism, "action": r.action, "reason": r.reason}
                for r in result.repairs
            ]
            if result is not None
            else []
        ),
        "model_repairs": dict(model_repairs or {}),
        "card": (
            {"width_mm": float(result.card.width), "depth_mm": float(result.card.depth)}
            if result is not None
            else None
        ),
        "fit_coverage": float(result.coverage) if result is not None else None,
        "fit": (
            {
                name: getattr(result, name)
                for name in (
                    "coverage",
                    "coverage_error",
                    "symmetry_error",
                    "ransac_draws",
                    "outer_samples",
                    "inner_samples",
                    "turned_faces",
                )
                if hasattr(result, name)
            }
            if result is not None
            else None
        ),
        "plate": plate_entry(getattr(result, "plate", None)) if result is not None else None,
        "diagnostics": list(getattr(result, "diagnostics", None) or []) if result else [],
        "primitives": [primitive_entry(p) for p in result.primitives] if result is not None else [],
        "profiles": (
            [profile_entry(p) for p in getattr(result, "profiles", ())]
            if result is not None
            else []
        ),
        "depth_layers": (
            [depth_layer_entry(x) for x in getattr(result, "depth_layers", ())]
            if result is not None
            else []
        ),
        "validity": (
            {"valid": bool(validity["valid"]), "diagnostics": list(validity["diagnostics"])}
            if validity is not None
            else None
        ),
        "options": options,
        "files": files,
    }
    return plain(report)


def write_report(report, path):
    with open(path, "w") as f:
        json.dump(report, f, indent=2, allow_nan=False)
        f.write("\n")
    return path
