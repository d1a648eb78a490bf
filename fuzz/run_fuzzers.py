#!/usr/bin/python3
"""Runs the libFuzzer targets of fuzz/ for a given time each and sums up what they found.

Each target fuzzes a working corpus under --work (seeded from fuzz/corpus/<target>, which it never
writes), with crash, leak, timeout and slow-unit files written to <work>/<target>/artifacts/.
Exit status 0 only when every target ran its time without a crash, a leak, a timeout, an
out-of-memory or a sanitizer report. Used by `make fuzz` and by the ctest test fuzz_smoke.
"""

import argparse
import os
import re
import subprocess
import sys
import time

TARGETS = ["design_file", "check_validity"]
HERE = os.path.dirname(os.path.abspath(__file__))


def run_target(args, target):
    binary = os.path.join(args.build_dir, f"{target}_fuzzer")
    if not os.access(binary, os.X_OK):
        sys.exit(f"run_fuzzers: {binary} is missing: build the fuzz tree first (make build)")
    work = os.path.join(args.work, target)
    corpus = os.path.join(work, "corpus")
    artifacts = os.path.join(work, "artifacts")
    os.makedirs(corpus, exist_ok=True)
    os.makedirs(artifacts, exist_ok=True)
    log_path = os.path.join(work, "fuzz.log")
    command = [
        binary,
        f"-max_total_time={args.seconds}",
        f"-timeout={args.timeout}",
        f"-report_slow_units={args.slow}",
        f"-rss_limit_mb={args.rss_limit_mb}",
        "-print_final_stats=1",
        f"-artifact_prefix={artifacts}/",
        corpus,
        os.path.join(HERE, "corpus", target),
    ] + args.libfuzzer_args
    env = dict(os.environ)
    # Leaks are findings; a UBSan report stops the run (the build also uses
    # -fno-sanitize-recover=all).
    env.setdefault("ASAN_OPTIONS", "detect_leaks=1:abort_on_error=1")
    env.setdefault("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1")
    print(f"== {target}: {' '.join(command)}", flush=True)
    started = time.monotonic()
    with open(log_path, "w") as log:
        status = subprocess.call(command, stdout=log, stderr=subprocess.STDOUT, env=env)
    elapsed = time.monotonic() - started
    with open(log_path, errors="replace") as log:
        text = log.read()

    def stat(name):
        found = re.findall(rf"stat::{name}:\s+(\d+)", text)
        return int(found[-1]) if found else None

    done = re.findall(r"#(\d+)\s+DONE\s+cov: (\d+) ft: (\d+) corp: (\d+)/(\S+)", text)
    slow = re.findall(r"Slowest unit: (\d+) s", text)
    reports = re.findall(
        r"ERROR: (?:AddressSanitizer|LeakSanitizer|libFuzzer)[^\n]*|runtime error:[^\n]*", text
    )
    summary = {
        "target": target,
        "status": status,
        "seconds": round(elapsed),
        "executions": stat("number_of_executed_units"),
        "peak_rss_mb": stat("peak_rss_mb"),
        "coverage": int(done[-1][1]) if done else None,
        "corpus_units": len(os.listdir(corpus)),
        "slowest_unit_s": max(map(int, slow)) if slow else 0,
        "reports": reports,
        "log": log_path,
    }
    print(
        f"   {target}: exit {status}, {summary['executions']} executions in {elapsed:.0f} s, "
        f"cov {summary['coverage']}, corpus {summary['corpus_units']} units, "
        f"peak RSS {summary['peak_rss_mb']} MB, slowest unit >= {args.slow} s: "
        f"{summary['slowest_unit_s'] or 'none'}",
        flush=True,
    )
    for report in reports:
        print(f"   {report}", flush=True)
    if status != 0:
        print(text[-6000:], flush=True)
    return summary


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build-dir", required=True, help="folder with the *_fuzzer binaries")
    parser.add_argument("--work", required=True, help="working corpora, logs and artifacts")
    parser.add_argument("--seconds", type=int, default=60, help="per target (default 60)")
    parser.add_argument("--timeout", type=int, default=10, help="an input this slow (s) fails")
    parser.add_argument("--slow", type=int, default=1, help="report inputs this slow (s)")
    parser.add_argument("--rss-limit-mb", type=int, default=2048)
    parser.add_argument("--targets", nargs="+", default=TARGETS, choices=TARGETS)
    parser.add_argument("libfuzzer_args", nargs="*", help="passed on (after --)")
    args = parser.parse_args()
    summaries = [run_target(args, target) for target in args.targets]
    failed = [s["target"] for s in summaries if s["status"] != 0 or s["reports"]]
    if failed:
        sys.exit(f"run_fuzzers: findings in {', '.join(failed)} (see the logs and artifacts)")
    print("run_fuzzers: no crash, leak, timeout or sanitizer report", flush=True)


if __name__ == "__main__":
    main()
