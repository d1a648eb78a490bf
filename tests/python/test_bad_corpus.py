"""Issue 10's bad inputs as a corpus: the design files of tests/data/bad/ (written by its
make_bad_designs.py from the project's own test designs) and the rows of
tests/data/bad/expectations.json, each run through build/bin/popup as a user would.

A row gives the command (`{file}` is the row's design, `{out}` a fresh folder), the exit status and
message fragments that name the field, patch or option at fault. Every row also must not crash
(no signal), hang (a timeout), print "internal error", "unknown exception" or a traceback, or let a
terminal escape through. Rows run in parallel, so the corpus costs a few seconds of wall time.
"""

import concurrent.futures
import importlib.util
import json
import os
import subprocess
import time

import pytest

from conftest import TIME_SCALE

SOURCE_DIR = os.environ.get(
    "POPUP_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
)
BUILD_DIR = os.environ.get("POPUP_BUILD_DIR", os.path.join(SOURCE_DIR, "build"))
POPUP = os.path.join(BUILD_DIR, "bin", "popup")
BAD_DIR = os.path.join(SOURCE_DIR, "tests", "data", "bad")
TIMEOUT = 60  # seconds; a row may ask for less with max_seconds (both times TIME_SCALE)
NEVER = ("internal error", "unknown exception", "Traceback (most recent call last)")

with open(os.path.join(BAD_DIR, "expectations.json"), encoding="utf-8") as _f:
    ROWS = json.load(_f)["rows"]


def _maker():
    spec = importlib.util.spec_from_file_location(
        "make_bad_designs", os.path.join(BAD_DIR, "make_bad_designs.py")
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _design_path(row, folder):
    """The row's design: a file of tests/data/bad (or ../ for the project's own test designs), or
    `generated:<name>`, a design too large to commit, written into `folder`."""
    name = row.get("file")
    if name is None:
        return None
    if name.startswith("generated:"):
        return _maker().generated(name.split(":", 1)[1], folder)
    return os.path.normpath(os.path.join(BAD_DIR, name))


def run_row(row, folder):
    """Runs one row in `folder`: {"returncode", "stdout", "stderr", "seconds", "timed_out",
    "stale_left"}."""
    os.makedirs(folder, exist_ok=True)
    out = os.path.join(folder, "out")
    design = _design_path(row, folder)
    if row.get("stale"):
        os.makedirs(out, exist_ok=True)
        for name in row["stale"]:
            with open(os.path.join(out, name), "w") as f:
                f.write("left by an earlier run\n")
    args = [a.replace("{file}", design or "").replace("{out}", out) for a in row["args"]]
    started = time.monotonic()
    try:
        proc = subprocess.run(
            [POPUP, *args],
            capture_output=True,
            text=True,
            errors="backslashreplace",
            timeout=row.get("max_seconds", TIMEOUT) * TIME_SCALE,
            cwd=SOURCE_DIR,
        )
        result = {"returncode": proc.returncode, "stdout": proc.stdout, "stderr": proc.stderr}
        result["timed_out"] = False
    except subprocess.TimeoutExpired as e:
        result = {"returncode": None, "stdout": str(e.stdout), "stderr": str(e.stderr)}
        result["timed_out"] = True
    result["seconds"] = time.monotonic() - started
    result["stale_left"] = [n for n in row.get("stale", []) if os.path.exists(os.path.join(out, n))]
    return result


@pytest.fixture(scope="module")
def results(request, tmp_path_factory):
    """{row id: future result}, every selected row started at once (in parallel, two at a time
    per core: most of a row's time is Python and FreeCAD importing)."""
    selected = {
        item.callspec.params["row"]["id"]
        for item in request.session.items
        if item.originalname == "test_bad_input" and hasattr(item, "callspec")
    }
    folder = tmp_path_factory.mktemp("bad")
    workers = max(2, 2 * (os.cpu_count() or 1))
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        futures = {
            row["id"]: pool.submit(run_row, row, str(folder / row["id"]))
            for row in ROWS
            if row["id"] in selected
        }
        yield futures


def _describe(row, result):
    return (
        f"{row['id']}: popup {' '.join(row['args'])} -> exit {result['returncode']} "
        f"in {result['seconds']:.1f} s\n--- stdout\n{result['stdout'][:3000]}"
        f"\n--- stderr\n{result['stderr'][:3000]}"
    )


def _marks(row):
    if "xfail" in row:  # named in the row and in the test output, never silent
        return [pytest.mark.xfail(reason=row["xfail"], strict=True)]
    return []


@pytest.mark.parametrize(
    "row", [pytest.param(row, id=row["id"], marks=_marks(row)) for row in ROWS]
)
def test_bad_input(row, results):
    assert os.access(POPUP, os.X_OK), f"{POPUP} missing: run `make build`"
    result = results[row["id"]].result()
    what = _describe(row, result)
    assert not result["timed_out"], f"timed out after {result['seconds']:.0f} s\n{what}"
    assert result["returncode"] >= 0, f"killed by signal {-result['returncode']}\n{what}"
    text = result["stdout"] + result["stderr"]
    for never in NEVER:
        assert never not in text, what
    assert "\x1b" not in text, f"a terminal escape reached the output\n{what}"
    assert result["returncode"] == row["exit"], what
    where = {"stdout": result["stdout"], "stderr": result["stderr"]}.get(row.get("stream"), text)
    for fragment in row.get("fragments", []):
        assert fragment in where, f"missing {fragment!r}\n{what}"
    for fragment in row.get("absent", []):
        assert fragment not in text, f"unexpected {fragment!r}\n{what}"
    if row["exit"] == 2:  # unusable input: one line on stderr, nothing on stdout
        assert len(result["stderr"].strip().splitlines()) == 1, what
        assert result["stdout"] == "", what
    assert result["stale_left"] == [], f"stale files left in --out: {result['stale_left']}"
    if "max_seconds" in row:
        assert result["seconds"] < row["max_seconds"] * TIME_SCALE, what


def test_rows_are_unique_and_complete():
    ids = [row["id"] for row in ROWS]
    assert len(ids) == len(set(ids))
    for row in ROWS:
        assert {"id", "why", "args", "exit"} <= set(row), row
        assert row["exit"] in (0, 1, 2), row
        assert row["exit"] == 0 or row.get("fragments"), f"{row['id']}: name what is wrong"


def test_every_bad_file_has_a_row_and_matches_its_maker():
    maker = _maker()
    files = {name for name in os.listdir(BAD_DIR) if name.endswith(".json")}
    files.discard("expectations.json")
    used = {row["file"] for row in ROWS if "file" in row}
    assert files <= used, f"files no row runs: {sorted(files - used)}"
    made = {f"{name}.json" for name in [*maker.DESIGNS, *maker.RAW]}
    assert files == made, "tests/data/bad/ and make_bad_designs.py disagree"
    for name in sorted(made):
        with open(os.path.join(BAD_DIR, name), "rb") as f:
            assert f.read() == maker.contents(
                name[: -len(".json")]
            ), f"{name}: run make_bad_designs.py"
