// Complete elliptic integrals in Bulirsch's general form (DLMF 19.2(iii))
//     cel(kc, p, a, b) = integral_0^{pi/2} (a cos^2 t + b sin^2 t)
//                        / ((cos^2 t + p sin^2 t) sqrt(cos^2 t + kc^2 sin^2 t)) dt,
// by Bulirsch's iteration (Bulirsch 1969, "Numerical calculation of elliptic integrals and
// elliptic functions. III", Numer. Math. 13), which converges quadratically: it stops where
// the relative change is below 1e-8, so that the truncation is ~1e-16 of the value.
//
// One iteration gives the family one kc needs: K(k) = cel(kc, 1, 1, 1), E(k) = cel(kc, 1, 1,
// kc^2) and C(P) = cel(kc, P, 1, 1) (Legendre's Pi(1 - P, k)) with dC/dP, carried through the
// iteration as a derivative (forward mode): the iteration's count depends on kc alone, so the
// derivative is that of one fixed algebraic expression. Boost.Math has K, E and Pi but not
// Pi's derivative in its parameter, which the second power of the pole needs
// (microfacet/ggx_schlick_azimuth.hpp), and whose reduction to K, E and Pi cancels where the
// pole meets the modulus (n = k^2). Checked against Boost's ellint_1, _2, _3 and their
// differences in tests/test_composition.cpp.
#pragma once
#include <array>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstddef>

namespace normzoo::detail {

struct elliptic_family {
    double k, e;        // K(k), E(k)
    double c, dc_dp;    // cel(kc, P, 1, 1) and its derivative in P (< 0)
};

// For N (kc, P) pairs at once, kc in (0, 1], P > 0: the pairs' iterations run side by side, each
// stopping at its own step, so that every result is bit for bit the single pair's, while the
// processor overlaps the pairs' chains of divisions and square roots (one pair's iteration is a
// chain of dependent ones; docs/microfacet.md, "The split-sum pair to a tolerance").
template <std::size_t N>
std::array<elliptic_family, N> complete_elliptic(const std::array<double, N>& kc, const std::array<double, N>& P) {
    using std::abs;
    using std::sqrt;
    constexpr double ca = 1e-8;
    // p = 1 (K, E): two (a, b) pairs on one p1; p = P (C) with the derivatives in P.
    std::array<double, N> qc, e, em, p1, ak, bk, ae, be, p, dp, a, da, b, db;
    std::array<bool, N> running;
    for (std::size_t i = 0; i < N; ++i) {
        qc[i] = abs(kc[i]), e[i] = qc[i], em[i] = 1, running[i] = true;
        p1[i] = 1, ak[i] = 1, bk[i] = 1, ae[i] = 1, be[i] = qc[i] * qc[i];
        p[i] = sqrt(P[i]), dp[i] = 0.5 / p[i];
        a[i] = 1, da[i] = 0, b[i] = 1 / p[i], db[i] = -b[i] * dp[i] / p[i];
    }
    for (int iteration = 0; iteration < 64; ++iteration) {
        bool any = false;
        for (std::size_t i = 0; i < N; ++i) {
            if (!running[i]) continue;
            {  // p = 1
                const double r1 = 1 / p1[i], g = e[i] * r1;
                const double fk = ak[i], fe = ae[i];
                ak[i] += bk[i] * r1, ae[i] += be[i] * r1;
                bk[i] = 2 * (bk[i] + fk * g), be[i] = 2 * (be[i] + fe * g);
                p1[i] += g;
            }
            {  // p = P, with d/dP
                const double r = 1 / p[i], f = a[i], df = da[i];
                const double bp = b[i] * r, dpp = dp[i] * r;
                a[i] += bp, da[i] += (db[i] - bp * dp[i]) * r;
                const double g = e[i] * r, dg = -g * dpp;
                b[i] = 2 * (b[i] + f * g), db[i] = 2 * (db[i] + df * g + f * dg);
                p[i] += g, dp[i] += dg;
            }
            const double g = em[i];
            em[i] += qc[i];
            if (abs(g - qc[i]) <= g * ca) {
                running[i] = false;
                continue;
            }
            qc[i] = 2 * sqrt(e[i]);
            e[i] = qc[i] * em[i];
            any = true;
        }
        if (!any) break;
    }
    const double half_pi = boost::math::constants::half_pi<double>();
    std::array<elliptic_family, N> out;
    for (std::size_t i = 0; i < N; ++i) {
        const double den1 = em[i] * (em[i] + p1[i]), den = em[i] * (em[i] + p[i]);
        out[i] = {half_pi * (bk[i] + ak[i] * em[i]) / den1, half_pi * (be[i] + ae[i] * em[i]) / den1,
                  half_pi * (b[i] + a[i] * em[i]) / den,
                  half_pi * ((db[i] + da[i] * em[i]) / den - (b[i] + a[i] * em[i]) * dp[i] / (den * (em[i] + p[i])))};
    }
    return out;
}

// kc in (0, 1], P > 0.
inline elliptic_family complete_elliptic(double kc, double P) {
    return complete_elliptic<1>(std::array<double, 1>{kc}, std::array<double, 1>{P})[0];
}

}  // namespace normzoo::detail
