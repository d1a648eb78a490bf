#!/usr/bin/python3
"""Builds the core, the bindings and the C++ tests with ASan + UBSan and runs both test suites.

Called by `make asan` as `/usr/bin/python3 tools/run_asan.py --build build-asan`. The build is a
separate CMake tree (g++ -fsanitize=address,undefined, no fuzzers). The C++ suite runs with leak
detection on; its UBSan reports do not stop it. The Python suite runs Debian's uninstrumented
python3 with the ASan runtime preloaded (an ASan extension module needs it first in the process),
then libstdc++ (python3 does not link it: without it ASan finds no real __cxa_throw to forward to
and the first C++ exception ends the process in a CHECK failure), and leak detection off (the
interpreter's own allocations are not ours). pytest captures only Python's sys.stdout/stderr
(--capture=sys), so what the sanitizers write to file descriptor 2 of pytest's own process reaches
the log, from a passing test or a dying process alike. Much of the suite's native code runs in
subprocesses (the popup command, FreeCAD scripts) whose stderr the tests capture: there any
sanitizer report, UBSan's included, ends the process with exit status 86, which no PopUp command
uses, so its test, which checks that status, fails (most of them show the process's stderr, the
report, in their failure message). Reports (ASan, LeakSanitizer, UBSan, and sanitizer CHECK
failures) are counted from the logs. The tests' time limits are for the optimised build:
POPUP_TIME_SCALE stretches them here. Exit status 0 only with both suites passing and 0 reports.
Logs: <build>/asan-cpp.log and <build>/asan-python.log.
"""

import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SANITIZE = "-fsanitize=address,undefined -fno-omit-frame-pointer"
# GCC's -Wmaybe-uninitialized misfires in CGAL's headers once ASan instruments them
# (CGAL/Epic_converter.h): a warning here, an error in the normal build.
NO_ERROR = "-Wno-error=maybe-uninitialized"
REPORT = re.compile(
    r"ERROR: (?:AddressSanitizer|LeakSanitizer)[^\n]*|^[^\n]*runtime error:[^\n]*"
    r"|Sanitizer: CHECK failed:[^\n]*",
    re.M,
)
# The sanitized build runs check_validity about 40 times slower than the -O3 one (at -O1 Eigen's
# small products are not inlined, and its assertions are on): the time limits of the Python tests
# (hang and speed checks) are multiplied by this.
TIME_SCALE = 20
# Exit status of a Python-suite process that a sanitizer stops (PopUp's commands use 0 to 3).
SANITIZER_EXIT = 86


def run(command, **kwargs):
    print("+", " ".join(command), flush=True)
    return subprocess.call(command, **kwargs)


def runtime_library(name):
    """g++'s own copy of a runtime library, the file itself, to preload."""
    path = os.path.realpath(
        subprocess.check_output(["g++", f"-print-file-name={name}"], text=True).strip()
    )
    with open(path, "rb") as f:
        if f.read(4) != b"\x7fELF":
            sys.exit(f"run_asan: {path} (for {name}) is not a shared object to preload")
    return path


def build(build_dir, jobs):
    status = run(
        [
            "cmake",
            "-S",
            ROOT,
            "-B",
            build_dir,
            "-DCMAKE_BUILD_TYPE=None",
            f"-DCMAKE_CXX_FLAGS=-O1 -g {SANITIZE} {NO_ERROR}",
            f"-DCMAKE_EXE_LINKER_FLAGS={SANITIZE}",
            f"-DCMAKE_SHARED_LINKER_FLAGS={SANITIZE}",
            f"-DCMAKE_MODULE_LINKER_FLAGS={SANITIZE}",
            "-DPython3_EXECUTABLE=/usr/bin/python3",
            "-DPOPUP_FUZZERS=OFF",
        ]
    )
    if status:
        sys.exit("run_asan: configure failed")
    targets = ["popup_core_tests", "popupcore", "popup_write_samples"]
    if run(["cmake", "--build", build_dir, "-j", str(jobs), "--target"] + targets):
        sys.exit("run_asan: build failed")
    if run(["/usr/bin/python3", os.path.join(ROOT, "tools", "write_launcher.py"), build_dir]):
        sys.exit("run_asan: write_launcher failed")


def suite(name, command, env, log_path):
    with open(log_path, "w") as log:
        status = run(command, env=env, cwd=ROOT, stdout=log, stderr=subprocess.STDOUT)
    with open(log_path, errors="replace") as log:
        text = log.read()
    reports = REPORT.findall(text)
    tail = [line for line in text.splitlines() if line.strip()][-3:]
    print(f"== {name}: exit {status}, {len(reports)} sanitizer reports ({log_path})")
    for line in tail:
        print(f"   {line}")
    for report in sorted(set(reports))[:20]:
        print(f"   {report}")
    return status, reports


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build-asan", help="build folder (default build-asan)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count())
    args = parser.parse_args()
    build_dir = os.path.abspath(args.build)
    build(build_dir, args.jobs)

    base = dict(os.environ)
    base["UBSAN_OPTIONS"] = "print_stacktrace=1"
    cpp_env = dict(base, ASAN_OPTIONS="detect_leaks=1")
    cpp = suite(
        "C++ suite (leak detection on)",
        [os.path.join(build_dir, "tests", "core", "popup_core_tests")],
        cpp_env,
        os.path.join(build_dir, "asan-cpp.log"),
    )

    preload = [runtime_library("libasan.so"), runtime_library("libstdc++.so")]
    sandbox = os.path.join(build_dir, "sandbox", "home")
    os.makedirs(sandbox, exist_ok=True)
    py_env = dict(
        base,
        LD_PRELOAD=" ".join(preload),
        ASAN_OPTIONS=f"detect_leaks=0:exitcode={SANITIZER_EXIT}",
        # GCC 12's runtime takes the exit status of UBSan's reports from UBSAN_OPTIONS.
        UBSAN_OPTIONS=f"print_stacktrace=1:halt_on_error=1:exitcode={SANITIZER_EXIT}",
        POPUP_TIME_SCALE=str(TIME_SCALE),
        PYTHONPATH=os.pathsep.join(
            [
                os.path.join(build_dir, "python"),
                os.path.join(ROOT, "Workbench"),
                "/usr/lib/freecad-python3/lib",
            ]
        ),
        POPUP_SOURCE_DIR=ROOT,
        POPUP_BUILD_DIR=build_dir,
        FREECAD_USER_HOME=sandbox,
        HOME=sandbox,
    )
    python = suite(
        "Python suite (ASan runtime and libstdc++ preloaded, leak detection off)",
        [
            "/usr/bin/python3",
            "-m",
            "pytest",
            "-q",
            "-rfEs",
            "--capture=sys",
            "-p",
            "no:cacheprovider",
            "tests/python",
        ],
        py_env,
        os.path.join(build_dir, "asan-python.log"),
    )
    if cpp[0] or python[0] or cpp[1] or python[1]:
        sys.exit("run_asan: failures or sanitizer reports (see the logs)")
    print("run_asan: both suites pass with 0 sanitizer reports")


if __name__ == "__main__":
    main()
