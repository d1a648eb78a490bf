#!/usr/bin/python3
"""Builds the core, the bindings and the C++ tests with ASan + UBSan and runs both test suites.

Called by `make asan` as `/usr/bin/python3 tools/run_asan.py --build build-asan`. The build is a
separate CMake tree (g++ -fsanitize=address,undefined, no fuzzers). The C++ suite runs with leak
detection on. The Python suite runs Debian's uninstrumented python3 with the ASan runtime
preloaded (an ASan extension module needs it first in the process) and leak detection off (the
interpreter's own allocations are not ours). UBSan reports do not stop a run: they are counted,
with the ASan and LeakSanitizer ones, from the logs. Exit status 0 only with both suites passing
and 0 reports. Logs: <build>/asan-cpp.log and <build>/asan-python.log.
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
    r"ERROR: (?:AddressSanitizer|LeakSanitizer)[^\n]*|^[^\n]*runtime error:[^\n]*", re.M
)


def run(command, **kwargs):
    print("+", " ".join(command), flush=True)
    return subprocess.call(command, **kwargs)


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

    libasan = subprocess.check_output(["g++", "-print-file-name=libasan.so"], text=True).strip()
    sandbox = os.path.join(build_dir, "sandbox", "home")
    os.makedirs(sandbox, exist_ok=True)
    py_env = dict(
        base,
        LD_PRELOAD=libasan,
        ASAN_OPTIONS="detect_leaks=0",
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
        "Python suite (ASan runtime preloaded, leak detection off)",
        ["/usr/bin/python3", "-m", "pytest", "-q", "-p", "no:cacheprovider", "tests/python"],
        py_env,
        os.path.join(build_dir, "asan-python.log"),
    )
    if cpp[0] or python[0] or cpp[1] or python[1]:
        sys.exit("run_asan: failures or sanitizer reports (see the logs)")
    print("run_asan: both suites pass with 0 sanitizer reports")


if __name__ == "__main__":
    main()
