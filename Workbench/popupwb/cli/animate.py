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
allowed range). The steps it shares with `popup fit` are in design_steps.py.

`--chains "Hand.L,Foot.R"` animates those chains only (MotionOptions.animate_only: the others are
held still, the report says so); `--list-chains` prints the chains found and exits 0 without
designing (no --out needed).
"""

import os
import time

from popupwb import option_fields
from popupwb.cli import design_steps as steps
from popupwb.cli.common import InputError, import_core, stdout_to_stderr
from popupwb.cli.design_steps import DESIGN_FILE, REPORT_FILE, SHEETS_DIR
from popupwb.readable_file import unreadable

PATHS_FILE = "paths.png"
MOVIE_FILE = "motion.gif"
PROGRESS_STEP = 0.1  # a progress line every 10 %


# The options the flags set, by flag; their ranges, defaults and docs are the core's.
FLAGS = {
    "--iterations": "iterations",
    "--first-frame": "first_frame",
    "--last-frame": "last_frame",
    "--scale": "scale",
}


def add_parser(sub):
    from popupwb.motion.motion_run import MIN_ITERATIONS

    core = option_fields.fields("MotionOptions")
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
    # Not required: --list-chains writes nothing (run() asks for it when designing).
    animate.add_argument("--out", metavar="DIR", help="folder for the files")
    steps.add_seed_flag(animate, core.get("seed"))
    metavars = {"--iterations": "N", "--first-frame": "F", "--last-frame": "L", "--scale": "MM"}
    for flag, name in FLAGS.items():
        low = MIN_ITERATIONS if name == "iterations" else None
        option_fields.add_flag(animate, flag, core.get(name), metavars[flag], low)
    for name in ("view", "up"):
        option_fields.add_vector_flag(animate, f"--{name}", core.get(name), "MotionOptions")
    animate.add_argument(
        "--keep-travel",
        action="store_true",
        help="keep a walking character's travel along the ground; by default it is kept in "
        "place (as at the last frame), so its limbs' paths are what the card can show",
    )
    animate.add_argument(
        "--chains",
        metavar="NAMES",
        help="animate only these chains, comma-separated, named as the report and --list-chains "
        'name them ("Hand.L,Foot.R"); the others are held still; default: all',
    )
    animate.add_argument(
        "--list-chains",
        action="store_true",
        help="print the chains found (name, bones, reach on the card, moving or still) with "
        "the view and frame flags given, and exit without designing",
    )
    steps.add_paper_flag(animate)
    animate.set_defaults(run=run)
    return animate


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


def _options(args, motion_run):
    """The MotionOptions and the paper from the flags; InputError naming the flag."""
    core = option_fields.fields("MotionOptions")
    try:
        option_fields.check(core.get("seed"), args.seed, "--seed")
        for flag, name in FLAGS.items():
            low = motion_run.MIN_ITERATIONS if name == "iterations" else None
            option_fields.check(core.get(name), getattr(args, name), flag, low)
    except ValueError as e:
        raise InputError(str(e))
    view, up = steps.directions(args, motion_run.direction, ("view", "up"))
    paper, card_size = steps.paper_and_card_size(args, motion_run.card_size_for_paper)
    animate_only = None
    if args.chains is not None:
        animate_only = motion_run.chain_names(args.chains)
        if not animate_only:
            raise InputError(f"--chains {args.chains!r}: name at least one chain")
    with steps.core_range_checks():
        options = motion_run.motion_options(
            seed=args.seed,
            iterations=args.iterations,
            first_frame=args.first_frame,
            last_frame=args.last_frame,
            view=view,
            up=up,
            scale=args.scale,
            card_size=card_size,
            keep_travel=args.keep_travel or None,
            animate_only=animate_only,
            # Frames the maker names are shown as named (the core chooses only the whole take's).
            auto_frames=False
            if args.first_frame is not None or args.last_frame is not None
            else None,
            flags=steps.flags_given(args, {name: name for name in (*FLAGS.values(), "view", "up")}),
        )
    return options, paper


def run(args):
    """The `popup animate` command."""
    say = steps.Say("animate")
    popupcore = import_core()
    from popupwb.motion import motion_run

    steps.require_core(
        popupcore, ("load_animation", "load_trajectories", "MotionOptions", "design_motion")
    )
    options, paper = _options(args, motion_run)
    if args.out is None and not args.list_chains:
        raise InputError("--out DIR is required to design (only --list-chains goes without)")
    if args.out is not None:
        steps.check_out_and_input(args, args.animation)
    elif unreadable(args.animation):
        raise InputError(unreadable(args.animation))

    stages = motion_run.Stages(say)
    with stages.stage("load", f"reading {args.animation}"):
        with stdout_to_stderr():
            try:
                animation, what = motion_run.read_animation(args.animation)
            except (ValueError, RuntimeError, OSError) as e:
                raise InputError(steps.named(args.animation, e))
    say(what)
    if args.list_chains:
        return _list_chains(args, animation, options, motion_run)

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
        _raise_if_unknown_chain(args, e)
        steps.raise_unless_no_design(e, args.animation)
        report = _report(common, None, None, stages, files)
        return steps.report_no_design(args, args.animation, e, report, files, say)
    _add_core_stages(stages, result.timings, time.perf_counter() - started)
    shown = motion_run.frames_shown(result.targets, "--first-frame and --last-frame")
    if shown:
        say(shown)
    say(
        f"{len(result.chains)} chain(s) on {len(result.mechanisms)} mechanism(s); weighted "
        f"motion error {result.weighted_error:.4f} of the character's diagonal"
    )

    validity = _write_design(args, result, animation, stages, files, say)
    _write_pictures(args, result, animation, tuple(options.view.up), stages, files, say)
    report = _report(common, result, validity, stages, files)
    if report["valid"] and not result.pops_up:  # the core's rule: a bare card is no pop-up
        report["valid"] = False
        say("no mechanism: every chain is printed on the page, nothing stands up")
    valid = report["valid"]
    status = steps.sheets_of_valid_design(args, paper, report, valid, files, stages, say)
    return steps.finish(args, report, status, files, stages, say, _print_summary)


def _list_chains(args, animation, options, motion_run):
    """--list-chains: the chains found, one a line on stdout; exit 0."""
    try:
        chains = motion_run.chains_found(animation, options)
    except ValueError as e:  # DesignError: a view or frame option the animation refuses
        raise InputError(steps.named(args.animation, e))
    for chain in chains:
        print(motion_run.chain_line(chain))
    print(f"{len(chains)} chain(s); animate some with --chains NAME,NAME")
    return 0


def _raise_if_unknown_chain(args, error):
    """The core's error for a --chains name no chain has, led by the flag (exit 2)."""
    unknown = [
        d["message"]
        for d in getattr(error, "diagnostics", None) or []
        if d.get("parameter") == "animate_only"
    ]
    if unknown:
        raise InputError(f"--chains {args.chains}: " + "; ".join(unknown) + " (see --list-chains)")


def _add_core_stages(stages, timings, wall_s):
    """The core's own stages (MotionResult.timings), and what the call took beyond them
    (`design_other`: the worker thread, the progress polling), so the stages add up."""
    stages.add(timings.stages)
    stages.add([("design_other", max(wall_s - sum(float(t) for _, t in timings.stages), 0.0))])


def _write_design(args, result, animation, stages, files, say):
    """Builds, checks and saves the FreeCAD design; returns the check's dict."""
    with steps.design_document("PopUpAnimate") as doc:
        from popupwb.motion.design_from_motion import build_design

        _, checked = steps.build_and_check(
            stages,
            lambda: build_design(
                doc, result, animation, source_file=os.path.abspath(args.animation)
            ),
        )
        path = steps.save_design(doc, args.out, files)
    say(f"wrote {path}")
    return checked


def _write_pictures(args, result, animation, up, stages, files, say):
    from popupwb.motion.motion_movie import MovieError, write_result_movie
    from popupwb.motion.paths_plot import write_paths_plot

    title = os.path.basename(args.animation)
    with stages.stage("plot", "plotting the paths"):
        files["paths"] = write_paths_plot(
            os.path.join(args.out, PATHS_FILE),
            result.chains,
            result.card.width,
            result.card.depth,
            title=f"{title}: weighted motion error {result.weighted_error:.4f} "
            f"(reach floor {result.weighted_floor:.4f})",
        )
    say(f"wrote {files['paths']}")
    with stages.stage("movie", "drawing the card opening beside the animation"):
        try:
            movie = os.path.join(args.out, MOVIE_FILE)
            files["movie"], _, _ = write_result_movie(movie, result, animation, up, title)
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


def _print_summary(report, files):
    steps.print_written(files, ("design", "paths", "movie", "report"))
    for chain in report["chains"]:
        why = f" ({chain['reason']})" if chain["reason"] else ""
        print(
            f"chain {chain['name']}: {chain['mechanism']}, {chain['status']}{why}, error "
            f"{steps.g(chain['error'])} (floor {steps.g(chain['floor'])}, best alone "
            f"{steps.g(chain.get('bound'))} by {chain.get('bound_mechanism') or 'n/a'}), weight "
            f"{steps.g(chain['weight'])}"
        )
    print(
        f"{report['number_of_mechanisms']} mechanism(s); weighted motion error "
        f"{steps.g(report['weighted_error'])} of the character's diagonal (no design on this "
        f"card scores under {steps.g(report['weighted_floor'])}: the reach floor)"
    )
    print("valid design" if report["valid"] else "no valid design found")
