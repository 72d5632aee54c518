#!/usr/bin/python3
"""The peers of the work-precision benchmark, on the same integral families, in the same run.

Usage: bench/wp_peers.py FAMILIES.jsonl [--smoke] > PEERS.jsonl
FAMILIES.jsonl is normzoo-bench-wp's output: its "family" lines give each family's truth.
mpmath quad at 15, 32 and 50 digits (the 1D zoo integrals as a user writes them, and the 2D
families at 15 digits), SciPy quad (1D) and dblquad (2D) with the tolerance swept. One JSON
object per line, in the shape of the C++ runs.
"""
import json
import math
import signal
import sys
import time

import mpmath as mp
import numpy as np
from scipy import integrate

SMOKE = "--smoke" in sys.argv


class TimedOut(Exception):
    pass


def _alarm(signum, frame):
    raise TimedOut()


signal.signal(signal.SIGALRM, _alarm)


def timed(fn, limit=60):
    """Minimum time over a few runs (one if slow); None if a run exceeds `limit` seconds."""
    signal.alarm(limit)
    try:
        a = time.perf_counter()
        value = fn()
        best = time.perf_counter() - a
        runs = 0 if SMOKE or best > 0.2 else min(10, int(0.2 / max(best, 1e-6)))
        for _ in range(runs):
            a = time.perf_counter()
            value = fn()
            best = min(best, time.perf_counter() - a)
    except TimedOut:
        return None, None
    finally:
        signal.alarm(0)
    return value, best


def emit(family, method, type_, knob, seconds, value, truth, reported=-1.0):
    mp.mp.dps = 60
    value = mp.re(value)  # mpmath answers cos(t)^1.5 at t ~ pi/2 with a complex part of 1e-129
    err = abs(mp.mpf(value) - truth)
    print(json.dumps({"kind": "run", "family": family, "method": method, "type": type_, "knob": knob,
                      "seconds": seconds, "value": mp.nstr(mp.mpf(value), 40), "error": float(err),
                      "reported_error": float(reported), "evaluations": -1}), flush=True)


def gave_up(family, method, type_, knob):
    print(json.dumps({"kind": "gave_up", "family": family, "method": method, "type": type_, "knob": knob}), flush=True)


def zoo(fam, n):
    truth = fam["truth_mp"]
    for dps in (15, 32, 50):
        mp.mp.dps = dps
        nn = mp.mpf(n)
        f = lambda t: mp.cos(t) ** (nn + 1) * mp.sin(t)
        value, sec = timed(lambda: mp.quad(f, [0, mp.pi / 2]))
        if value is None:
            gave_up(fam["family"], f"mpmath quad ({dps} digits)", "mpmath", f"dps {dps}")
        else:
            emit(fam["family"], f"mpmath quad ({dps} digits)", "mpmath", f"dps {dps}", sec, value, truth)
    g = lambda t: math.cos(t) ** (n + 1) * math.sin(t)
    for d in (4, 6, 8, 10, 12, 14)[: 1 if SMOKE else None]:
        tol = 10.0 ** -d
        value, sec = timed(lambda: integrate.quad(g, 0, math.pi / 2, epsabs=tol, epsrel=tol, limit=200))
        emit(fam["family"], "SciPy quad", "double", f"{tol:.0e}", sec, value[0], truth, value[1])


def albedo_integrand(theta_deg, n):
    t = math.radians(theta_deg)
    lx, lz = math.sin(t), math.cos(t)
    # blinn-phong-modified: (n+2)(n+4) / (8 pi (2^(-n/2) + n)) (N.H)^n, times N.V sin(theta)
    c = (n + 2) * (n + 4) / (8 * math.pi * (2 ** (-n / 2) + n))

    def f(phi, theta):  # dblquad's order: inner variable first
        st, ct = math.sin(theta), math.cos(theta)
        vx, vy, vz = st * math.cos(phi), st * math.sin(phi), ct
        hx, hy, hz = lx + vx, vy, lz + vz
        nh = hz / math.sqrt(hx * hx + hy * hy + hz * hz)
        return c * max(nh, 0.0) ** n * ct * st
    return f


def ggx_albedo_integrand(mu, alpha):
    # ggx/smith-height-correlated/one: D G / (4 N.L N.V) times N.L sin(theta), L about N
    vx, vz = math.sqrt((1 - mu) * (1 + mu)), mu
    a2 = alpha * alpha

    def lam(c):
        t2 = (1 - c * c) / (c * c)
        return (math.sqrt(1 + a2 * t2) - 1) / 2

    def f(phi, theta):
        st, ct = math.sin(theta), math.cos(theta)
        if ct <= 0:
            return 0.0
        lx, ly, lz = st * math.cos(phi), st * math.sin(phi), ct
        hx, hy, hz = lx + vx, ly, lz + vz
        r = math.sqrt(hx * hx + hy * hy + hz * hz)
        nh = hz / r
        t2 = (1 - nh * nh) / (nh * nh)
        d = a2 / (math.pi * nh ** 4 * (a2 + t2) ** 2)
        g = 1 / (1 + lam(lz) + lam(vz))
        return d * g / (4 * lz * vz) * lz * st
    return f


def cap_integrand(tilt_deg):
    t = math.radians(tilt_deg)
    ct, st_ = math.cos(t), math.sin(t)

    def f(phi, theta):
        nl = math.cos(theta) * ct - math.sin(theta) * math.cos(phi) * st_
        return max(nl, 0.0) * math.sin(theta)
    return f


def two_d(fam, f, theta_hi):
    truth = fam["truth_mp"]
    for d in (4, 6, 8, 10, 12, 14)[: 1 if SMOKE else None]:
        tol = 10.0 ** -d
        value, sec = timed(lambda: integrate.dblquad(f, 0, theta_hi, 0, 2 * math.pi, epsabs=tol, epsrel=tol), limit=120)
        if value is None:
            gave_up(fam["family"], "SciPy dblquad", "double", f"{tol:.0e}")
            break
        emit(fam["family"], "SciPy dblquad", "double", f"{tol:.0e}", sec, value[0], truth, value[1])
    mp.mp.dps = 15
    g = lambda theta, phi: f(float(phi), float(theta))
    value, sec = timed(lambda: mp.quad(g, [0, theta_hi], [0, 2 * mp.pi]), limit=30 if SMOKE else 300)
    if value is None:
        gave_up(fam["family"], "mpmath quad (15 digits)", "mpmath", "dps 15")
    else:
        emit(fam["family"], "mpmath quad (15 digits)", "mpmath", "dps 15", sec, value, truth)


def main():
    families = {}
    for line in open(sys.argv[1]):
        r = json.loads(line)
        if r["kind"] == "family":
            mp.mp.dps = 60
            r["truth_mp"] = mp.mpf(r["truth"])
            families[r["family"]] = r
    for name, fam in families.items():
        if name == "zoo-low":
            zoo(fam, 0.5)
        elif name == "zoo-high":
            zoo(fam, 1e6)
        elif name == "albedo-normal":
            two_d(fam, albedo_integrand(0, 64), math.pi / 2)
        elif name == "albedo-grazing":
            two_d(fam, albedo_integrand(85, 64), math.pi / 2)
        elif name == "irradiance-cap":
            two_d(fam, cap_integrand(80), math.asin(0.5))
        elif name == "microfacet-albedo":
            two_d(fam, ggx_albedo_integrand(0.5, 0.3), math.pi / 2)


if __name__ == "__main__":
    main()
