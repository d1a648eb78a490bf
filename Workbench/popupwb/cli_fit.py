"""`popup fit <model> --out DIR`: a pop-up designed from a 3D model (issue 12), written as
DIR/design.FCStd (a PopUpCard with mechanism features and the source model), DIR/report.json
(docs/FIT_REPORT.md), DIR/preview.png and, for a valid design, the cutting sheets in DIR/sheets/
exactly as `popup sheet` writes them (the same code path).

Progress goes to stderr, the files written and the verdict to stdout. Exit 0 for a valid design
with usable sheets, 1 when no valid design was found (the report and the document still say what
was tried), 2 for input that cannot be used (a one-line error naming the file or flag).

cli.py keeps the parser; this module is the command, handed the cli module for its shared helpers
(InputError, the FreeCAD import, cmd_sheet) so that `python -m popupwb.cli` does not load a
second copy of it.
"""

import math
import os
import sys

DESIGN_FILE = "design.FCStd"
REPORT_FILE = "report.json"
PREVIEW_FILE = "preview.png"
SHEETS_DIR = "sheets"
DEFAULT_PAPER = "A4"


def add_parser(sub, max_mechanisms):
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
    fit.add_argument("--out", required=True, metavar="DIR", help="folder for the files")
    fit.add_argument(
        "--max-mechanisms",
        type=int,
        default=8,
        metavar="N",
        help=f"at most this many mechanisms, 1 to {max_mechanisms} (default 8)",
    )
    fit.add_argument(
        "--seed", type=int, default=1, metavar="S", help="random seed; same seed, same design"
    )
    fit.add_argument(
        "--detail",
        type=float,
        default=0.5,
        metavar="D",
        help="0 coarse (few large prisms) to 1 fine (smaller prisms too); default 0.5",
    )
    fit.add_argument(
        "--min-part",
        type=float,
        metavar="MM",
        help="shortest glued crease a mechanism may have, mm (default: what the sheets' "
        "narrowest glue tab needs; 0 allows any, and the sheets may then refuse a tab)",
    )
    fit.add_argument(
        "--no-depth-layers",
        action="store_true",
        help="keep box folds' fronts, backs and tops flat: no nested mechanisms for the parts "
        "of the model standing proud of them (thesis §5.1.3)",
    )
    fit.add_argument(
        "--paper",
        help=f"paper of the sheets, A4, A3, Letter, Tabloid or WxH mm; the card is the largest "
        f"that fits on it (default: the PopUp preference, else {DEFAULT_PAPER})",
    )
    fit.add_argument(
        "--up",
        metavar="X,Y,Z",
        help="model direction that becomes up (default: from the model's normals)",
    )
    fit.add_argument(
        "--facing",
        metavar="X,Y,Z",
        help="model direction that faces the viewer of the open card (default: from the model)",
    )
    return fit


class _Say:
    """Progress lines on stderr."""

    def __call__(self, text):
        print(f"popup fit: {text}", file=sys.stderr, flush=True)


def _options(args, cli, fit_run):
    """The FitOptions, the paper and the directions from the flags; InputError naming the flag."""
    if not 1 <= args.max_mechanisms <= fit_run.MAX_MECHANISMS:
        raise cli.InputError(
            f"--max-mechanisms {args.max_mechanisms}: must be 1 to {fit_run.MAX_MECHANISMS}"
        )
    if args.seed < 0:
        raise cli.InputError(f"--seed {args.seed}: must be >= 0")
    if not (math.isfinite(args.detail) and 0.0 <= args.detail <= 1.0):
        raise cli.InputError(f"--detail {args.detail:g}: must be from 0 (coarse) to 1 (fine)")
    if args.min_part is not None and not (math.isfinite(args.min_part) and args.min_part >= 0):
        raise cli.InputError(f"--min-part {args.min_part:g}: must be a length >= 0 mm")
    try:
        up = fit_run.direction(args.up, "--up") if args.up is not None else None
        facing = fit_run.direction(args.facing, "--facing") if args.facing is not None else None
    except ValueError as e:
        raise cli.InputError(str(e))
    paper = args.paper or cli._preferences().sheet_paper or DEFAULT_PAPER
    try:
        card_size = fit_run.card_size_for_paper(paper)
    except ValueError as e:
        raise cli.InputError(f"--paper {paper}: {cli._one_line(e)}")
    try:
        options = fit_run.fit_options(
            args.max_mechanisms, args.seed, up, facing, args.detail, card_size
        )
        if args.min_part is not None:
            options.min_part_mm = args.min_part
        options.depth_layers = not args.no_depth_layers
    except ValueError as e:  # the core's own range checks of the same values
        raise cli.InputError(cli._one_line(e))
    return options, paper


def _diagnostic_codes(error):
    return [d.get("code") for d in getattr(error, "diagnostics", None) or []]


def _write_outcome(out, report, files, say):
    from popupwb.fitting.fit_report import write_report

    files["report"] = os.path.join(out, REPORT_FILE)
    report["files"] = dict(files)
    write_report(report, files["report"])
    say(f"wrote {files['report']}")


def run(args, cli):
    """The `popup fit` command; `cli` is the popupwb.cli module that parsed `args`."""
    say = _Say()
    popupcore = cli._import_core()
    from popupwb.fitting import fit_run

    for needed in ("load_model", "clean_model", "FitOptions", "fit_design", "fit_metrics"):
        if not hasattr(popupcore, needed):
            raise RuntimeError(f"popupcore.{needed} is missing: rebuild (make build)")
    options, paper = _options(args, cli, fit_run)
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        raise cli.InputError(f"--out {args.out}: is a file, not a folder")
    why = cli.unreadable(args.model)
    if why:
        raise cli.InputError(why)

    stages = fit_run.Stages(say)
    with stages.stage("load", f"reading {args.model}"):
        with cli._stdout_to_stderr():
            if cli.is_document(args.model):
                cli._import_freecad()
            try:
                model, what = fit_run.read_model(args.model)
            except (ValueError, RuntimeError, OSError) as e:
                raise cli.InputError(_named(args.model, e, cli))
    say(f"{what}: {len(model.vertices)} vertices, {len(model.triangles)} triangles")
    with stages.stage("clean", "cleaning the mesh"):
        try:
            model, repairs = fit_run.clean_model(model)
        except ValueError as e:
            raise cli.InputError(_named(args.model, e, cli))
    done = {k: v for k, v in repairs.items() if v and not isinstance(v, bool)}
    if done:
        say("repaired: " + ", ".join(f"{k} {v}" for k, v in sorted(done.items())))

    os.makedirs(args.out, exist_ok=True)
    files = {}
    common = dict(
        model_file=os.path.abspath(args.model),
        model=model,
        model_repairs=repairs,
        options=fit_run.options_dict(options),
    )
    say(f"fitting (seed {options.seed}, at most {options.max_mechanisms} mechanisms)")
    try:
        result = fit_run.fit(model, options)
    except popupcore.DesignError as e:
        if "no_design_found" not in _diagnostic_codes(e):
            raise cli.InputError(_named(args.model, e, cli))
        say(f"no valid design: {cli._one_line(e)}")
        report = _no_design_report(common, stages, e)
        _write_outcome(args.out, report, files, say)
        print(f"no valid design found for {args.model}; see {files['report']}")
        return cli.EXIT_INVALID
    stages.add(result.timings)
    say(
        f"fitted {len(result.primitives)} primitive(s), {len(result.mechanisms)} mechanism(s); "
        f"{len(result.repairs)} repair(s)"
    )

    design = _write_design(args, cli, result, model, options, stages, files, say)
    report = _report(common, result, design, stages, files)
    if design["validity"]["valid"] and result.valid and result.mechanisms:
        status = _write_sheets(args, cli, paper, files, stages, say)
    else:
        status = cli.EXIT_INVALID
        for d in report.get("diagnostics") or []:
            say(f"{d.get('severity', 'error')}: {d.get('code')}: {d.get('message')}")
        say("no valid design found: no sheets written")
    report["timings_s"] = _report_timings(stages)
    report["sheets_ok"] = bool(report["valid"] and status == cli.EXIT_VALID)
    _write_outcome(args.out, report, files, say)
    _print_summary(report, files)
    if report["valid"] and status != cli.EXIT_VALID:
        print(
            "but its cutting sheets have errors (listed above; "
            f"{os.path.join(files['sheets'], 'report.json')})"
        )
    if not result.mechanisms:
        print(f"no mechanism could be fitted to {args.model}")
        return cli.EXIT_INVALID
    return status if report["valid"] else cli.EXIT_INVALID


def _named(path, error, cli):
    text = cli._one_line(error)
    return text if path in text or os.path.basename(path) in text else f"{path}: {text}"


def _write_design(args, cli, result, model, options, stages, files, say):
    """Builds, checks, measures, saves and previews the FreeCAD design; returns what the report
    needs from it."""
    from popupwb.fitting import fit_run
    from popupwb.fitting.model_source import transformed
    from popupwb.fitting.preview import scaffold_outlines, write_preview

    with cli._stdout_to_stderr():
        FreeCAD = cli._import_freecad()
        from popupwb import card_scaffold, validity
        from popupwb.fitting.design_from_fit import build_design

        doc = FreeCAD.newDocument("PopUpFit")
        try:
            with stages.stage("document", "building the card's features"):
                design = build_design(doc, result, model, source_file=_model_file(args.model))
            with stages.stage("check", "checking the card's validity"):
                checked = validity.run_check(design.card)
            files["design"] = os.path.join(args.out, DESIGN_FILE)
            doc.saveAs(os.path.abspath(files["design"]))
            say(f"wrote {files['design']}")
            built = card_scaffold.for_card(design.card)
            if built.card_error or built.errors:
                problems = [built.card_error] if built.card_error else []
                raise RuntimeError(
                    "the fitted design does not build in FreeCAD: "
                    + "; ".join(problems + list(built.errors.values()))
                )
            scaffold = built.scaffold
            metrics = None  # a card without mechanisms has no pop-up to measure
            if result.mechanisms:
                with stages.stage("metrics", "measuring the pop-up against the model"):
                    metrics = fit_run.measure(model, result, scaffold, options)
            with stages.stage("preview", "drawing the preview"):
                outlines, card_patches = scaffold_outlines(scaffold)
                files["preview"] = write_preview(
                    os.path.join(args.out, PREVIEW_FILE),
                    transformed(model.vertices, result.model_to_card),
                    model.triangles,
                    outlines,
                    card_patches,
                    title=f"{os.path.basename(args.model)}: {len(result.mechanisms)} mechanism(s)",
                )
            say(f"wrote {files['preview']}")
            return {
                "validity": checked,
                "metrics": metrics,
                "patches": len(scaffold.patches),
            }
        finally:
            FreeCAD.closeDocument(doc.Name)


def _model_file(path):
    """The model file the card keeps for its artwork: a mesh file, not a FreeCAD document (its
    meshes and shapes have no colours of their own to print)."""
    return "" if path.lower().endswith(".fcstd") else os.path.abspath(path)


def _write_sheets(args, cli, paper, files, stages, say):
    """`popup sheet DIR/design.FCStd --out DIR/sheets --paper PAPER`, through cmd_sheet itself."""
    sheets = os.path.join(args.out, SHEETS_DIR)
    with stages.stage("sheets", f"laying out the cutting sheets on {paper}"):
        sheet_args = cli.build_parser().parse_args(
            ["sheet", files["design"], "--out", sheets, "--paper", paper]
        )
        status = sheet_args.run(sheet_args)
    files["sheets"] = sheets
    return status


def _report_timings(stages):
    from popupwb.fitting.fit_report import timings

    return timings(stages.timings, stages.total())


def _report(common, result, design, stages, files):
    from popupwb.fitting.fit_report import build_report

    return build_report(
        **common,
        result=result,
        validity=design["validity"],
        metrics=design["metrics"],
        patches=design["patches"],
        stages=stages.timings,
        total_s=stages.total(),
        files=files,
    )


def _no_design_report(common, stages, error):
    from popupwb.fitting.fit_report import build_report

    report = build_report(
        **common,
        result=None,
        validity=None,
        metrics=None,
        patches=0,
        stages=stages.timings,
        total_s=stages.total(),
        files={},
    )
    report["diagnostics"] = list(getattr(error, "diagnostics", None) or [])
    return report


def _print_summary(report, files):
    for role in ("design", "preview", "report"):
        if role in files:
            print(f"wrote {files[role]}")
    kinds = ", ".join(f"{m['name']} ({m['type']} on {m['host']})" for m in report["mechanisms"])
    print(f"{report['number_of_mechanisms']} mechanism(s): {kinds or 'none'}")
    metrics = report.get("metrics") or {}
    hausdorff = (metrics.get("hausdorff") or {}).get("model_to_popup") or {}
    if hausdorff:
        print(
            "model to pop-up, / diagonal {:.1f} mm: mean {}, rms {}, max {}; volume difference "
            "{}; coverage {}".format(
                metrics.get("diagonal_mm") or 0.0,
                _g(hausdorff.get("mean")),
                _g(hausdorff.get("rms")),
                _g(hausdorff.get("max")),
                _g(metrics.get("volume_difference")),
                _g(metrics.get("coverage")),
            )
        )
    print("valid design" if report["valid"] else "no valid design found")


def _g(value):
    return "n/a" if value is None else f"{value:.4g}"
