"""PopUp on the FreeCAD releases makers run (README "Platforms"): the add-on `make install` lays
out, the core named by its Python ABI tag and the message for a core built for another Python,
and the static check .ci/run makes for what breaks FreeCAD 1.x.

Expected values come from FreeCAD itself (where it loads the add-on from), from Python's own
EXT_SUFFIX, and from files written here with one known defect each.
"""

import json
import os
import shutil
import subprocess
import sys
import sysconfig
import textwrap

import pytest

from conftest import BUILD_DIR, SOURCE_DIR, WORKBENCH_DIR

PYTHON = "/usr/bin/python3"
CHECK = os.path.join(SOURCE_DIR, "tools", "check_freecad_compat.py")


def clean_env(home):
    """No PYTHONPATH or POPUP_BUILD_DIR: the add-on must find its core by itself."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "POPUP_BUILD_DIR")}
    env.update(HOME=home, FREECAD_USER_HOME=home)
    return env


def user_app_data_dir(env):
    probe = "import FreeCAD; print(FreeCAD.getUserAppDataDir())"
    done = subprocess.run(
        ["freecadcmd", "-c", probe], env=env, capture_output=True, text=True, timeout=120
    )
    return [l for l in done.stdout.splitlines() if l.startswith("/")][-1]


def test_make_install_lays_out_the_addon_freecad_loads_with_the_core_for_its_python(tmp_path):
    home = str(tmp_path / "home")
    os.makedirs(home)
    env = clean_env(home)
    done = subprocess.run(
        [PYTHON, os.path.join(SOURCE_DIR, "tools", "install_addon.py"), "--build", BUILD_DIR],
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr
    addon = os.path.join(user_app_data_dir(env), "Mod", "PopUp")
    core_name = "popupcore" + sysconfig.get_config_var("EXT_SUFFIX")
    for part in (
        "package.xml",
        "LICENSE",
        "Workbench/Init.py",
        "Workbench/InitGui.py",
        "Workbench/popupwb/core.py",
        f"lib/{core_name}",
    ):
        assert os.path.isfile(os.path.join(addon, part)), part
    assert f"cpython-{sys.version_info.major}{sys.version_info.minor}" in core_name
    probe = tmp_path / "probe.py"
    probe.write_text("import popupwb.core as c\nprint('CORE', c.popupcore.__file__)\n")
    ran = subprocess.run(
        ["freecadcmd", str(probe)], env=env, capture_output=True, text=True, timeout=120
    )
    cores = [l.split(" ", 1)[1] for l in ran.stdout.splitlines() if l.startswith("CORE ")]
    assert cores == [os.path.join(addon, "lib", core_name)], ran.stdout + ran.stderr
    # The command line installed beside it runs from the copy too.
    popup = os.path.join(home, ".local", "bin", "popup")
    version = subprocess.run([popup, "--version"], env=env, capture_output=True, text=True)
    assert version.stdout.strip() == "popup 0.1.0", version.stderr


def test_a_core_built_for_another_python_is_named_with_both_versions(tmp_path):
    addon = tmp_path / "Mod" / "PopUp"
    shutil.copytree(
        WORKBENCH_DIR, addon / "Workbench", ignore=shutil.ignore_patterns("__pycache__")
    )
    (addon / "lib").mkdir()
    (addon / "lib" / "popupcore.cpython-399-x86_64-linux-gnu.so").write_bytes(b"\0")
    env = clean_env(str(tmp_path))
    env["PYTHONPATH"] = str(addon / "Workbench")
    done = subprocess.run(
        [PYTHON, "-c", "import popupwb.core"],
        env=env,
        capture_output=True,
        text=True,
        cwd=str(tmp_path),
    )
    assert done.returncode != 0
    running = f"{sys.version_info.major}.{sys.version_info.minor}"
    assert (
        f"PopUp's core was built for Python 3.99; this FreeCAD runs {running}: "
        "run make install with it"
    ) in done.stderr


def test_the_source_tree_has_none_of_the_freecad_1x_breakers():
    done = subprocess.run([PYTHON, CHECK], capture_output=True, text=True, cwd=SOURCE_DIR)
    assert done.returncode == 0, done.stdout


# file name -> {text, what the finding says, the line it names}: kept out of Python files, which
# the check itself reads.
with open(os.path.join(SOURCE_DIR, "tests", "data", "freecad_compat_breakers.json")) as _handle:
    BREAKERS = json.load(_handle)


@pytest.mark.parametrize("name", sorted(BREAKERS))
def test_the_static_check_names_each_breaker_with_its_line(tmp_path, name):
    text, message, line_number = (BREAKERS[name][k] for k in ("text", "finding", "line"))
    path = tmp_path / name
    path.write_text(text)
    done = subprocess.run([PYTHON, CHECK, str(path)], capture_output=True, text=True)
    assert done.returncode == 1
    lines = done.stdout.splitlines()
    assert len(lines) == 1 and message in lines[0], done.stdout
    assert int(lines[0].split(":")[1]) == line_number


def test_a_proxy_inheriting_dumps_passes_the_static_check(tmp_path):
    path = tmp_path / "fine.py"
    path.write_text(
        textwrap.dedent(
            """\
        class Base:
            def dumps(self):
                return None

            def loads(self, state):
                return None


        class Feature(Base):
            def execute(self, obj):
                pass
        """
        )
    )
    done = subprocess.run([PYTHON, CHECK, str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stdout
