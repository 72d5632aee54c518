#!/usr/bin/python3
"""The peer for the material benchmark: SciPy's dblquad (QUADPACK) on the same glTF material points,
the material written again in Python from the glTF 2.0 specification's Appendix B (Lambert diffuse,
GGX with the separable Smith G or the height-correlated one, Schlick's Fresnel on V.H, fresnel_mix
for the dielectric at ior 1.5, conductor_fresnel for the metal, mixed by metallic), asked for 1e-10
absolute and relative. One JSON object per line: the whole material's albedo per channel with V held,
one dblquad per channel (a lower bound on the peer's cost for the whole and each lobe).

The integral is over L in plain spherical coordinates around N (theta in [0, pi/2], phi in [0, pi],
doubled by the mirror symmetry about the plane of incidence): what a user of SciPy would write.
"""
import json
import math
import sys
import time
import warnings

from scipy import integrate

POINTS = [  # (baseColor, metallic, roughness, mu, masking): the same list as bench/material_bench.cpp
    ((0.8, 0.5, 0.2), 0.5, 0.5, 0.5, "separable"),
    ((1.0, 1.0, 1.0), 1.0, 1.0, 1.0, "height-correlated"),
    ((0.9, 0.9, 0.9), 0.0, 0.3, 0.8, "separable"),
    ((0.5, 0.5, 0.5), 1.0, 0.1, 0.3, "height-correlated"),
]


def gltf_f(l, v, color, metallic, roughness, masking):
    nl, nv = l[2], v[2]
    h = [l[i] + v[i] for i in range(3)]
    hn = math.sqrt(sum(x * x for x in h))
    h = [x / hn for x in h]
    nh, vh = h[2], sum(v[i] * h[i] for i in range(3))
    a2 = roughness ** 4
    d = a2 / (math.pi * (nh * nh * (a2 - 1) + 1) ** 2)
    if masking == "separable":
        g1 = lambda x: 2 * x / (x + math.sqrt(a2 + (1 - a2) * x * x))
        vis = g1(nl) * g1(nv) / (4 * nl * nv)
    else:
        vis = 0.5 / (nl * math.sqrt(nv * nv * (1 - a2) + a2) + nv * math.sqrt(nl * nl * (1 - a2) + a2))
    fr = lambda f0: f0 + (1 - f0) * (1 - abs(vh)) ** 5
    metal = fr(color) * d * vis
    dielectric = (1 - fr(0.04)) * color / math.pi + fr(0.04) * d * vis
    return (1 - metallic) * dielectric + metallic * metal


def albedo(color, metallic, roughness, mu, masking):
    sv = math.sqrt((1 - mu) * (1 + mu))
    v = (sv, 0.0, mu)

    def g(phi, th):  # dblquad: inner variable first
        st, ct = math.sin(th), math.cos(th)
        l = (st * math.cos(phi), st * math.sin(phi), ct)
        return gltf_f(l, v, color, metallic, roughness, masking) * ct * st

    return integrate.dblquad(g, 0, math.pi / 2, 0, math.pi, epsabs=1e-10, epsrel=1e-10)


def main():
    import scipy
    for color, metallic, roughness, mu, masking in POINTS:
        times, values = [], []
        for _ in range(3):  # median of 3, or one when it takes over a second
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                a = time.perf_counter()
                values = [albedo(c, metallic, roughness, mu, masking) for c in color]
                times.append(time.perf_counter() - a)
            if times[-1] > 1:
                break
        s = sorted(times)[len(times) // 2]
        print(json.dumps({"baseColor": color, "metallic": metallic, "roughness": roughness, "mu": mu, "masking": masking,
                          "seconds": s, "albedo_rgb": [2 * v for v, _ in values],
                          "claimed_error": [2 * e for _, e in values], "warnings": len(caught), "scipy": scipy.__version__}))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
