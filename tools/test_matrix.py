#!/usr/bin/python3
"""`make test-matrix`: the README's commands on the FreeCAD releases makers run, in chroots.

For each platform (Debian 13 with FreeCAD 1.0, Debian sid with FreeCAD 1.1) this builds, or
reuses, a minimal Debian chroot under <build>/matrix/<platform> with debootstrap, from the mirror
the machine's own apt sources name; bind-mounts the source tree at /src; and runs `make test`
there (which runs `make deps`, so the Makefile's package choice for that release is tested too),
with a build folder of its own, <build>/matrix/<platform>-build. Then one line per platform:
its FreeCAD and Python, the ctest counts, the time and the disk.

Usage: test_matrix.py [--build build] [--only debian-13,...] [--target test] [--jobs N]
                      [--keep-going] [--command CMD] [--unmount]
Exit 0 when every platform passes, 1 otherwise, 2 when a chroot cannot be made (the message says
why). Needs root (debootstrap, chroot, mount); `make test-matrix` installs debootstrap.
"""

import argparse
import contextlib
import fcntl
import glob
import os
import re
import shutil
import signal
import subprocess
import sys
import time

# name -> Debian suite. Debian 12 is the machine itself (`make test`, .ci/run).
PLATFORMS = {"debian-13": "trixie", "debian-sid": "sid"}
READY_MARK = ".popup-matrix-ready"
SOURCE_IN_CHROOT = "/src"
BUILD_IN_CHROOT = "/build"


class MatrixError(Exception):
    """A platform cannot be set up on this machine; the message says what to do."""


def host_mirror():
    """The Debian archive the machine's apt sources name (never a host name of our own)."""
    uris = []
    for path in sorted(glob.glob("/etc/apt/sources.list.d/*.sources")):
        with open(path) as handle:
            uris += re.findall(r"^URIs:\s*(\S+)", handle.read(), re.M)
    for path in ["/etc/apt/sources.list"] + sorted(glob.glob("/etc/apt/sources.list.d/*.list")):
        if os.path.exists(path):
            with open(path) as handle:
                uris += re.findall(r"^deb\s+(?:\[[^]]*\]\s+)?(\S+)", handle.read(), re.M)
    archive = [uri for uri in uris if "security" not in uri and uri.rstrip("/").endswith("debian")]
    if not archive:
        raise MatrixError("no Debian archive in /etc/apt/sources.list{,.d}: cannot run debootstrap")
    return archive[0]


def ensure_chroot(root, suite, mirror, log):
    """A minimal chroot of `suite` at `root`, made once; a half-made one is made again."""
    if os.path.exists(os.path.join(root, READY_MARK)):
        return
    if shutil.which("debootstrap") is None:
        raise MatrixError("debootstrap is not installed: run `make test-matrix` (it installs it)")
    if os.path.exists(root):
        shutil.rmtree(root)
    print(f"  debootstrap {suite} from {mirror} into {root} ...", flush=True)
    with open(log, "w") as out:
        done = subprocess.run(
            [
                "debootstrap",
                "--variant=minbase",
                "--include=make,ca-certificates",
                suite,
                root,
                mirror,
            ],
            stdout=out,
            stderr=subprocess.STDOUT,
        )
    if done.returncode != 0:
        raise MatrixError(f"debootstrap {suite} failed (exit {done.returncode}): see {log}")
    # No service starts from a package installed in the chroot.
    policy = os.path.join(root, "usr/sbin/policy-rc.d")
    with open(policy, "w") as handle:
        handle.write("#!/bin/sh\nexit 101\n")
    os.chmod(policy, 0o755)
    # A mirror's sid can lag behind its Release file's Valid-Until: apt would then refuse it.
    with open(os.path.join(root, "etc/apt/apt.conf.d/99popup-matrix"), "w") as handle:
        handle.write('Acquire::Check-Valid-Until "false";\n')
    open(os.path.join(root, READY_MARK), "w").close()


class Mounts:
    """proc, sys, dev, the source tree (read-only: nothing in the chroot can change it) and the
    platform's build folder inside the chroot; unmounted in reverse on exit, also on SIGTERM."""

    def __init__(self, root, source, build_dir):
        self.root = root
        self.plan = [
            (["-t", "proc", "proc"], "proc", False),
            (["-t", "sysfs", "sysfs"], "sys", False),
            (["--bind", "/dev"], "dev", False),
            (["--bind", "/dev/pts"], "dev/pts", False),
            (["--bind", source], SOURCE_IN_CHROOT, True),
            (["--bind", build_dir], BUILD_IN_CHROOT, False),
        ]
        self.mounted = []

    def __enter__(self):
        shutil.copyfile("/etc/resolv.conf", os.path.join(self.root, "etc/resolv.conf"))
        signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # runs __exit__
        try:
            for args, target, read_only in self.plan:
                where = os.path.join(self.root, target.lstrip("/"))
                os.makedirs(where, exist_ok=True)
                subprocess.run(["mount"] + args + [where], check=True)
                self.mounted.append(where)
                if read_only:
                    subprocess.run(["mount", "-o", "remount,bind,ro", where], check=True)
        except subprocess.CalledProcessError as error:
            self.__exit__()
            raise MatrixError(f"cannot mount into {self.root}: {error}") from error
        return self

    def __exit__(self, *exc):
        for where in reversed(self.mounted):
            if subprocess.run(["umount", where]).returncode != 0:
                subprocess.run(["umount", "-l", where])
        self.mounted = []


@contextlib.contextmanager
def platform_lock(matrix, name):
    """One run per platform at a time: a second would mount over the first and unmount it."""
    path = os.path.join(matrix, f"{name}.lock")
    with open(path, "w") as handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise MatrixError(f"{name} is being tested by another run ({path} is locked)")
        yield


def unmount_stale(folder):
    """Unmounts what a run killed with SIGKILL left mounted under `folder`, deepest first:
    `rm -rf build` would otherwise reach the host's /dev through them."""
    with open("/proc/mounts") as handle:
        points = [line.split()[1] for line in handle]
    inside = [p for p in points if p.startswith(os.path.realpath(folder) + os.sep)]
    for point in sorted(inside, key=len, reverse=True):
        if subprocess.run(["umount", point]).returncode != 0:
            subprocess.run(["umount", "-l", point])


def in_chroot(root, command, log=None, extra_env=()):
    """Runs a shell command in the chroot with a clean environment; returns (exit code, output)."""
    env = ["env", "-i", "PATH=/usr/sbin:/usr/bin:/sbin:/bin", "HOME=/root", "LANG=C.UTF-8"]
    env += list(extra_env)
    argv = ["chroot", root] + env + ["bash", "-c", command]
    if log is None:
        done = subprocess.run(argv, capture_output=True, text=True)
        return done.returncode, done.stdout + done.stderr
    with open(log, "w") as out:
        process = subprocess.Popen(
            argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
        )
        lines = []
        for line in process.stdout:
            out.write(line)
            out.flush()
            lines.append(line)
        return process.wait(), "".join(lines)


def ctest_counts(output):
    """(passed, total, seconds) from ctest's summary, or None when ctest never reported."""
    summary = re.findall(r"(\d+)% tests passed, (\d+) tests? failed out of (\d+)", output)
    if not summary:
        return None
    failed, total = int(summary[-1][1]), int(summary[-1][2])
    seconds = re.findall(r"Total Test time \(real\) =\s*([\d.]+) sec", output)
    return total - failed, total, float(seconds[-1]) if seconds else float("nan")


def disk_gb(*paths):
    sizes = subprocess.run(
        ["du", "-sxb"] + [p for p in paths if os.path.exists(p)], capture_output=True, text=True
    ).stdout.split()
    return sum(int(s) for s in sizes[::2]) / 1e9


def platform_line(name, root, target, jobs, logs, keep_going=False, command=None):
    """Runs `make <target>` (or `command`) on one platform; returns (ok, the summary line)."""
    started = time.monotonic()
    code, output = in_chroot(
        root,
        command or f"cd {SOURCE_IN_CHROOT} && make {target} BUILD={BUILD_IN_CHROOT} JOBS={jobs}",
        log=os.path.join(logs, f"{name}.log"),
        extra_env=["MAKEFLAGS=-k"] if keep_going else [],
    )
    seconds = time.monotonic() - started
    _, freecad = in_chroot(root, "dpkg-query -W -f='${Version}' freecad 2>/dev/null")
    _, python = in_chroot(root, "/usr/bin/python3 -c 'import sys; print(sys.version.split()[0])'")
    counts = ctest_counts(output)
    tests = (
        f"{counts[0]}/{counts[1]} tests passed (ctest {counts[2]:.0f} s)"
        if counts
        else f"make {target} exit {code}"
    )
    ok = code == 0 and (counts is None or counts[0] == counts[1])
    line = (
        f"{name:<11} FreeCAD {freecad.strip() or '-':<14} Python {python.strip() or '-':<7} "
        f"{tests}; make {target} {seconds:.0f} s"
    )
    return ok, line


def run_platform(name, matrix, mirror, source, args):
    """The chroot made or reused, mounted, `make` run, unmounted; (ok, the summary line)."""
    root = os.path.join(matrix, name)
    unmount_stale(root)  # left by a run of this platform killed with SIGKILL
    ensure_chroot(root, PLATFORMS[name], mirror, os.path.join(matrix, f"{name}.debootstrap.log"))
    build_dir = os.path.join(matrix, f"{name}-build")
    os.makedirs(build_dir, exist_ok=True)
    with Mounts(root, source, build_dir):
        ok, line = platform_line(
            name, root, args.target, args.jobs, matrix, args.keep_going, args.command
        )
    # Measured unmounted: du would count the source tree through the bind mount.
    line += f"; disk {disk_gb(root, build_dir):.1f} GB"
    return ok, line + ("" if ok else f"  FAILED: see {matrix}/{name}.log")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build", help="the host build folder (relative)")
    parser.add_argument("--only", default=",".join(PLATFORMS), help="platforms, comma-separated")
    parser.add_argument("--target", default="test", help="the make target run on each platform")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument(
        "--keep-going", action="store_true", help="make -k: every compile error in one run"
    )
    parser.add_argument(
        "--command", help="a shell command instead of make (in /src; the build folder is /build)"
    )
    parser.add_argument(
        "--unmount",
        action="store_true",
        help="only unmount what a killed run left mounted (make clean runs it)",
    )
    args = parser.parse_args()
    if os.geteuid() != 0:
        print("test-matrix: needs root (debootstrap, chroot, mount)", file=sys.stderr)
        return 2
    source = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    matrix = os.path.join(source, args.build, "matrix")
    os.makedirs(matrix, exist_ok=True)
    if args.unmount:
        # Exit 1 while a run is going on: `make clean` must not rm -rf through its mounts.
        busy = False
        for name in PLATFORMS:
            try:
                with platform_lock(matrix, name):
                    unmount_stale(os.path.join(matrix, name))
            except MatrixError as error:
                print(f"test-matrix: {error}: left mounted", file=sys.stderr)
                busy = True
        return 1 if busy else 0
    names = [n for n in args.only.split(",") if n]
    unknown = [n for n in names if n not in PLATFORMS]
    if unknown:
        print(
            f"test-matrix: unknown platform {unknown[0]} (known: {', '.join(PLATFORMS)})",
            file=sys.stderr,
        )
        return 2
    lines, all_ok = [], True
    try:
        mirror = host_mirror()
        for name in names:
            with platform_lock(matrix, name):
                ok, line = run_platform(name, matrix, mirror, source, args)
            print(line, flush=True)
            lines.append(line)
            all_ok &= ok
    except MatrixError as error:
        print(f"test-matrix: {error}", file=sys.stderr)
        return 2
    print("\n".join(["", "test-matrix:"] + lines))
    return 0 if all_ok else 1


if __name__ == "__main__":
    sys.exit(main())
