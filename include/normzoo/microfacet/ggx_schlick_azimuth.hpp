// GGX's D times Schlick's (1 - V.h)^5, integrated over L's azimuth in closed form (docs/microfacet.md,
// "Schlick's F over L's azimuth"): with s = 1 + L.V = A + B cos phi (A = 1 + N.L N.V, B = sin t_L
// sin t_V), V.h = sqrt(s/2) and
//     D = (4 a^2 / pi) s^2 / (2s - p)^2,   p = c^2 (1 - a^2),  c = N.L + N.V
// (distribution.hpp, d_ggx), (1 - sqrt(s/2))^5 splits into integer powers of s (rational in
// cos phi: residues) and half-integer ones (sqrt(s) times a rational function: complete
// elliptic integrals, with s = (A + B) (cos^2 t + kc^2 sin^2 t), phi = 2t, kc = c / (A + B)).
// Every term is built from
//     I_nu = integral s^nu dphi           (K and E at nu = -1/2, 1/2; upward in nu by the
//                                          Legendre recurrence, stable: P_nu is the dominant solution)
//     U1_nu = integral s^nu / (2s - p),  U2_nu = integral s^nu / (2s - p)^2
//           (Bulirsch's cel and its P-derivative at nu = -1/2, 2s - p = (2(A+B) - p)(cos^2 t + P sin^2 t);
//            upward by s^nu / (2s - p) = (s^(nu-1) + p s^(nu-1) / (2s - p)) / 2, a sum of terms >= 0)
// so nothing cancels until the alternating sum of (1 - y)^5's six terms, whose rounding is
// bounded by 64 ulps of the sum of their magnitudes (at most 32 times D's integral; measured: under 3 ulps
// against long-double quadrature, tests/test_composition.cpp). alpha <= 1 (p >= 0).
#pragma once
#include <array>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstddef>
#include <limits>

#include "../detail/complete_elliptic.hpp"

namespace normzoo::microfacet::detail {

struct ggx_schlick_azimuthal {
    double d;            // integral of D over L's azimuth (d_ggx has a shorter form; split_sum_to.hpp takes this one)
    double d5, d5_error; // integral of D (1 - V.h)^5 and a bound on its rounding
    // with F82 (OpenPBR's metal: Schlick's F less b V.h (1 - V.h)^6): integral of D V.h (1 - V.h)^6,
    // seven alternating terms, two U2 one step further; its bound as d5's (0 without F82)
    double d6, d6_error;
};

// At N nodes cos t_L = nl[i] with cos t_L - cos t_V = nl_minus_nv[i] and sin t_L = sl[i], one
// view cos t_V = nv, sin t_V = sv (the sines' squares exact from the variable they are integrated
// in: azimuthal_albedo.hpp), roughness a in (0, 1]. The nodes' elliptic integrals are computed
// side by side (detail/complete_elliptic.hpp): each result is bit for bit the single node's. D's
// integral errs by at most 64 ulps too: x[0] below is U2 at nu = 2, sums and products of terms >= 0.
// F82: also D V.h (1 - V.h)^6 (y (1 - y)^6 = sum_j C(6, j) (-1)^j y^(j + 1): U2 at 2.5 to 5.5).
template <std::size_t N, bool F82 = false>
std::array<ggx_schlick_azimuthal, N> ggx_schlick_azimuthal_integrals_at(const std::array<double, N>& nl, double nv,
                                                                        const std::array<double, N>& nl_minus_nv,
                                                                        const std::array<double, N>& sl, double sv, double a) {
    using std::sqrt;
    const double pi = boost::math::constants::pi<double>(), two_pi = 2 * pi, a2 = a * a;
    struct node {
        double c2, A, B, S0, p, below, above, one_minus_P;
    };
    std::array<node, N> at;
    std::array<double, N> kc, P;
    for (std::size_t i = 0; i < N; ++i) {
        node& n = at[i];
        const double c = nl[i] + nv;
        n.c2 = c * c, n.A = 1 + nl[i] * nv, n.B = sl[i] * sv, n.S0 = n.A + n.B, n.p = n.c2 * (1 - a2);
        // 2 - (A + B) = 1 - cos(t_L - t_V) = (N.L - N.V)^2 (1 + c^2 / (sin t_L + sin t_V)^2) / 2, exact
        // near the mirror direction; then 2d - p (d = A - B = c^2 / (A + B)), the pole's distance.
        const double ss = sl[i] + sv;
        const double gap = ss > 0 ? nl_minus_nv[i] * nl_minus_nv[i] * (1 + n.c2 / (ss * ss)) / 2 : 0.0;
        n.below = n.c2 * (gap / n.S0 + a2);  // 2d - p > 0
        n.above = n.below + 4 * n.B;         // 2(A + B) - p = (2d - p) + 4B: no cancellation
        kc[i] = c / n.S0, P[i] = n.below / n.above, n.one_minus_P = 4 * n.B / n.above;
    }
    const std::array<normzoo::detail::elliptic_family, N> family = normzoo::detail::complete_elliptic<N>(kc, P);
    std::array<ggx_schlick_azimuthal, N> out;
    for (std::size_t i = 0; i < N; ++i) {
        const auto& [c2, A, B, S0, p, below, above, one_minus_P] = at[i];
        const normzoo::detail::elliptic_family& f = family[i];
        const double root = sqrt(S0);
        // Half-integer powers nu = h - 1/2, h = 0..5.
        double ih[6], u1h[6], u2h[6];
        ih[0] = 4 * f.k / root;
        ih[1] = 4 * root * f.e;
        // (nu + 1) I_(nu+1) = (2 nu + 1) A I_nu - nu (A^2 - B^2) I_(nu-1), A^2 - B^2 = c^2
        constexpr double half_up[4][2] = {{4.0 / 3, 1.0 / 3}, {8.0 / 5, 3.0 / 5}, {12.0 / 7, 5.0 / 7}, {16.0 / 9, 7.0 / 9}};
        for (int h = 1; h < 5; ++h) ih[h + 1] = half_up[h - 1][0] * A * ih[h] - half_up[h - 1][1] * c2 * ih[h - 1];
        u1h[0] = 4 * f.c / (above * root);
        u2h[0] = 4 * (f.c - one_minus_P * f.dc_dp) / (above * above * root);  // both terms >= 0 (dc/dP < 0)
        for (int h = 1; h < 6; ++h) {
            u1h[h] = (ih[h - 1] + p * u1h[h - 1]) / 2;
            u2h[h] = (u1h[h - 1] + p * u2h[h - 1]) / 2;
        }
        // Integer powers m = 0..4: 1/(R + S cos phi) and its square over the circle, R = 2A - p, S = 2B,
        // R^2 - S^2 = (2d - p)(2(A + B) - p).
        double ii[5], u1i[5], u2i[5];
        ii[0] = two_pi;
        ii[1] = two_pi * A;
        constexpr double whole_up[3][2] = {{3.0 / 2, 1.0 / 2}, {5.0 / 3, 2.0 / 3}, {7.0 / 4, 3.0 / 4}};
        for (int m = 1; m < 4; ++m) ii[m + 1] = whole_up[m - 1][0] * A * ii[m] - whole_up[m - 1][1] * c2 * ii[m - 1];
        const double rs = below * above, r = below + 2 * B;  // R = (R - S) + S: no cancellation near the pole
        u1i[0] = two_pi / sqrt(rs);
        u2i[0] = two_pi * r / (rs * sqrt(rs));
        for (int m = 1; m < 5; ++m) {
            u1i[m] = (ii[m - 1] + p * u1i[m - 1]) / 2;
            u2i[m] = (u1i[m - 1] + p * u2i[m - 1]) / 2;
        }
        // (1 - y)^5 = sum_j C(5, j) (-1)^j 2^(-j/2) s^(j/2), times s^2 / (2s - p)^2: U2 at 2 + j/2.
        const double x[6] = {u2i[2], u2h[3], u2i[3], u2h[4], u2i[4], u2h[5]};
        constexpr double binomial[6] = {1, 5, 10, 10, 5, 1};
        const double half_root2 = 0.70710678118654752440;
        double sum = 0, magnitude = 0, scale = 1;
        for (int j = 0; j < 6; ++j) {
            const double term = binomial[j] * scale * x[j];
            sum += j % 2 ? -term : term;
            magnitude += term;
            scale *= half_root2;
        }
        const double k = 4 * a2 / pi, eps = std::numeric_limits<double>::epsilon();
        out[i] = {k * x[0], k * sum, 64 * eps * k * magnitude, 0, 0};
        if constexpr (F82) {
            const double u2i5 = (u1i[4] + p * u2i[4]) / 2, u2h6 = (u1h[5] + p * u2h[5]) / 2;
            const double x6[7] = {u2h[3], u2i[3], u2h[4], u2i[4], u2h[5], u2i5, u2h6};
            constexpr double binomial6[7] = {1, 6, 15, 20, 15, 6, 1};
            double sum6 = 0, magnitude6 = 0, scale6 = half_root2;
            for (int j = 0; j < 7; ++j) {
                const double term = binomial6[j] * scale6 * x6[j];
                sum6 += j % 2 ? -term : term;
                magnitude6 += term;
                scale6 *= half_root2;
            }
            out[i].d6 = k * sum6, out[i].d6_error = 64 * eps * k * magnitude6;
        }
    }
    return out;
}

// The same at one node, from the squares of the sines.
template <bool F82 = false>
ggx_schlick_azimuthal ggx_schlick_azimuthal_integrals(double nl, double nv, double nl_minus_nv, double sl2, double sv2, double a) {
    using one = std::array<double, 1>;
    return ggx_schlick_azimuthal_integrals_at<1, F82>(one{nl}, nv, one{nl_minus_nv}, one{std::sqrt(sl2)}, std::sqrt(sv2), a)[0];
}

}  // namespace normzoo::microfacet::detail
