#!/usr/bin/python3
"""The albedo speed figures, measured in one run: the albedo at 1e-10 per point against SciPy's
dblquad on the same points, the single-core time of every point of the default sweep, and the
wall time of `./verify energy` on all cores.

Usage: bench/energy_vs_scipy.py BUILD_DIR OUT_MD   (bench/run calls it after a Release build)
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time
import machine
from lines import run_lines

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def main():
    build, out_md = sys.argv[1], sys.argv[2]
    bench = os.path.join(build, "bench", "normzoo-bench-albedo")
    # 1. ./verify energy, default grid, all cores: median of 3 after a warm-up.
    walls = []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(4):
            a = time.perf_counter()
            subprocess.run([os.path.join(ROOT, "verify"), "energy", "--out", tmp], check=True, capture_output=True)
            if i:
                walls.append(time.perf_counter() - a)
    wall = statistics.median(walls)
    # 2. Every point of the default sweep, one core, one at a time.
    sweep = run_lines([bench, "sweep"])
    secs = sorted(r["seconds"] for r in sweep)
    p90 = secs[int(0.9 * (len(secs) - 1))]
    # 3. The peer points: normzoo median of 5, SciPy median of 3 (one call when slow).
    ours = run_lines([bench, "points", "5"])
    scipy = run_lines(["/usr/bin/python3", os.path.join(HERE, "scipy_albedo.py")])
    ratios = [s["seconds"] / o["seconds"] for o, s in zip(ours, scipy)]
    cpu = machine.cpu_name()
    lines = [
        "# bench-energy: the directional albedo at 1e-10 against SciPy's dblquad, measured in one run",
        "",
        f"Produced by `bench/run` (Release build) on {cpu}, {os.cpu_count()} cores; SciPy {scipy[0]['scipy']} "
        "(`integrate.dblquad`, QUADPACK, epsabs = epsrel = 1e-10, the BRDF written again in Python from vectors, "
        "the same mirror symmetry). Timings vary from run to run; ratios are what to quote.",
        "",
        "| what | normzoo | peer | ratio |",
        "|---|---|---|---|",
        f"| whole default sweep ({len(sweep)} albedo points, 9 forms, 14 exponents, 93 angles) | `./verify energy` "
        f"wall on {os.cpu_count()} cores, summary refinement, claims, F V tables, Monte Carlo and files included: "
        f"{wall:.2f} s (median of 3) | target 10 s | {10 / wall:.1f}x under |",
        f"| one albedo point of the default sweep, one core | median {statistics.median(secs) * 1e3:.3f} ms, "
        f"mean {statistics.mean(secs) * 1e3:.3f} ms, 90th percentile {p90 * 1e3:.2f} ms, "
        f"slowest {secs[-1] * 1e3:.1f} ms | target 1 ms (median) | |",
        f"| the {len(ours)} peer points below, one core each | median {statistics.median(o['seconds'] for o in ours) * 1e3:.3f} ms "
        f"| SciPy dblquad median {statistics.median(s['seconds'] for s in scipy) * 1e3:.2f} ms "
        f"| median {statistics.median(ratios):.1f}x faster (from {min(ratios):.1f}x to {max(ratios):.0f}x) |",
        "",
        "Per point: normzoo's value with its error bound, SciPy's value with the error it claims, and the time of "
        "each (normzoo median of 5 after a warm-up; SciPy median of 3, or one call over 0.1 s).",
        "",
        "| model | n | theta (deg) | normzoo albedo | bound | SciPy albedo | SciPy claims | difference | "
        "SciPy warnings | normzoo time | SciPy time | ratio |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for o, s, q in zip(ours, scipy, ratios):
        diff = abs(o["albedo"] - s["albedo"])
        lines.append(f"| {o['model']} | {o['n']:g} | {o['theta']:g} | {o['albedo']:.14g} | {o['error']:.1e} | "
                     f"{s['albedo']:.14g} | {s['claimed_error']:.1e} | {diff:.1e} | {s['warnings']} | "
                     f"{o['seconds'] * 1e3:.3f} ms | {s['seconds'] * 1e3:.2f} ms | {q:.1f}x |")
    lines += ["", "Single-core time per point of the default sweep, by form:", "",
              "| model | points | median (ms) | 90th percentile (ms) | slowest (ms) | evaluations (median) |",
              "|---|---|---|---|---|---|"]
    models = []
    for r in sweep:
        if r["model"] not in models:
            models.append(r["model"])
    for m in models:
        t = sorted(r["seconds"] for r in sweep if r["model"] == m)
        ev = statistics.median(r["evaluations"] for r in sweep if r["model"] == m)
        lines.append(f"| {m} | {len(t)} | {statistics.median(t) * 1e3:.3f} | {t[int(0.9 * (len(t) - 1))] * 1e3:.2f} | "
                     f"{t[-1] * 1e3:.1f} | {ev:.0f} |")
    open(out_md, "w").write("\n".join(lines) + "\n")
    print("\n".join(lines[:10]))


if __name__ == "__main__":
    main()
