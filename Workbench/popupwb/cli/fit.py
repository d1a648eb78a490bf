"""`popup fit <model> --out DIR`: a pop-up designed from a 3D model (issue 12), written as
DIR/design.FCStd (a PopUpCard with mechanism features and the source model), DIR/report.json
(docs/FIT_REPORT.md), DIR/preview.png and, for a valid design, the cutting sheets in DIR/sheets/
exactly as `popup sheet` writes them (the same code path).

Progress goes to stderr, the files written and the verdict to stdout. Exit 0 for a valid design
with usable sheets, 1 when no valid design was found (the report and the document still say what
was tried), 2 for input that cannot be used (a one-line error naming the file or flag).

What it shares with `popup animate` (flags, checks, sheets, report, exit code) is in
design_steps.py.
"""

import math
import os
import shutil

from popupwb import option_fields
from popupwb.cli import design_steps as steps
from popupwb.cli.common import EXIT_INVALID, InputError, import_core, import_freecad
from popupwb.cli.common import stdout_to_stderr
from popupwb.cli.design_steps import DESIGN_FILE, REPORT_FILE, SHEETS_DIR
from popupwb.cli.designs import is_document
from popupwb.fitting.fit_report import plain

PREVIEW_FILE = "preview.png"


def add_parser(sub):
    from popupwb.fitting.fit_run import DEFAULT_DETAIL

    core = option_fields.fields("FitOptions")  # ranges, defaults and docs: the core's
    fit = sub.add_parser(
        "fit",
        help="design a pop-up from a 3D model: FreeCAD document, report, preview and sheets",
        description="Fit rectangular and triangular prisms to a 3D model (STL, OBJ, PLY, OFF, "
        "glTF/GLB, FBX, Collada, 3MF, or the meshes and Part shapes of an .FCStd), map them to "
        "box, step, v- and tent folds on a card, keep what the validity check accepts and write "
        f"DIR/{DESIGN_FILE}, DIR/{REPORT_FILE}, DIR/{PREVIEW_FILE} and DIR/{SHEETS_DIR}/ (the "
        "files of popup sheet). Exit 0 valid, 1 no valid design found, 2 unusable input.",
    )
    fit.add_argument("model", help="model file, or an .FCStd holding Mesh or Part objects")
    steps.add_out_flag(fit)
    option_fields.add_flag(fit, "--max-mechanisms", core.get("max_mechanisms"), "N")
    steps.add_seed_flag(fit, core.get("seed"))
    fit.add_argument(
        "--detail",
        type=float,
        default=DEFAULT_DETAIL,
        metavar="D",
        help=f"0 coarse (few large prisms) to 1 fine (smaller prisms too); default "
        f"{DEFAULT_DETAIL:g}",
    )
    option_fields.add_flag(fit, "--min-part", core.get("min_part_mm"), "MM")
    depth_layers = core.get("depth_layers")
    fit.add_argument(
        "--no-depth-layers",
        action="store_true",
        help="keep box folds' fronts, backs and tops flat"
        + (f" (on by default: {depth_layers.doc})" if depth_layers else ""),
    )
    steps.add_paper_flag(fit)
    for name in ("up", "facing"):
        option_fields.add_vector_flag(fit, f"--{name}", core.get(name), "FitOptions")
    fit.set_defaults(run=run)
    return fit


def _options(args, fit_run):
    """The FitOptions, the paper and the directions from the flags; InputError naming the flag."""
    core = option_fields.fields("FitOptions")
    try:
        option_fields.check(core.get("max_mechanisms"), args.max_mechanisms, "--max-mechanisms")
        option_fields.check(core.get("seed"), args.seed, "--seed")
        option_fields.check(core.get("min_part_mm"), args.min_part, "--min-part")
    except ValueError as e:
        raise InputError(str(e))
    if not (math.isfinite(args.detail) and 0.0 <= args.detail <= 1.0):
        raise InputError(f"--detail {args.detail:g}: must be from 0 (coarse) to 1 (fine)")
    up, facing = steps.directions(args, fit_run.direction, ("up", "facing"))
    paper, card_size = steps.paper_and_card_size(args, fit_run.card_size_for_paper)
    with steps.core_range_checks():
        options = fit_run.fit_options(
            args.max_mechanisms,
            args.seed,
            up,
            facing,
            args.detail,
            card_size,
            min_part_mm=args.min_part,
            depth_layers=not args.no_depth_layers,
            flags=steps.flags_given(args, {"min_part_mm": "min_part", "up": "up"}),
        )
    return options, paper


def run(args):
    """The `popup fit` command."""
    say = steps.Say("fit")
    popupcore = import_core()
    from popupwb.fitting import fit_run

    steps.require_core(
        popupcore, ("load_model", "clean_model", "FitOptions", "fit_design", "fit_metrics")
    )
    options, paper = _options(args, fit_run)
    steps.check_out_and_input(args, args.model)

    stages = fit_run.Stages(say)
    with stages.stage("load", f"reading {args.model}"):
        with stdout_to_stderr():
            if is_document(args.model):
                import_freecad()
            try:
                model, what = fit_run.read_model(args.model)
            except (ValueError, RuntimeError, OSError) as e:
                raise InputError(steps.named(args.model, e))
    say(f"{what}: {len(model.vertices)} vertices, {len(model.triangles)} triangles")
    # A texture that cannot be read leaves the model usable, shaded grey on the sheets.
    model_warnings = list(getattr(model, "warnings", None) or [])
    for d in model_warnings:
        say(f"warning: {d['code']}: {d['message']}")
    with stages.stage("clean", "cleaning the mesh"):
        try:
            model, repairs = fit_run.clean_model(model)
        except ValueError as e:
            raise InputError(steps.named(args.model, e))
    done = {k: v for k, v in repairs.items() if v and not isinstance(v, bool)}
    if done:
        say("repaired: " + ", ".join(f"{k} {v}" for k, v in sorted(done.items())))

    os.makedirs(args.out, exist_ok=True)
    files = {}
    common = dict(
        model_file=os.path.abspath(args.model),
        model=model,
        model_repairs=repairs,
        model_warnings=model_warnings,
        options=fit_run.options_dict(options),
    )
    say(f"fitting (seed {options.seed}, at most {options.max_mechanisms} mechanisms)")
    steps.import_sheet_libraries_meanwhile()
    try:
        result = fit_run.fit(model, options)
    except popupcore.DesignError as e:
        steps.raise_unless_no_design(e, args.model)
        report = _no_design_report(common, stages)
        return steps.report_no_design(args, args.model, e, report, files, say)
    stages.add(result.timings.stages)
    say(
        f"fitted {len(result.primitives)} primitive(s), {len(result.mechanisms)} mechanism(s); "
        f"{len(result.repairs)} repair(s)"
    )

    design = _write_design(args, result, model, options, stages, files, say)
    report = _report(common, result, design, stages, files)
    valid = design["validity"]["valid"] and result.pops_up
    status = steps.sheets_of_valid_design(args, paper, report, valid, files, stages, say)
    if _outlines_broke_the_sheets(status, valid, result, files):
        # The round trip found an outlined piece off the design (docs/DESIGN.md, "When outlined
        # sheets do not verify"): the same mechanisms without outlines, said in the report.
        say("the outlined design's sheets did not verify: the same design without outlines")
        shutil.rmtree(files.pop("sheets"), ignore_errors=True)
        design["measured"]()  # the outlined design's measure ends before the refit starts
        options.outlines = False
        result = fit_run.fit(model, options)
        stages.add(result.timings.stages)
        design = _write_design(args, result, model, options, stages, files, say)
        report = _report(common, result, design, stages, files)
        report["repairs"].append(_OUTLINES_DROPPED)
        valid = design["validity"]["valid"] and result.pops_up
        status = steps.sheets_of_valid_design(args, paper, report, valid, files, stages, say)
    report["metrics"] = plain(design["measured"]())
    status = steps.finish(args, report, status, files, stages, say, _print_summary)
    if not result.mechanisms:
        print(f"no mechanism could be fitted to {args.model}")
        return EXIT_INVALID
    return status


_OUTLINES_DROPPED = {
    "mechanism": "outlines",
    "action": "dropped",
    "reason": "the cutting sheets of the outlined design did not verify (the round trip found a "
    "piece off the design): the same mechanisms without the model's outlines",
}


def _outlines_broke_the_sheets(status, valid, result, files):
    """A valid design with outlines whose written sheets did not verify."""
    return status != steps.EXIT_VALID and valid and "sheets" in files and bool(result.profiles)


def _write_design(args, result, model, options, stages, files, say):
    """Builds, checks, measures, saves and previews the FreeCAD design; returns what the report
    needs from it."""
    from popupwb.fitting import fit_run
    from popupwb.model.model_source import transformed
    from popupwb.fitting.preview import scaffold_outlines, write_preview

    with steps.design_document("PopUpFit") as doc:
        from popupwb.model import card_scaffold
        from popupwb.fitting.design_from_fit import build_design

        design, checked = steps.build_and_check(
            stages,
            lambda: build_design(doc, result, model, source_file=_model_file(args.model)),
        )
        say(f"wrote {steps.save_design(doc, args.out, files)}")
        built = card_scaffold.for_card(design.card)
        if built.card_error or built.errors:
            problems = [built.card_error] if built.card_error else []
            raise RuntimeError(
                "the fitted design does not build in FreeCAD: "
                + "; ".join(problems + list(built.errors.values()))
            )
        scaffold = built.scaffold
        measured = lambda: None  # a card without mechanisms has no pop-up to measure
        # On a plate (a terrain slab, a print bed) the pop-up is what stands on it.
        shown = fit_run.standing_model(model, result)
        if result.mechanisms:
            # On its own thread: the preview and the sheets are drawn meanwhile.
            measured = stages.background(
                "metrics",
                "measuring the pop-up against the model",
                lambda: fit_run.measure(shown, result, scaffold, options),
            )
        with stages.stage("preview", "drawing the preview"):
            outlines, card_patches = scaffold_outlines(scaffold)
            files["preview"] = write_preview(
                os.path.join(args.out, PREVIEW_FILE),
                transformed(shown.vertices, result.model_to_card),
                shown.triangles,
                outlines,
                card_patches,
                title=f"{os.path.basename(args.model)}: {len(result.mechanisms)} mechanism(s)",
            )
        say(f"wrote {files['preview']}")
        return {
            "validity": checked,
            "measured": measured,
            "patches": len(scaffold.patches),
        }


def _model_file(path):
    """The model file the card keeps for its artwork: a mesh file, not a FreeCAD document (its
    meshes and shapes have no colours of their own to print)."""
    return "" if path.lower().endswith(".fcstd") else os.path.abspath(path)


def _report(common, result, design, stages, files):
    from popupwb.fitting.fit_report import build_report

    return build_report(
        **common,
        result=result,
        validity=design["validity"],
        metrics=None,  # run() sets it once the measure on its thread is done
        patches=design["patches"],
        stages=stages.timings,
        total_s=stages.total(),
        files=files,
    )


def _no_design_report(common, stages):
    from popupwb.fitting.fit_report import build_report

    return build_report(
        **common,
        result=None,
        validity=None,
        metrics=None,
        patches=0,
        stages=stages.timings,
        total_s=stages.total(),
        files={},
    )


def _print_summary(report, files):
    steps.print_written(files, ("design", "preview", "report"))
    kinds = ", ".join(f"{m['name']} ({m['type']} on {m['host']})" for m in report["mechanisms"])
    print(f"{report['number_of_mechanisms']} mechanism(s): {kinds or 'none'}")
    metrics = report.get("metrics") or {}
    hausdorff = (metrics.get("hausdorff") or {}).get("model_to_popup") or {}
    if hausdorff:
        print(
            "model to pop-up, / diagonal {:.1f} mm: mean {}, rms {}, max {}; volume difference "
            "{}; coverage {}".format(
                metrics.get("diagonal_mm") or 0.0,
                steps.g(hausdorff.get("mean")),
                steps.g(hausdorff.get("rms")),
                steps.g(hausdorff.get("max")),
                steps.g(metrics.get("volume_difference")),
                steps.g(metrics.get("coverage")),
            )
        )
    print("valid design" if report["valid"] else "no valid design found")
