#!/usr/bin/python3
"""The engine-style example (examples/brdfs/engine/, docs/brdf-code.md#an-engines-file) against the
built-in composition it writes out, in one run: its first run (the shader cache empty: preprocessing,
validation, translation and compilation of its programs) and its cached runs, beside `energy --model`
on the same points. Release build; medians of several runs; the ratios are what to quote.

Usage: bench/brdf_engine.py BUILD_DIR OUT_MD   (bench/run calls it after a Release build)
"""
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import machine

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENGINE = os.path.join(ROOT, "examples", "brdfs", "engine")
MUS = "1,0.7,0.5,0.3,0.1"


def engine_args(defines):
    return (["--brdf", os.path.join(ENGINE, "specular.glsl"), "--include-dir", os.path.join(ENGINE, "common")] + defines +
            ["--param", "perceptualRoughness=0.5", "--param", "f0=0.04,0.04,0.04", "--mu", MUS])


def run(binary, args, cache):
    """Wall seconds of one run, and what it says on stderr."""
    env = dict(os.environ, NORMZOO_CACHE_DIR=cache)
    a = time.perf_counter()
    p = subprocess.run([binary] + args, capture_output=True, text=True, env=env)
    t = time.perf_counter() - a
    if p.returncode != 0:
        sys.exit(f"brdf_engine.py: {' '.join(args)} exited {p.returncode}: {p.stderr}")
    return t, p.stderr


def first_and_cached(binary, args, runs):
    """Medians of the first run (a fresh cache each time), the compile seconds it reports, and cached runs."""
    firsts, compiles, cached = [], [], []
    for _ in range(runs):
        cache = tempfile.mkdtemp(prefix="normzoo-bench-cache-")
        try:
            t, err = run(binary, args, cache)
            firsts.append(t)
            m = re.search(r"compiled in ([0-9.e+-]+) s", err)
            compiles.append(float(m.group(1)) if m else float("nan"))
            cached.append(run(binary, args, cache)[0])
        finally:
            shutil.rmtree(cache, ignore_errors=True)
    return statistics.median(firsts), statistics.median(compiles), statistics.median(cached)


def built_in(binary, model, runs):
    """Median wall seconds of `energy --model` on the same points, after one warm-up."""
    args = ["energy", "--model"] + model.split(" ") + ["--alpha", "0.25", "--mu", MUS, "--json"]
    return statistics.median([run(binary, args, tempfile.gettempdir())[0] for _ in range(runs + 1)][1:])


def main():
    build, out_md = sys.argv[1], sys.argv[2]
    binary = os.path.join(build, "normzoo-verify")
    runs = 5
    rows = []
    for label, defines, model in (("desktop (SPECULAR_QUALITY 1)", [], "ggx/smith-height-correlated/schlick --f0 0.04"),
                                  ("mobile (TARGET_MOBILE, SPECULAR_QUALITY=0)", ["--define", "TARGET_MOBILE", "--define", "SPECULAR_QUALITY=0"],
                                   "ggx/hammon/schlick --f0 0.04")):
        first, compile_s, cached = first_and_cached(binary, engine_args(defines), runs)
        peer = built_in(binary, model, runs)
        rows.append(f"| {label} | {first:.2f} s ({compile_s:.2f} s compiling) | {cached:.3f} s | `{model}`: {peer:.3f} s | "
                    f"{first / peer:.0f}x | {cached / peer:.1f}x |")
    lines = [
        "# bench-brdf-engine: an engine's shader file against the composition it writes out",
        "",
        f"Produced by `bench/run` (Release build) on {machine.cpu_name()}, {os.cpu_count()} cores. The file: "
        "`examples/brdfs/engine/specular.glsl` with `--include-dir examples/brdfs/engine/common`, perceptual "
        f"roughness 0.5 (alpha 0.25), F0 = 0.04, mu = {MUS}, L fixed, tolerance 1e-10; the whole command, "
        f"wall time, median of {runs} runs. First run: an empty shader cache (preprocessing, validation, "
        "translation, compilation); cached: the same command again. The peer: `verify energy --model` on the "
        "same points, the built-in composition's exact integral.",
        "",
        "| build | first run | cached run | built-in | first / built-in | cached / built-in |",
        "|---|---|---|---|---|---|",
    ] + rows + [""]
    tmp = out_md + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines))
    os.replace(tmp, out_md)


if __name__ == "__main__":
    main()
