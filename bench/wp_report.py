#!/usr/bin/python3
"""results/bench.md and the work-precision plots, from one run of the harness and its peers.

Usage: bench/wp_report.py BUILD_DIR OUT_DIR [--smoke]
Runs normzoo-bench-wp (C++: Boost.Math's integrators, fixed Gauss, trapezoid, Monte Carlo and
normzoo's scheme in double, long double, float128 and 50 digits), then bench/wp_peers.py
(mpmath, SciPy), then the speed targets (zoo 1D against mpmath at 35 digits, the double
path, the albedo point, the whole ./verify and a one-material scene, peak memory), and writes
OUT_DIR/bench.md and OUT_DIR/bench-<family>.svg.
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
import machine

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)

TARGETS = (1e-8, 1e-15, 1e-30)


def run_measured(cmd, **kw):
    """Runs cmd; returns (stdout, wall seconds, peak resident MiB of the process, from wait4).
    ./verify execs its binary, so for it the peak is the binary's."""
    with tempfile.TemporaryFile() as err:
        a = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=err, text=True, **kw)
        out = p.stdout.read()
        _, status, usage = os.wait4(p.pid, 0)
        wall = time.perf_counter() - a
        p.stdout.close()
        p.returncode = os.waitstatus_to_exitcode(status)
        if p.returncode != 0:
            err.seek(0)
            sys.exit(f"{cmd[0]} failed ({p.returncode}): {err.read()[-2000:].decode(errors='replace')}")
    return out, wall, usage.ru_maxrss / 1024


def curves(runs):
    by = {}
    for r in runs:
        by.setdefault((r["method"], r["type"]), []).append(r)
    return by


# An error below a type's rounding unit is luck (the truth happened to round to it): a point is
# credited with at most its type's precision.
FLOOR = {"double": 1.1e-16, "long double": 5.4e-20, "float128": 9.6e-35, "50 digits": 1e-50}


def credited(p, truth):
    floor = FLOOR.get(p["type"])
    if floor is None and p["method"].startswith("mpmath"):
        floor = 10.0 ** -int(p["knob"].split()[-1])
    return max(p["error"], (floor or 0) * abs(truth))


def cheapest(points, target):
    ok = [p for p in points if p["credited"] <= target]
    return min(ok, key=lambda p: p["seconds"]) if ok else None


def plot(family, desc, by, out_svg):
    """One log-log plot per family: seconds against achieved error, one curve per method and type."""
    data = []
    for (method, type_), pts in sorted(by.items()):
        pts = sorted(pts, key=lambda p: p["seconds"])
        # the floor of an exact answer: show errors below 1e-50 at 1e-50
        rows = "\n".join(f"{max(p['error'], 1e-50):.3e} {p['seconds']:.4e}" for p in pts)
        style = "linespoints lw 3 pt 7" if method == "normzoo" else "linespoints lw 1 pt 6"
        data.append((f"{method} ({type_})".replace("_", "\\_"), rows, style))
    script = [
        "set terminal svg size 1100,700 dynamic font 'Sans,11' background rgb 'white'",
        f"set output '{out_svg}'",
        f"set title '{desc}' noenhanced",
        "set logscale xy", "set format x '10^{%L}'", "set format y '10^{%L}'",
        "set xlabel 'achieved error |value - truth| (left is better)'", "set ylabel 'seconds per integral (lower is better)'",
        "set xrange [*:1] reverse", "set grid", "set key outside right top font ',9'",
    ]
    plots = []
    for i, (title, rows, style) in enumerate(data):
        script.append(f"$d{i} << EOD\n{rows}\nEOD")
        plots.append(f"$d{i} using 1:2 with {style} title '{title}'")
    script.append("plot " + ", \\\n     ".join(plots))
    subprocess.run(["gnuplot"], input="\n".join(script) + "\n", text=True, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def main():
    build, out_dir = sys.argv[1], sys.argv[2]
    smoke = "--smoke" in sys.argv
    wp_bin = os.path.join(build, "bench", "normzoo-bench-wp")
    with tempfile.TemporaryDirectory() as tmp:
        wp_path = os.path.join(tmp, "wp.jsonl")
        args = [wp_bin] + (["--smoke"] if smoke else [])
        out, wp_wall, wp_rss = run_measured(args)
        open(wp_path, "w").write(out)
        peers, peers_wall, _ = run_measured(["/usr/bin/python3", os.path.join(HERE, "wp_peers.py"), wp_path] + (["--smoke"] if smoke else []))
    lines = [json.loads(l) for l in out.splitlines()] + [json.loads(l) for l in peers.splitlines()]
    families = [l for l in lines if l["kind"] == "family"]
    runs = [l for l in lines if l["kind"] == "run"]
    truth_of = {f["family"]: float(f["truth"]) for f in lines if f["kind"] == "family"}
    for r in runs:
        r["credited"] = credited(r, truth_of[r["family"]])
    gave = [l for l in lines if l["kind"] == "gave_up"]

    cpu = machine.cpu_name()
    md = ["# bench: work-precision of normzoo against its peers, measured in one run", "",
          f"Produced by `./verify bench` (`bench/run`, Release build) on {cpu}, {os.cpu_count()} cores"
          + (" (smoke run: one point per curve, not for quoting)" if smoke else "") + ". "
          "Each point is one integral: time is the minimum over repeated calls after a warm-up, error is "
          "|value - truth| against a closed form evaluated in 50 digits (or, for the grazing albedo, normzoo's "
          "own 1e-14 result with its bound). Timings vary from run to run; the ratios are what to quote.", ""]

    md += ["## Ratios at equal error", "",
           "Time of the cheapest point of each peer that reaches the error, divided by the time of normzoo's "
           "cheapest point that reaches it (any number type). Above 1: normzoo is faster. `-`: the peer never "
           "reaches that error in this run.", ""]
    peers_of_interest = ["mpmath quad (15 digits)", "mpmath quad (32 digits)", "mpmath quad (50 digits)", "SciPy quad",
                         "SciPy dblquad", "pbrt-style Monte Carlo", "naive Monte Carlo", "tanh_sinh", "exp_sinh",
                         "gauss_kronrod 15", "gauss_kronrod 31", "gauss_kronrod 61", "trapezoidal", "gauss 20 fixed"]
    md.append("| family | error | normzoo | " + " | ".join(peers_of_interest) + " |")
    md.append("|---|---|---|" + "---|" * len(peers_of_interest))
    behind = []
    for fam in families:
        fr = [r for r in runs if r["family"] == fam["family"]]
        ours = [r for r in fr if r["method"] == "normzoo"]
        for target in TARGETS:
            if fam["truth_error"] > target / 10:
                continue  # the reference cannot tell errors this small
            best = cheapest(ours, target)
            cells = []
            for peer in peers_of_interest:
                p = cheapest([r for r in fr if r["method"] == peer], target)
                if p is None:
                    cells.append("-")
                elif best is None:
                    cells.append(f"{p['seconds'] * 1e6:.0f} us (normzoo: -)")
                    behind.append((fam["family"], target, peer, p, None))
                else:
                    ratio = p["seconds"] / best["seconds"]
                    cells.append(f"{ratio:.3g}x")
                    if ratio < 1:
                        behind.append((fam["family"], target, peer, p, best))
            md.append(f"| {fam['family']} | {target:.0e} | "
                      + (f"{best['seconds'] * 1e6:.1f} us ({best['type']})" if best else "-") + " | " + " | ".join(cells) + " |")
    md.append("")
    md += ["## Where normzoo is not ahead", ""]
    if not behind:
        md.append("Nowhere in this run.")
    else:
        md += ["Why, in short (details in `docs/method.md`, section Speed): normzoo always spends both of its "
               "rules, to give a bound it can stand behind, so a smooth integrand that a peer's first rule "
               "happens to resolve can cost normzoo as much or more; and its albedo panels are graded for a "
               "lobe cut by the horizon, which a mild incidence needs less than grazing light does, so at a "
               "loose tolerance they are what the time is spent on.", ""]
    for fam, target, peer, p, best in behind:
        md.append(f"- {fam} at {target:.0e}: {peer} ({p['type']}, {p['knob']}) {p['seconds'] * 1e6:.1f} us"
                  + (f" against normzoo's {best['seconds'] * 1e6:.1f} us ({best['type']})." if best else "; normzoo does not reach it."))
    md.append("")

    md += ["## The families", ""]
    for fam in families:
        mantissa, _, exponent = fam["truth"].partition("e")
        md.append(f"- **{fam['family']}** ({fam['dimension']}D): {fam['description']}; truth {mantissa[:40]}e{exponent}"
                  + (f" +- {fam['truth_error']:.1e}" if fam["truth_error"] else "") + f". Plot: `bench-{fam['family']}.svg`.")
        plot(fam["family"], f"{fam['family']}: {fam['description']}", curves([r for r in runs if r["family"] == fam["family"]]),
             os.path.join(out_dir, f"bench-{fam['family']}.svg"))
    md.append("")

    # The best point of every curve, and whether its own error report covered the true error.
    md += ["## Every curve: its most accurate point", "",
           "A **no** in the last column is a confident wrong answer: the method reported less error than it made.", "",
           "| family | method | type | knob | seconds | achieved error | reported error | reported >= achieved |",
           "|---|---|---|---|---|---|---|---|"]
    for fam in families:
        fr = curves([r for r in runs if r["family"] == fam["family"]])
        for (method, type_), pts in sorted(fr.items()):
            p = min(pts, key=lambda r: (r["error"], r["seconds"]))
            rep = p["reported_error"]
            # below the reference's own bound an error cannot be told, nor whether a report covers it
            unresolved = p["error"] < fam["truth_error"]
            honest = "" if rep < 0 or unresolved else ("yes" if rep >= p["error"] else "**no**")
            shown = f"< {fam['truth_error']:.1e} (reference)" if unresolved else f"{p['error']:.1e}"
            md.append(f"| {fam['family']} | {method} | {type_} | {p['knob']} | {p['seconds']:.2e} | {shown} | "
                      + (f"{rep:.1e}" if rep >= 0 else "(none)") + f" | {honest} |")
    md.append("")
    if gave:
        md += ["Points given up (an adaptive rule past 4e6 evaluations, or a peer past its time limit): "
               + "; ".join(f"{g['family']} {g['method']} ({g['type']}, {g['knob']})" for g in gave) + ".", ""]

    albedo_points = [r for r in runs if r["family"].startswith("albedo") and r["method"] == "normzoo" and r["knob"] == "1e-10"]
    md += targets(build, smoke, albedo_points)
    md += growth(runs, smoke)
    md += [f"The harness ran in {wp_wall:.0f} s"
           + (f" with a peak resident memory of {wp_rss:.1f} MiB" if wp_rss else "") + f"; the peers in {peers_wall:.0f} s.", ""]
    open(os.path.join(out_dir, "bench.md"), "w").write("\n".join(md) + "\n")
    print("\n".join(md[:40]))


def growth(runs, smoke):
    """How the cost of each family grows with n, with the tolerance and with the grid."""
    md = ["## How the cost grows", ""]
    for fam in ("albedo-normal", "albedo-grazing"):
        pts = sorted((r for r in runs if r["family"] == fam and r["method"] == "normzoo"), key=lambda r: float(r["knob"]), reverse=True)
        if pts:
            md.append(f"- {fam}, normzoo, tolerance -> time: " + ", ".join(f"{r['knob']}: {r['seconds'] * 1e3:.2f} ms" for r in pts) + ".")
    with tempfile.TemporaryDirectory() as tmp:
        sizes = (12, 24, 48) if not smoke else (12,)
        cells = []
        for k in sizes:
            angles = ",".join(f"{89.9 * i / (k - 1):.4f}" for i in range(k))
            _, w, _ = run_measured([os.path.join(ROOT, "verify"), "energy", "--theta", angles, "--out", tmp])
            cells.append(f"{k} angles: {w:.2f} s")
        md.append("- Energy sweep (all models, default exponents), grid size -> wall time: " + ", ".join(cells) + ".")
    md.append("- Zoo 1D against n: see `bench-zoo.md` (the rule's cost does not depend on n: the same nodes in the Laplace variable).")
    md.append("")
    return md


def targets(build, smoke, albedo_points):
    """The speed targets, each measured here."""
    import mpmath_zoo
    import io
    import contextlib
    md = ["## Targets", ""]
    runs = "3" if smoke else "21"
    per = [json.loads(l) for l in run_measured([os.path.join(build, "bench", "normzoo-bench-zoo"), runs])[0].splitlines()]
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        saved = sys.argv
        sys.argv = ["mpmath_zoo.py", "35"]
        mpmath_zoo.main()
        sys.argv = saved
    mp = {(r["row"], float(r["n"])): r for r in map(json.loads, buf.getvalue().splitlines())}
    ratios = sorted((mp[(r["row"], float(r["n"]))]["seconds_whole"] / r["seconds_1d"], r["row"], r["n"]) for r in per)
    digits_mp = min(r["digits_whole"] for r in mp.values())
    md.append(f"- **Zoo 1D at >= 32 digits against mpmath at 35 digits**, one integral at a time, one core each, "
              f"{len(per)} integrals: median {statistics.median(x[0] for x in ratios):.1f}x faster, slowest "
              f"{ratios[0][0]:.1f}x ({ratios[0][1]}, n = {ratios[0][2]:g}); {sum(x[0] >= 10 for x in ratios)} of "
              f"{len(ratios)} at 10x or more. normzoo's estimate is at most {max(r['error_estimate'] for r in per):.1e} "
              f"(relative); mpmath's fewest correct digits {digits_mp:.1f}.")
    below = [x for x in ratios if x[0] < 10]
    if below:
        md.append("  Below 10x: " + ", ".join(f"{row} n = {n:g} ({x:.1f}x)" for x, row, n in below) + ".")
    worst_ulps = max(r["ulps_double"] for r in per)
    slowest_d = max(r["seconds_double"] for r in per)
    md.append(f"- **The double path**: every zoo integral in double within {worst_ulps:.1f} ulp of the closed form; "
              f"median {statistics.median(r['seconds_double'] for r in per) * 1e6:.2f} us, slowest {slowest_d * 1e6:.2f} us "
              f"(target: 4 ulp in 2 us).")
    with tempfile.TemporaryDirectory() as tmp:
        full = [run_measured([os.path.join(ROOT, "verify"), "--out", tmp]) for _ in range(1 if smoke else 4)]
        walls = [w for _, w, _ in full]
        rss = max(r for _, _, r in full)
        scene = os.path.join(ROOT, "scenes", "single-material.toml")
        swalls = [run_measured([os.path.join(ROOT, "verify"), "--scene", scene, "--out", tmp])[1]
                  for _ in range(1 if smoke else 5)]
    md.append(f"- **The whole default `./verify`** (all tables, both cores): {min(walls):.2f} s wall (best of {len(walls)}; "
              f"target 10 s); peak resident memory {rss:.1f} MiB (target 200).")
    for r in albedo_points:
        md.append(f"- **An albedo point at 1e-10** ({r['family']}): {r['seconds'] * 1e3:.3f} ms (target 1 ms); "
                  "the whole energy sweep's per-point figures are in `bench-energy.md`.")
    md.append(f"- **`./verify --scene scenes/single-material.toml`**: {min(swalls):.3f} s wall (target 0.5 s).")
    md.append("")
    return md


if __name__ == "__main__":
    main()
