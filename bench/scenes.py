#!/usr/bin/python3
"""The scenes' speed figure, measured in one run: the wall time of `./verify --scene` for each example
scene against the full `./verify` (all tables), Release build, all cores.

Usage: bench/scenes.py OUT_MD   (bench/run calls it after a Release build)
"""
import glob
import os
import statistics
import subprocess
import sys
import tempfile
import time
import machine

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
VERIFY = os.path.join(ROOT, "verify")


def wall(args, runs=3):
    times = []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(runs + 1):
            a = time.perf_counter()
            r = subprocess.run([VERIFY] + args + ["--out", tmp], capture_output=True)
            if i:
                times.append(time.perf_counter() - a)
    return statistics.median(times), r.returncode


def main():
    out_md = sys.argv[1]
    full, _ = wall([], runs=3)
    cpu = machine.cpu_name()
    lines = ["# bench-scenes: `./verify --scene` for each example scene against the full run, in one run", "",
             f"Produced by `bench/run` (Release build) on {cpu}, {os.cpu_count()} cores; wall times, median of 3 "
             "after a warm-up. Timings vary from run to run; ratios are what to quote.", "",
             "| run | wall | exit | share of the full run |", "|---|---|---|---|",
             f"| `./verify` (every table) | {full:.2f} s | 0 | 100 % |"]
    for scene in sorted(glob.glob(os.path.join(ROOT, "scenes", "*.toml"))):
        t, code = wall(["--scene", scene])
        lines.append(f"| `./verify --scene scenes/{os.path.basename(scene)}` | {t:.2f} s | {code} | {100 * t / full:.1f} % |")
    open(out_md, "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
