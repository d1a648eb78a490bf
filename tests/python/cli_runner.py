"""Running the `popup` command line (build/bin/popup, written by `make build`) as a user would,
and reading what it wrote: shared by the command-line tests (test_cli*.py, test_animate_cli.py,
test_fit_*.py, ...). Also runs the scripts that build their FreeCAD documents, and loads the model
and demo writers of tools/."""

import importlib.util
import json
import os
import subprocess

from conftest import BUILD_DIR, FREECAD_LIB, SOURCE_DIR, TIME_SCALE, WORKBENCH_DIR

POPUP = os.path.join(BUILD_DIR, "bin", "popup")
DATA_DIR = os.path.join(SOURCE_DIR, "tests", "data")


def data(name):
    """A test design of tests/data, which must exist."""
    path = os.path.join(DATA_DIR, name)
    assert os.path.isfile(path), f"test design {path} is missing"
    return path


def popup(*args, home=None, env_vars=None):
    """Runs build/bin/popup with `args`; `env_vars` adds to (or overrides) the environment."""
    assert os.access(POPUP, os.X_OK), f"{POPUP} missing: run `make build`"
    env = dict(os.environ)
    if home:
        env.update(FREECAD_USER_HOME=home, HOME=home)
    env.update(env_vars or {})
    return subprocess.run(
        [POPUP, *args],
        capture_output=True,
        text=True,
        timeout=300 * TIME_SCALE,
        env=env,
        cwd=SOURCE_DIR,
    )


def run_design(command, source, out, *extra, home=None):
    """`popup COMMAND SOURCE --out OUT EXTRA...` (fit, animate), which must not end in a
    traceback whatever its exit code."""
    proc = popup(command, str(source), "--out", str(out), *extra, home=home)
    assert "Traceback" not in proc.stdout + proc.stderr, proc.stderr
    return proc


def read_report(*folders):
    """The report.json in the folder os.path.join(*folders) as a dict."""
    with open(os.path.join(*map(str, folders), "report.json")) as f:
        return json.load(f)


def assert_clean_error(proc, *fragments):
    """Exit 2, one line on stderr containing every fragment, no traceback anywhere."""
    assert proc.returncode == 2, (proc.returncode, proc.stdout, proc.stderr)
    assert "Traceback" not in proc.stderr + proc.stdout
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    for fragment in fragments:
        assert fragment in lines[0], (fragment, lines[0])


def assert_named_error(proc, *fragments):
    """Exit 2; the last stderr line is the one error line, naming every fragment; no traceback."""
    assert proc.returncode == 2, (proc.returncode, proc.stdout, proc.stderr)
    lines = proc.stderr.strip().splitlines()
    errors = [line for line in lines if line.startswith("popup: error:")]
    assert errors == lines[-1:], proc.stderr
    for fragment in fragments:
        assert fragment in lines[-1], (fragment, lines[-1])


def assert_input_refused(proc, path, out):
    """The input file `path` refused: exit 2 with the one error line naming it, and no design
    written to the folder `out`."""
    assert_named_error(proc, os.path.basename(path))
    assert not os.path.exists(os.path.join(out, "design.FCStd"))


def run_freecad_script(script, *args, home):
    """Runs `script` in Debian's Python with FreeCAD and the workbench (headless, as the tests'
    document builders need); fails the test with its stderr when it fails."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [os.path.join(BUILD_DIR, "python"), WORKBENCH_DIR, FREECAD_LIB]
    )
    env.update(FREECAD_USER_HOME=home, HOME=home)
    proc = subprocess.run(
        ["/usr/bin/python3", "-c", script, *map(str, args)],
        capture_output=True,
        text=True,
        timeout=300 * TIME_SCALE,
        env=env,
    )
    assert proc.returncode == 0, proc.stderr
    return proc


def load_tool(name):
    """tools/NAME.py as a module (make_models, run_demo: the writers of the test inputs)."""
    spec = importlib.util.spec_from_file_location(
        name, os.path.join(SOURCE_DIR, "tools", f"{name}.py")
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
