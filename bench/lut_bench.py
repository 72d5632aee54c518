#!/usr/bin/python3
"""The baked tables' time, measured in one run: `verify lut --kind dfg` (the split-sum pair at 1e-10
with its bounds) at the sizes engines use, on all cores and on one, beside the baker engines run
(`--monte-carlo N`: GGX importance sampling at Hammersley points in float, no bound) as the peer.

Then the checks (lut_engines.py): the five tables engines ship, made in their conventions, what
`--detect` finds in each and how long it takes; a 1024^2 8-bit check and a list of points against
the same points by `--size`.

Usage: bench/lut_bench.py BUILD_DIR OUT_MD   (bench/run calls it after a Release build)
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time
import lut_engines
import machine

TARGET_128 = 2.0  # seconds of wall time for the exact 128^2 (A, B) table on 2 cores


def wall(binary, args, runs):
    """Median wall time of `runs` runs after one warm-up."""
    times = []
    for i in range(runs + 1):
        a = time.perf_counter()
        subprocess.run([binary, "lut", "--kind", "dfg"] + args, check=True, capture_output=True)
        if i:
            times.append(time.perf_counter() - a)
    return statistics.median(times)


def main():
    build, out_md = sys.argv[1], sys.argv[2]
    binary = os.path.join(build, "normzoo-verify")
    cores = os.cpu_count()
    cpu = machine.cpu_name()
    rows = []
    for n in (32, 64, 128):
        size = ["--size", str(n)]
        exact = wall(binary, size, 5)
        one = wall(binary, size + ["--jobs", "1"], 3)
        baker = {s: wall(binary, size + ["--monte-carlo", str(s)], 5) for s in (256, 1024)}
        target = ""
        if n == 128:
            target = f"target {TARGET_128:g} s: " + (f"{TARGET_128 / exact:.2f}x under" if exact <= TARGET_128 else "not met")
        rows.append(f"| {n}^2 | {exact:.3f} s wall on {cores} cores (median of 5); {one:.3f} s on one | "
                    f"{baker[256]:.3f} s / {baker[1024]:.3f} s | {exact / baker[1024]:.1f}x | {target} |")
    lines = [
        "# bench-lut: the exact split-sum table against the baker engines run, in one run",
        "",
        f"Produced by `bench/run` (Release build) on {cpu}, {cores} cores. "
        "normzoo: `verify lut --kind dfg --size N`, A and B at every texel centre to 1e-10 with their bounds "
        "(ggx/smith-height-correlated, docs/lut.md). The peer: `--monte-carlo 256` and `1024`, the table as "
        "engines bake it (its error is measured in the shortcut audit, docs/microfacet.md). Timings vary from "
        "run to run; ratios are what to quote.",
        "",
        "| size | normzoo, exact | Monte Carlo baker, 256 / 1024 samples | exact / baker at 1024, wall | |",
        "|---|---|---|---|---|",
    ] + rows
    with tempfile.TemporaryDirectory() as folder:
        lines += [
            "",
            "## Checking the tables engines ship",
            "",
            "Each made by normzoo in the engine's convention (`bench/lut_engines.py`: `verify lut` with the engine's preset, "
            "baked by `--monte-carlo` as the engine bakes it where the engine's model is the default one, then wrapped as the "
            "engine ships it), then checked by `verify lut --check FILE --kind dfg --detect` with no other key: the reading it "
            "finds, the whole check's largest errors under it, its time (median of 3), and the check by the engine's preset.",
            "",
            "| table | `--detect` finds | largest error | time, wall (CPU) | by the preset |",
            "|---|---|---|---|---|",
        ] + lut_engines.detect_rows(binary, folder)
        lines += [
            "",
            "## What a check costs",
            "",
            "Median of 3 runs each, in one run; a check computes each texel to a hundredth of its tolerance (docs/lut.md, "
            "\"How a check chooses its accuracy\").",
            "",
            "| run | wall | CPU | |",
            "|---|---|---|---|",
        ] + lut_engines.check_speed_rows(binary, folder)
    tmp = out_md + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, out_md)


if __name__ == "__main__":
    main()
