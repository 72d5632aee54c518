#!/usr/bin/python3
"""The irradiance speed figures, measured in one run: `./verify irradiance` on the default grid (wall time),
and normzoo's cap quadrature against mpmath (dps 34, tanh-sinh, the azimuth done in closed form,
split at the horizon) on a sample of the same records.

Usage: bench/irradiance_vs_mpmath.py BUILD_DIR OUT_MD   (bench/run calls it after a Release build)
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import mpmath as mp

import machine

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
mp.mp.dps = 34


def cap_irradiance(light, ratio, tilt_deg):
    x = mp.mpf(ratio)
    b = mp.asin(x) if light == "sphere" else mp.atan(x)
    t = mp.radians(mp.mpf(tilt_deg))

    def ring(a):
        A, B = mp.cos(a) * mp.cos(t), mp.sin(a) * mp.sin(t)
        if B == 0:
            return 2 * mp.pi * max(A, 0) * mp.sin(a)
        c = -A / B
        if c >= 1:
            return mp.mpf(0)
        pm = mp.pi if c <= -1 else mp.acos(c)
        return (2 * pm * A + 2 * B * mp.sin(pm)) * mp.sin(a)

    a0 = abs(mp.pi / 2 - t)
    return mp.quad(ring, [0] + ([a0] if a0 < b else []) + [b])


def main():
    build, out_md = sys.argv[1], sys.argv[2]
    walls = []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(6):
            a = time.perf_counter()
            subprocess.run([os.path.join(ROOT, "verify"), "irradiance", "--out", tmp], check=True, capture_output=True)
            if i:
                walls.append(time.perf_counter() - a)
            one = time.perf_counter()
            subprocess.run([os.path.join(ROOT, "verify"), "irradiance", "--jobs", "1", "--out", tmp], check=True,
                           capture_output=True) if i == 1 else None
            if i == 1:
                single = time.perf_counter() - one
        rows = [json.loads(l.strip().rstrip(",")) for l in open(os.path.join(tmp, "irradiance.json")) if l.startswith("  {")]
        punctual = [json.loads(l.strip().rstrip(",")) for l in open(os.path.join(tmp, "punctual-limit.json")) if l.startswith("  {")]
    wall = statistics.median(walls)
    sample = [r for r in rows if r["tilt_deg"] in (0, 60, 85, 89.9, 90.5) and r["ratio"] in (1e-1, 1e-2, 1e-15, 1e-300)]
    mp_times, mp_digits, ours_digits, cases = [], [], [], []
    for r in sample:
        a = time.perf_counter()
        e = cap_irradiance(r["light"], r["ratio"], r["tilt_deg"])
        mp_times.append(time.perf_counter() - a)
        closed = mp.mpf(r["E_closed_form"])
        if closed != 0:
            rel = abs(e - closed) / closed
            mp_digits.append(float(-mp.log10(rel)) if rel > 0 else 34.0)
            ours_digits.append(r["digits"])
            cases.append(f"{r['light']} ratio {r['ratio']:g} tilt {r['tilt_deg']:g}")
    worst_case = cases[mp_digits.index(min(mp_digits))]
    out = subprocess.run([os.path.join(build, "bench", "normzoo-bench-irradiance")], check=True, capture_output=True,
                         text=True).stdout
    bench_rows = [json.loads(l) for l in out.splitlines()]
    per = {(r["light"], r["ratio"], r["tilt"]): r["seconds"] for r in bench_rows}
    # What exact decimal inputs cost: the cap at the decimals (with the rounding terms) against
    # the cap at the doubles nearest them, point by point in the same run.
    exact_cost = statistics.median(r["seconds"] / r["seconds_double_input"] for r in bench_rows)
    ours_times = [per[(r["light"], r["ratio"], r["tilt_deg"])] for r in sample]
    all_times = sorted(per.values())
    cpu = machine.cpu_name()
    lines = [
        "# bench-irradiance: the irradiance tables' time, and the cap quadrature against mpmath, in one run",
        "",
        f"Produced by `bench/run` (Release build) on {cpu}, {os.cpu_count()} cores; mpmath {mp.__version__} "
        f"(backend {mp.libmp.BACKEND}) at dps 34. Timings vary from run to run; ratios are what to quote.",
        "",
        "| what | normzoo | mpmath | ratio |",
        "|---|---|---|---|",
        f"| default `./verify irradiance` ({len(rows)} irradiance records, {len(punctual)} punctual-limit records, "
        f"summary, plot and files) | {wall:.2f} s wall on {os.cpu_count()} cores (median of 5); {single:.2f} s on one | | |",
        f"| one cap irradiance, all {len(all_times)} default records, one core | median {statistics.median(all_times) * 1e3:.2f} ms, "
        f"slowest {all_times[-1] * 1e3:.2f} ms | | |",
        f"| one cap irradiance, {len(sample)} records of the default grid (tilts 0, 60, 85, 89.9, 90.5; ratios 1e-1, "
        f"1e-2, 1e-15, 1e-300) | median {statistics.median(ours_times) * 1e3:.2f} ms (binary128, 30x30 and 20x20 "
        f"Gauss-Legendre, azimuth by quadrature) | median {statistics.median(mp_times) * 1e3:.1f} ms (tanh-sinh, "
        f"azimuth in closed form) | {statistics.median(mp_times) / statistics.median(ours_times):.1f}x faster |",
        f"| r0/r and the tilt as the decimals typed, against the doubles nearest them, per record | median "
        f"{exact_cost:.3f}x | | |",
        f"| fewest digits against the closed form on those records | {min(ours_digits):.1f} (binary128, two product "
        f"rules) | {min(mp_digits):.1f} (at {worst_case}) | |",
        "",
    ]
    open(out_md, "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
