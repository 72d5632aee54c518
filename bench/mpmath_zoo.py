#!/usr/bin/python3
"""The peer: mpmath (with gmpy2) computing the same 1D zoo integrals at 35 digits.

For each row and exponent: mpmath.quad of the reduced integrand over [0, pi/2], once as a user
would write it (whole interval) and once with the lobe split at 4/sqrt(n+1) and 16/sqrt(n+1)
(what a careful user would add). Time per integral and the digits reached against the closed
form evaluated at 60 digits. One JSON object per line.
"""
import json
import sys
import time

import mpmath as mp

ROWS = {
    "lambert": (False, lambda t, n: mp.cos(t) * mp.sin(t), lambda n: 1 / mp.pi),
    "phong": (True, lambda t, n: mp.cos(t) ** n * mp.sin(t), lambda n: (n + 1) / (2 * mp.pi)),
    "phong-modified": (True, lambda t, n: mp.cos(t) ** n * mp.cos(t) * mp.sin(t), lambda n: (n + 2) / (2 * mp.pi)),
    "blinn-phong": (True, lambda t, n: mp.cos(t / 2) ** n * mp.sin(t),
                    lambda n: (n + 2) / (4 * mp.pi * (2 - mp.power(2, -n / 2)))),
    "blinn-phong-modified": (True, lambda t, n: mp.cos(t / 2) ** n * mp.cos(t) * mp.sin(t),
                             lambda n: (n + 2) * (n + 4) / (8 * mp.pi * (mp.power(2, -n / 2) + n))),
    "blinn-phong-ndf": (True, lambda t, n: mp.cos(t) ** n * mp.sin(t), lambda n: (n + 1) / (2 * mp.pi)),
    "blinn-phong-heightfield": (True, lambda t, n: mp.cos(t) ** n * mp.cos(t) * mp.sin(t), lambda n: (n + 2) / (2 * mp.pi)),
}
GRID = [0, 0.1, 0.5, 1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 1e4, 1e5, 1e6, 1e7]


def main():
    dps = int(sys.argv[1]) if len(sys.argv) > 1 else 35
    for row, (has_n, f, closed) in ROWS.items():
        for n in GRID if has_n else [0]:
            mp.mp.dps = 60
            truth = closed(mp.mpf(n))
            mp.mp.dps = dps
            nn = mp.mpf(n)
            g = lambda t: f(t, nn)
            out = {"row": row, "n": n, "dps": dps, "backend": mp.libmp.BACKEND}
            for name, points in (("whole", [0, mp.pi / 2]),
                                 ("split", [0] + [p for p in (4 / mp.sqrt(nn + 1), 16 / mp.sqrt(nn + 1)) if p < mp.pi / 2] + [mp.pi / 2])):
                a = time.perf_counter()
                integral = mp.quad(g, points)
                out["seconds_" + name] = time.perf_counter() - a
                mp.mp.dps = 60
                norm = 1 / (2 * mp.pi * integral)
                err = abs(norm - truth) / truth
                out["digits_" + name] = float(-mp.log10(err)) if err > 0 else 60.0
                mp.mp.dps = dps
            print(json.dumps(out), flush=True)


if __name__ == "__main__":
    main()
