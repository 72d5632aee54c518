#!/usr/bin/python3
"""The material speed figures, measured in one run: a glTF material point (whole: every lobe and
channel; and each lobe alone) at 1e-10, one core, median of 15, over roughness and incidence, against
the 200 us target; and the whole point against SciPy's dblquad on the peer's points, with both values.

Usage: bench/material_vs_scipy.py BUILD_DIR OUT_MD   (bench/run calls it after a Release build)
"""
import os
import statistics
import subprocess
import sys
import machine
from lines import run_lines

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    build, out_md = sys.argv[1], sys.argv[2]
    bench = os.path.join(build, "bench", "normzoo-bench-material")
    grid = run_lines([bench])
    ours = run_lines([bench, "peer"])
    configurations = run_lines([bench, "materials"])
    scipy = run_lines(["/usr/bin/python3", os.path.join(HERE, "scipy_material.py")])
    whole = [p["whole_us"] for p in grid]
    lobes = [max(p["diffuse_us"], p["specular_us"], p["metal_us"]) for p in grid]
    lines = [
        "# bench-material: a glTF material point at 1e-10, and SciPy's dblquad on the same points, measured in one run",
        "",
        f"Produced by `bench/run` (Release build) on {machine.cpu_name()}, one core; SciPy {scipy[0]['scipy']} "
        "(`integrate.dblquad`, QUADPACK, epsabs = epsrel = 1e-10, the material written again in Python from the "
        "specification, one dblquad per channel). Timings vary from run to run; ratios are what to quote.",
        "",
        f"A whole point (every lobe and channel, `material::albedo_of`), over {len(grid)} points (roughness 0.01 to 1, "
        f"mu 1e-4 to 1, baseColor 0.8, 0.4, 0.2, metallic 0.5): median {statistics.median(whole):.1f} us, largest "
        f"{max(whole):.1f} us (target: median at most 200 us); the slowest lobe alone: median "
        f"{statistics.median(lobes):.1f} us, largest {max(lobes):.1f} us.",
    ]
    lines += [
        "",
        "Each material and compensation the command takes (`material::albedo`, a whole point: every lobe and channel), "
        "over the same 25 points (roughness 0.01 to 1, mu 1e-4 to 1); glTF at baseColor 0.8, 0.4, 0.2, metallic 0.5. "
        "The first point (roughness 0.01, mu 1e-4) is also timed alone before them: under a sheen it builds the curve of "
        "the sheen's E for its alpha, under Kulla-Conty its E_avg and lost energy, which the other points at that alpha "
        "then read (docs/materials.md, \"E as a curve\"). A point's median reads them too, "
        "so the 25 points are also swept once, each once, on a new thread that has kept nothing: `a sweep, per point` is "
        "that sweep's time over 25, what a furnace over mu at five alphas pays a point:",
        "",
        "| material | median | largest | first point, alone | a sweep, per point | median against the 200 us target |",
        "|---|---|---|---|---|---|",
    ]
    for c in configurations:
        verdict = "within" if c["median_us"] <= 200 else (f"{c['median_us'] / 200:,.0f}x over" if c['median_us'] >= 20000 else f"{c['median_us'] / 200:.3g}x over")
        lines.append(f"| `{c['material']}` | {c['median_us']:.1f} us | {c['largest_us']:.1f} us | {c['first_us']:.1f} us | {c['sweep_us']:.1f} us | {verdict} |")
    lines += ["", "SciPy on the points of its own table, the same material single scattering:", "",
              "| baseColor | metallic | roughness | mu | masking | normzoo albedo (R) | its bound | SciPy albedo (R) | "
              "normzoo | SciPy | ratio |",
              "|---|---|---|---|---|---|---|---|---|---|---|"]
    for o, s in zip(ours, scipy):
        ratio = s["seconds"] * 1e6 / o["whole_us"]
        lines.append(f"| {', '.join(f'{c:g}' for c in s['baseColor'])} | {s['metallic']:g} | {s['roughness']:g} | {s['mu']:g} | "
                     f"{s['masking']} | {o['albedo_rgb'][0]:.12f} | {o['error'][0]:.2g} | {s['albedo_rgb'][0]:.12f} | "
                     f"{o['whole_us']:.1f} us | {s['seconds'] * 1e3:.2f} ms | {ratio:.0f}x |")
    with open(out_md + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(out_md + ".tmp", out_md)


if __name__ == "__main__":
    main()
