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
#include <boost/math/constants/constants.hpp>
#include <cmath>

namespace normzoo::detail {

struct elliptic_family {
    double k, e;        // K(k), E(k)
    double c, dc_dp;    // cel(kc, P, 1, 1) and its derivative in P (< 0)
};

// kc in (0, 1], P > 0.
inline elliptic_family complete_elliptic(double kc, double P) {
    using std::abs;
    using std::sqrt;
    constexpr double ca = 1e-8;
    double qc = abs(kc), e = qc, em = 1;
    // p = 1 (K, E): two (a, b) pairs on one p; p = P (C) with the derivatives in P.
    double p1 = 1, ak = 1, bk = 1, ae = 1, be = qc * qc;
    double p = sqrt(P), dp = 0.5 / p;
    double a = 1, da = 0, b = 1 / p, db = -b * dp / p;
    for (int iteration = 0; iteration < 64; ++iteration) {
        {  // p = 1
            const double r1 = 1 / p1, g = e * r1;
            const double fk = ak, fe = ae;
            ak += bk * r1, ae += be * r1;
            bk = 2 * (bk + fk * g), be = 2 * (be + fe * g);
            p1 += g;
        }
        {  // p = P, with d/dP
            const double r = 1 / p, f = a, df = da;
            const double bp = b * r, dpp = dp * r;
            a += bp, da += (db - bp * dp) * r;
            const double g = e * r, dg = -g * dpp;
            b = 2 * (b + f * g), db = 2 * (db + df * g + f * dg);
            p += g, dp += dg;
        }
        const double g = em;
        em += qc;
        if (abs(g - qc) <= g * ca) break;
        qc = 2 * sqrt(e);
        e = qc * em;
    }
    const double half_pi = boost::math::constants::half_pi<double>();
    const double den1 = em * (em + p1), den = em * (em + p);
    return {half_pi * (bk + ak * em) / den1, half_pi * (be + ae * em) / den1, half_pi * (b + a * em) / den,
            half_pi * ((db + da * em) / den - (b + a * em) * dp / (den * (em + p)))};
}

}  // namespace normzoo::detail
