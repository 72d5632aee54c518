#!/usr/bin/python3
"""The peer for the albedo benchmark: SciPy's dblquad (QUADPACK) on the same albedo points, f written again
from vectors in Python, asked for 1e-10 absolute and relative. One JSON object per line.

The integral is taken over V in plain spherical coordinates around N (theta_v in [0, pi/2], phi
in [0, pi], doubled by the same mirror symmetry normzoo uses): what a user of SciPy would write.
"""
import json
import math
import sys
import time
import warnings

from scipy import integrate

POINTS = [  # the same list, in the same order, as bench/albedo_bench.cpp
    ("lambert", 0, 45), ("phong-modified", 16, 30), ("phong-modified", 256, 60), ("phong-modified", 1e4, 75),
    ("blinn-phong-modified", 16, 45), ("blinn-phong-modified", 1024, 80), ("microfacet-blinn", 64, 60),
    ("minimalist-cook-torrance", 16, 70), ("minimalist-cook-torrance", 256, 89), ("cook-torrance-ksk", 100, 85),
    ("cook-torrance-ksk", 1e4, 30), ("phong", 4, 89.9),
    ("minimalist-cook-torrance", 16, 89.99), ("blinn-phong-modified", 1e5, 89.9),
]


def brdf(model, n, l, v):
    dot = lambda a, b: a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    r = (-l[0], -l[1], l[2])
    h = (l[0] + v[0], l[1] + v[1], l[2] + v[2])
    hn = math.sqrt(dot(h, h))
    h = (h[0] / hn, h[1] / hn, h[2] / hn)
    nh, lh, rv, nl = h[2], dot(l, h), dot(r, v), l[2]
    lobe_r = max(rv, 0.0) ** n if rv > 0 else 0.0
    lobe_h = nh ** n
    schlick = lambda c, x: c + (1 - c) * (1 - x) ** 5
    if model == "lambert":
        return 1 / math.pi
    if model == "phong":
        return (n + 1) / (2 * math.pi) * lobe_r / nl
    if model == "phong-modified":
        return (n + 2) / (2 * math.pi) * lobe_r
    if model == "blinn-phong-modified":
        return (n + 2) * (n + 4) / (8 * math.pi * (2 ** (-n / 2) + n)) * lobe_h
    if model == "microfacet-blinn":
        return schlick(1.0, lh) * (n + 2) / (8 * math.pi) * lobe_h
    if model == "minimalist-cook-torrance":
        return (n + 1) * lobe_h / (8 * math.pi * lh ** 3)
    if model == "cook-torrance-ksk":
        return (n + 2) / (2 * math.pi) * lobe_h * schlick(1.0, lh) / (4 * lh * lh)
    raise ValueError(model)


def albedo(model, n, theta_deg):
    t = math.radians(theta_deg)
    l = (math.sin(t), 0.0, math.cos(t))

    def g(phi, th):  # dblquad: inner variable first
        st, ct = math.sin(th), math.cos(th)
        v = (st * math.cos(phi), st * math.sin(phi), ct)
        return brdf(model, n, l, v) * ct * st

    return integrate.dblquad(g, 0, math.pi / 2, 0, math.pi, epsabs=1e-10, epsrel=1e-10)


def main():
    import scipy
    for model, n, theta in POINTS:
        times = []
        for _ in range(3):  # median of 3, or one call when it takes over a tenth of a second
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                a = time.perf_counter()
                value, err = albedo(model, n, theta)
                times.append(time.perf_counter() - a)
            if times[-1] > 0.1:
                break
        s = sorted(times)[len(times) // 2]
        print(json.dumps({"model": model, "n": n, "theta": theta, "seconds": s, "albedo": 2 * value,
                          "claimed_error": 2 * err, "warnings": len(caught), "scipy": scipy.__version__}))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
