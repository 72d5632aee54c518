#!/usr/bin/python3
"""The zoo's speed figures, measured in one run: normzoo's zoo against mpmath at 35 digits.

Usage: bench/zoo_vs_mpmath.py BUILD_DIR OUT_MD   (bench/run calls it after a Release build)
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import mpmath_zoo  # noqa: E402
import machine  # noqa: E402
from lines import run_lines  # noqa: E402


def main():
    build, out_md = sys.argv[1], sys.argv[2]
    # 1. ./verify zoo on the default grid, 2D checks included, wall time over 7 runs after a warm-up.
    walls = []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(8):
            a = time.perf_counter()
            subprocess.run([os.path.join(ROOT, "verify"), "zoo", "--out", tmp], check=True, capture_output=True)
            if i:
                walls.append(time.perf_counter() - a)
        zoo = json.load(open(os.path.join(tmp, "zoo.json")))["records"]
    wall = statistics.median(walls)
    # 2. One integral at a time (median of 21 runs each).
    per = run_lines([os.path.join(build, "bench", "normzoo-bench-zoo"), "21"])
    # 3. mpmath, same 1D integrals at 35 digits, in this same run.
    a = time.perf_counter()
    import io, contextlib
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        sys.argv = ["mpmath_zoo.py", "35"]
        mpmath_zoo.main()
    mp_wall = time.perf_counter() - a
    mp = [json.loads(l) for l in buf.getvalue().splitlines()]
    mp_whole = sum(r["seconds_whole"] for r in mp)
    mp_split = sum(r["seconds_split"] for r in mp)

    med1 = statistics.median(r["seconds_1d"] for r in per)
    med2 = statistics.median(r["seconds_2d"] for r in per)
    # What exact decimal inputs cost: the same integral at the decimal (with its rounding term)
    # and at the double nearest it, point by point in the same run.
    exact_cost = statistics.median(r["seconds_1d"] / r["seconds_1d_double_input"] for r in per)
    exact_cost_inexact = [r["seconds_1d"] / r["seconds_1d_double_input"] for r in per if r["n_input"] in ("0.1",)]
    mp_med = statistics.median(r["seconds_whole"] for r in mp)
    ours_digits = min(r["digits"] for r in zoo)
    ours_digits_2d = min(r["digits_2d"] for r in zoo)
    worst_ratio = max(r["rel_error"] / r["error_estimate"] for r in zoo)
    cpu = machine.cpu_name()
    lines = [
        "# bench-zoo: normzoo's zoo against mpmath at 35 digits, measured in one run",
        "",
        f"Produced by `bench/run` (Release build) on {cpu}, {os.cpu_count()} cores; mpmath {mpmath_zoo.mp.__version__} "
        f"with the {mpmath_zoo.mp.libmp.BACKEND} backend. Timings vary from run to run; ratios are what to quote.",
        "",
        "| what | normzoo | mpmath (35 digits) | ratio |",
        "|---|---|---|---|",
        f"| whole default grid ({len(zoo)} zoo records) | `./verify zoo` wall, 2D checks, constants and files included: "
        f"{wall * 1e3:.1f} ms (median of 7) | the {len(mp)} 1D integrals over [0, pi/2]: {mp_whole * 1e3:.0f} ms "
        f"(with lobe split points: {mp_split * 1e3:.0f} ms) | {mp_whole / wall:.1f}x faster |",
        f"| one 1D integral, median over the grid | {med1 * 1e6:.0f} us (binary128, two rules) | {mp_med * 1e6:.0f} us | "
        f"{mp_med / med1:.1f}x faster, one core each |",
        f"| one 2D vector integral, median | {med2 * 1e6:.0f} us (long double) | (none) | |",
        f"| the exponent as the decimal typed, against the double nearest it, per point | median {exact_cost:.3f}x "
        f"(an input binary128 holds: the exactness test only); at n = 0.1, which it does not hold: "
        f"{', '.join(f'{x:.2f}x' for x in exact_cost_inexact)} (a second quadrature measures the slope) | | |",
        f"| fewest correct digits over the grid | 1D {ours_digits:.1f}, 2D {ours_digits_2d:.1f} | whole interval "
        f"{min(r['digits_whole'] for r in mp):.1f}, split {min(r['digits_split'] for r in mp):.1f} | |",
        f"| largest true error / error estimate (1D) | {worst_ratio:.3f} (must be <= 1) | mpmath gives no bound it guarantees | |",
        "",
        "Per integral (seconds; normzoo one core, median of 21 after a warm-up; mpmath one call):",
        "",
        "| row | n | normzoo 1D | normzoo 2D | evaluations 1D | mpmath whole | mpmath digits |",
        "|---|---|---|---|---|---|---|",
    ]
    by_key = {(r["row"], float(r["n"])): r for r in mp}
    for r in per:
        m = by_key[(r["row"], float(r["n"]))]
        lines.append(f"| {r['row']} | {r['n']:g} | {r['seconds_1d']:.2e} | {r['seconds_2d']:.2e} | {r['evaluations_1d']} | "
                     f"{m['seconds_whole']:.2e} | {m['digits_whole']:.1f} |")
    open(out_md, "w").write("\n".join(lines) + "\n")
    print("\n".join(lines[:12]))


if __name__ == "__main__":
    main()
