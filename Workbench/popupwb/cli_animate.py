"""`popup animate <animation> --out DIR`: an animated pop-up designed from a character's animation
(issue 13, thesis ch. 6), written as DIR/design.FCStd (a PopUpCard with motion-mechanism features,
linked to the animation and, for a skinned character, its mesh posed at the last frame),
DIR/report.json (docs/MOTION_REPORT.md), DIR/paths.png (target paths against the mechanisms'),
DIR/motion.gif (the card opening beside the character) and, for a valid design, the cutting sheets
in DIR/sheets/ exactly as `popup sheet` writes them (the same code path; `popup verify` checks
them).

Progress goes to stderr, the files written and the verdict to stdout. Exit codes as `popup fit`:
0 a valid design with usable sheets, 1 no valid design (the report and what could be written say
what was tried), 2 input that cannot be used (one line naming the file or flag, the value and the
allowed range).
"""

import math
import os
import sys
import time

from popupwb.cli_fit import DEFAULT_PAPER, _diagnostic_codes, _named, _write_sheets

DESIGN_FILE = "design.FCStd"
REPORT_FILE = "report.json"
PATHS_FILE = "paths.png"
MOVIE_FILE = "motion.gif"
SHEETS_DIR = "sheets"
PROGRESS_STEP = 0.1  # a progress line every 10 %


def add_parser(sub):
    from popupwb.motion.motion_run import DEFAULT_ITERATIONS, MAX_ITERATIONS

    animate = sub.add_parser(
        "animate",
        help="design an animated pop-up from a character's animation: FreeCAD document, report, "
        "paths plot, movie and sheets",
        description="Split the character's skeleton into chains, project their end effectors' "
        "paths on the card, map each chain to a motion mechanism (vertical, diagonal, horizontal "
        "translation, rotation, or a stationary floating layer), anneal the parameters without "
        f"collisions and write DIR/{DESIGN_FILE}, DIR/{REPORT_FILE}, DIR/{PATHS_FILE}, "
        f"DIR/{MOVIE_FILE} and DIR/{SHEETS_DIR}/ (the files of popup sheet). Reads BVH, FBX, "
        "glTF/GLB, Collada (assimp) and the JSON of named trajectories. Exit 0 valid, 1 no valid "
        "design found, 2 unusable input.",
    )
    animate.add_argument("animation", help="animation file, or a .json of named trajectories")
    animate.add_argument("--out", required=True, metavar="DIR", help="folder for the files")
    animate.add_argument(
        "--seed", type=int, default=1, metavar="S", help="random seed; same seed, same design"
    )
    animate.add_argument(
        "--iterations",
        type=int,
        default=DEFAULT_ITERATIONS,
        metavar="N",
        help=f"annealing iterations per search chain, 1 to {MAX_ITERATIONS} "
        f"(default {DEFAULT_ITERATIONS})",
    )
    animate.add_argument(
        "--first-frame", type=int, metavar="F", help="frame shown closed (default 0)"
    )
    animate.add_argument(
        "--last-frame", type=int, metavar="L", help="frame shown open flat (default: the last)"
    )
    animate.add_argument(
        "--view",
        metavar="X,Y,Z",
        help="direction from the eye toward the character, in the file's axes (default 0,0,-1)",
    )
    animate.add_argument(
        "--up", metavar="X,Y,Z", help="file direction that becomes up on the card (default 0,1,0)"
    )
    animate.add_argument(
        "--scale",
        type=float,
        metavar="MM",
        help="card mm per file unit (default: the character's projected box fits the card)",
    )
    animate.add_argument(
        "--paper",
        help="paper of the sheets, A4, A3, Letter, Tabloid or WxH mm; the card is the largest "
        f"that fits on it (default: the PopUp preference, else {DEFAULT_PAPER})",
    )
    return animate


class _Say:
    """Progress lines on stderr."""

    def __call__(self, text):
        print(f"popup animate: {text}", file=sys.stderr, flush=True)


class _Progress:
    """Prints the annealing's progress every PROGRESS_STEP."""

    def __init__(self, say):
        self.say = say
        self.next = PROGRESS_STEP

    def __call__(self, fraction):
        if fraction >= self.next - 1e-12:
            self.say(f"designing: {int(round(100 * min(fraction, 1.0)))} %")
            while self.next <= fraction + 1e-12:
                self.next += PROGRESS_STEP


def _options(args, cli, motion_run):
    """The MotionOptions and the paper from the flags; InputError naming the flag."""
    if args.seed < 0:
        raise cli.InputError(f"--seed {args.seed}: must be >= 0")
    if not 1 <= args.iterations <= motion_run.MAX_ITERATIONS:
        raise cli.InputError(
            f"--iterations {args.iterations}: must be 1 to {motion_run.MAX_ITERATIONS}"
        )
    if args.first_frame is not None and args.first_frame < 0:
        raise cli.InputError(f"--first-frame {args.first_frame}: must be >= 0")
    if args.last_frame is not None and args.last_frame < 0:
        raise cli.InputError(f"--last-frame {args.last_frame}: must be >= 0")
    if (
        args.first_frame is not None
        and args.last_frame is not None
        and args.last_frame <= args.first_frame
    ):
        raise cli.InputError(
            f"--last-frame {args.last_frame}: must be after --first-frame {args.first_frame}"
        )
    if args.scale is not None and not (math.isfinite(args.scale) and args.scale > 0):
        raise cli.InputError(f"--scale {args.scale:g}: must be a finite number of mm > 0")
    try:
        view = motion_run.direction(args.view, "--view") if args.view is not None else None
        up = motion_run.direction(args.up, "--up") if args.up is not None else None
    except ValueError as e:
        raise cli.InputError(str(e))
    paper = args.paper or cli._preferences().sheet_paper or DEFAULT_PAPER
    try:
        card_size = motion_run.card_size_for_paper(paper)
    except ValueError as e:
        raise cli.InputError(f"--paper {paper}: {cli._one_line(e)}")
    try:
        options = motion_run.motion_options(
            seed=args.seed,
            iterations=args.iterations,
            first_frame=args.first_frame,
            last_frame=args.last_frame,
            view=view,
            up=up,
            scale=args.scale,
            card_size=card_size,
        )
    except ValueError as e:  # the core's own range checks of the same values
        raise cli.InputError(cli._one_line(e))
    return options, paper


def run(args, cli):
    """The `popup animate` command; `cli` is the popupwb.cli module that parsed `args`."""
    say = _Say()
    popupcore = cli._import_core()
    from popupwb.motion import motion_run

    for needed in ("load_animation", "load_trajectories", "MotionOptions", "design_motion"):
        if not hasattr(popupcore, needed):
            raise RuntimeError(f"popupcore.{needed} is missing: rebuild (make build)")
    options, paper = _options(args, cli, motion_run)
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        raise cli.InputError(f"--out {args.out}: is a file, not a folder")
    why = cli.unreadable(args.animation)
    if why:
        raise cli.InputError(why)

    stages = motion_run.Stages(say)
    with stages.stage("load", f"reading {args.animation}"):
        with cli._stdout_to_stderr():
            try:
                animation, what = motion_run.read_animation(args.animation)
            except (ValueError, RuntimeError, OSError) as e:
                raise cli.InputError(_named(args.animation, e, cli))
    say(what)

    os.makedirs(args.out, exist_ok=True)
    files = {}
    common = dict(
        animation_file=os.path.abspath(args.animation),
        animation=animation,
        options=motion_run.options_dict(options),
    )
    say(f"designing (seed {options.seed}, {options.iterations} iterations per search chain)")
    started = time.perf_counter()
    try:
        result = motion_run.design(animation, options, on_progress=_Progress(say))
    except popupcore.DesignError as e:
        if "no_design_found" not in _diagnostic_codes(e):
            raise cli.InputError(_named(args.animation, e, cli))
        say(f"no valid design: {cli._one_line(e)}")
        report = _report(common, None, None, stages, files)
        report["diagnostics"] = list(getattr(e, "diagnostics", None) or [])
        _write_report(args.out, report, files, say)
        print(f"no valid design found for {args.animation}; see {files['report']}")
        return cli.EXIT_INVALID
    _add_core_stages(stages, result, time.perf_counter() - started)
    say(
        f"{len(result.chains)} chain(s) on {len(result.mechanisms)} mechanism(s); weighted "
        f"motion error {result.weighted_error:.4f} of the character's diagonal"
    )

    validity = _write_design(args, cli, result, animation, stages, files, say)
    _write_pictures(args, result, animation, stages, files, say)
    report = _report(common, result, validity, stages, files)
    if report["valid"] and result.mechanisms:
        status = _write_sheets(args, cli, paper, files, stages, say)
    else:
        status = cli.EXIT_INVALID
        for d in report.get("diagnostics") or []:
            say(f"{d.get('severity', 'error')}: {d.get('code')}: {d.get('message')}")
        say("no valid design found: no sheets written")
    from popupwb.fitting.fit_report import timings

    report["timings_s"] = timings(stages.timings, stages.total())
    report["sheets_ok"] = bool(report["valid"] and status == cli.EXIT_VALID)
    _write_report(args.out, report, files, say)
    _print_summary(report, files)
    if report["valid"] and status != cli.EXIT_VALID:
        print(
            "but its cutting sheets have errors (listed above; "
            f"{os.path.join(files['sheets'], 'report.json')})"
        )
    return status if report["valid"] else cli.EXIT_INVALID


def _add_core_stages(stages, result, wall_s):
    """The core's own stages (MotionResult.timings), and what the call took beyond them
    (`design_other`: the worker thread, the progress polling), so the stages add up."""
    core = list(getattr(result, "timings", None) or getattr(result, "timings_s", None) or ())
    core = [(name, seconds) for name, seconds in core if name != "total"]  # ours is the total
    stages.add(core)
    stages.add([("design_other", max(wall_s - sum(float(t) for _, t in core), 0.0))])


def _write_design(args, cli, result, animation, stages, files, say):
    """Builds, checks and saves the FreeCAD design; returns the check's dict."""
    with cli._stdout_to_stderr():
        FreeCAD = cli._import_freecad()
        from popupwb import validity
        from popupwb.motion.design_from_motion import build_design

        doc = FreeCAD.newDocument("PopUpAnimate")
        try:
            with stages.stage("document", "building the card's features"):
                design = build_design(
                    doc, result, animation, source_file=os.path.abspath(args.animation)
                )
            with stages.stage("check", "checking the card's validity"):
                checked = validity.run_check(design.card)
            files["design"] = os.path.join(args.out, DESIGN_FILE)
            doc.saveAs(os.path.abspath(files["design"]))
        finally:
            FreeCAD.closeDocument(doc.Name)
    say(f"wrote {files['design']}")
    return checked


def _write_pictures(args, result, animation, stages, files, say):
    from popupwb.motion.motion_movie import MovieError, character_frames, write_movie
    from popupwb.motion.paths_plot import write_paths_plot

    title = os.path.basename(args.animation)
    with stages.stage("plot", "plotting the paths"):
        files["paths"] = write_paths_plot(
            os.path.join(args.out, PATHS_FILE),
            result.chains,
            result.card.width,
            result.card.depth,
            title=f"{title}: weighted motion error {result.weighted_error:.4f}",
        )
    say(f"wrote {files['paths']}")
    with stages.stage("movie", "drawing the card opening beside the animation"):
        try:
            files["movie"], _, _ = write_movie(
                os.path.join(args.out, MOVIE_FILE),
                result.scaffold,
                character_frames(
                    animation,
                    result.targets.animation_to_card,
                    result.targets.first_frame,
                    result.targets.last_frame,
                ),
                result.chains,
                title=title,
            )
        except MovieError as e:  # an invalid design that locks: the report says why
            say(f"no movie: {e}")
            return
    say(f"wrote {files['movie']}")


def _report(common, result, validity, stages, files):
    from popupwb.motion.motion_report import build_report

    return build_report(
        **common,
        result=result,
        validity=validity,
        stages=stages.timings,
        total_s=stages.total(),
        files=files,
    )


def _write_report(out, report, files, say):
    from popupwb.motion.motion_report import write_report

    files["report"] = os.path.join(out, REPORT_FILE)
    report["files"] = dict(files)
    write_report(report, files["report"])
    say(f"wrote {files['report']}")


def _print_summary(report, files):
    for role in ("design", "paths", "movie", "report"):
        if role in files:
            print(f"wrote {files[role]}")
    for chain in report["chains"]:
        why = f" ({chain['reason']})" if chain["reason"] else ""
        print(
            f"chain {chain['name']}: {chain['mechanism']}, {chain['status']}{why}, error "
            f"{_g(chain['error'])}, weight {_g(chain['weight'])}"
        )
    print(
        f"{report['number_of_mechanisms']} mechanism(s); weighted motion error "
        f"{_g(report['weighted_error'])} of the character's diagonal"
    )
    print("valid design" if report["valid"] else "no valid design found")


def _g(value):
    return "n/a" if value is None else f"{value:.4g}"
