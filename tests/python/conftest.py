"""Fixtures shared by the Python tests: FreeCAD headless, documents, a sandbox Mod folder.

ctest runs pytest with this environment (tests/CMakeLists.txt), and so can you, from the source tree:

    B=$PWD/build
    PYTHONPATH=$B/python:$PWD/Workbench:/usr/lib/freecad-python3/lib \
    POPUP_SOURCE_DIR=$PWD POPUP_BUILD_DIR=$B \
    FREECAD_USER_HOME=$B/sandbox/home HOME=$B/sandbox/home \
    /usr/bin/python3 -m pytest tests/python

Variables left unset get those values here (HOME excepted), so plain
`/usr/bin/python3 -m pytest tests/python` works too. Always /usr/bin/python3: FreeCAD's interpreter.
"""

import importlib
import json
import os
import subprocess
import sys

import pytest

SOURCE_DIR = os.environ.setdefault(
    "POPUP_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
)
BUILD_DIR = os.environ.setdefault("POPUP_BUILD_DIR", os.path.join(SOURCE_DIR, "build"))
USER_HOME = os.environ.setdefault("FREECAD_USER_HOME", os.path.join(BUILD_DIR, "sandbox", "home"))
WORKBENCH_DIR = os.path.join(SOURCE_DIR, "Workbench")
sys.path.append(WORKBENCH_DIR)
from popupwb import freecad_version  # noqa: E402  (importable before FreeCAD)

FREECAD_LIB = freecad_version.freecad_lib_dir()
# The tests' time limits (hang and speed checks) are for the optimised build: a slower one, such as
# tools/run_asan.py's sanitized build, sets POPUP_TIME_SCALE to stretch them all.
TIME_SCALE = float(os.environ.get("POPUP_TIME_SCALE", "1"))


def _ensure_path(directory):
    if directory not in sys.path:
        sys.path.append(directory)
    parts = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    if directory not in parts:
        os.environ["PYTHONPATH"] = os.pathsep.join(parts + [directory])


for _directory in (os.path.join(BUILD_DIR, "python"), WORKBENCH_DIR, FREECAD_LIB):
    _ensure_path(_directory)


def install_sandbox_mod(user_home=USER_HOME):
    """<FreeCAD's user Mod folder for user_home>/PopUp -> <source>/Workbench. Debian's FreeCAD
    restores a proxy only when its module lies in a Mod folder, so reopened files need this. The
    folder is FreeCAD's to name (versioned from 1.1 on); the link is replaced atomically: ctest
    runs the GUI tests, which do the same, in parallel."""
    env = dict(os.environ, FREECAD_USER_HOME=user_home, HOME=user_home)
    return freecad_version.link_into(freecad_version.user_mod_dir_for(env), WORKBENCH_DIR)


@pytest.fixture(scope="session")
def sandbox_mod():
    """The sandbox Mod/PopUp symlink (path), created before FreeCAD is imported."""
    return install_sandbox_mod()


@pytest.fixture(scope="session")
def freecad(sandbox_mod):
    """The FreeCAD module, headless."""
    import FreeCAD

    return FreeCAD


class WorkbenchModules:
    """popupwb's modules by short name (popup.make, popup.core: popupcore, ...), each imported at
    its first use, after FreeCAD."""

    MODULES = {
        "core": "popupwb.core",
        "make": "popupwb.make",
        "validity": "popupwb.validity",
        "card_scaffold": "popupwb.model.card_scaffold",
        "placement": "popupwb.model.placement",
        "profiles": "popupwb.profiles",
        "scaffold_feature": "popupwb.features.scaffold_feature",
        "cutting_sheet": "popupwb.features.cutting_sheet",
        "pages": "popupwb.sheets.techdraw_pages",
    }

    def __getattr__(self, name):
        if name not in self.MODULES:
            raise AttributeError(f"popup.{name}: not one of {sorted(self.MODULES)}")
        module = importlib.import_module(self.MODULES[name])
        return module.popupcore if name == "core" else module


@pytest.fixture(scope="module")
def popup(freecad):
    """The workbench's modules (WorkbenchModules) for the tests of its objects in documents."""
    return WorkbenchModules()


@pytest.fixture
def doc(freecad):
    """A new empty document, closed after the test."""
    document = freecad.newDocument("PopUpTest")
    yield document
    freecad.closeDocument(document.Name)


@pytest.fixture(scope="module")
def user_home(tmp_path_factory):
    """An empty FreeCAD user home for a test file's `popup` runs (cli_runner.py): the command line
    must work without the workbench installed."""
    return str(tmp_path_factory.mktemp("home"))


@pytest.fixture(scope="session")
def data_dir():
    return os.path.join(SOURCE_DIR, "tests", "data")


@pytest.fixture(scope="session")
def run_fresh_freecad(sandbox_mod):
    """Runs a Python script in a fresh /usr/bin/python3 with FreeCAD, as a user would have it: the
    workbench reached only through the sandbox Mod folder (Workbench/ removed from PYTHONPATH).
    The script prints one JSON document on its last stdout line; that is returned."""

    def run(script, timeout=300):
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join(
            p
            for p in env.get("PYTHONPATH", "").split(os.pathsep)
            if p and os.path.realpath(p) != os.path.realpath(WORKBENCH_DIR)
        )
        prelude = f"import sys\nsys.path.append({FREECAD_LIB!r})\nimport FreeCAD\n"
        process = subprocess.run(
            ["/usr/bin/python3", "-c", prelude + script],
            env=env,
            capture_output=True,
            text=True,
            timeout=timeout * TIME_SCALE,
        )
        assert process.returncode == 0, (
            f"fresh FreeCAD process failed ({process.returncode}):\n"
            f"{process.stdout}\n{process.stderr}"
        )
        return json.loads(process.stdout.strip().splitlines()[-1])

    return run
