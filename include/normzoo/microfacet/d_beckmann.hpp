// Beckmann's distribution, e^(-tan^2 t / a^2) / (pi a^2 cos^4 t) (Beckmann and Spizzichino 1963),
// its Smith Lambda (Heitz 2014) and D's integral over L's azimuth by Bessel functions.
#pragma once
#include <boost/math/special_functions/detail/bessel_i0.hpp>
#include <boost/math/special_functions/detail/bessel_i1.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <boost/math/constants/constants.hpp>

#include "distribution_part.hpp"

namespace normzoo::microfacet {

namespace detail {
// Smith's Lambda for Beckmann and GGX, w at polar angle t, a the roughness along its azimuth
// (Heitz 2014): m = 1 / (a tan t), from w's components.
template <class T>
T beckmann_lambda(const vec3<T>& w, const T& a) {
    using boost::math::erfc;
    using std::exp;
    using std::sqrt;
    const T t2 = tan2(w);
    if (!(t2 > 0)) return T(0);
    const T m = 1 / (a * sqrt(t2));
    // Both terms round to 0 in double beyond m^2 = 746 (erfc(m) < e^(-m^2)): Lambda is 0 there.
    if constexpr (std::is_same_v<T, double>)
        if (m * m > 746) return T(0);
    // In double, erfc without Boost's default promotion to long double (a few ulps either way,
    // inside the albedo integral's rounding model; several times faster).
    T tail;
    if constexpr (std::is_same_v<T, double>)
        tail = erfc(m, boost::math::policies::policy<boost::math::policies::promote_double<false>>());
    else
        tail = erfc(m);
    return (exp(-m * m) / (m * sqrt(pi<T>())) - tail) / 2;
}

// J_n(beta) = (1/(2 pi)) integral over the circle of (1 + cos phi)^n e^(-beta (1 + cos phi)) dphi,
// n = 0, 1, 2, each with a bound on its error: Beckmann's D over L's azimuth (d_beckmann) is a sum
// of them. With e^(-beta) I_k(beta) = I^_k: J_0 = I^_0, J_1 = I^_0 - I^_1, J_2 = 2 J_1 - I^_1 / beta,
// from Boost's I_0 and I_1 up to beta = 30, where the differences lose up to ~4 beta^2 / 3 ulps
// (counted); beyond, Watson's lemma on J_n = (2^n / pi) integral_0^1 u^(n-1/2) (1 - u)^(-1/2)
// e^(-2 beta u) du, whose terms are all > 0: the series in (1 - u)^(-1/2)'s coefficients, bounded
// by 4x the first term left out (u <= 3/4) and e^(-3 beta / 2) (u > 3/4).
template <class T>
struct azimuth_moments {
    T j[3], error[3];
};
template <class T>
azimuth_moments<T> beckmann_azimuth_moments(const T& beta) {
    using std::abs; using std::exp; using std::sqrt;
    const T eps = std::numeric_limits<T>::epsilon();
    azimuth_moments<T> r;
    if (beta <= 30) {
        // I_0, I_1 to a few ulps in T, no promotion of double to long double (as erfc above): Boost's
        // own kernels of cyl_bessel_i for the orders 0 and 1, whose header is a fraction of the
        // general Bessel functions' (what an engine's test that includes this pays to parse)
        const T e = exp(-beta);
        const T i0 = (beta > 0 ? boost::math::detail::bessel_i0(beta) : T(1)) * e;
        const T i1 = (beta > 0 ? boost::math::detail::bessel_i1(beta) : T(0)) * e;
        const T i1_over_beta = beta > 0 ? i1 / beta : T(0.5);
        r.j[0] = i0, r.j[1] = i0 - i1, r.j[2] = 2 * r.j[1] - i1_over_beta;
        const T u = 8 * eps;  // e^(-beta) I_k
        r.error[0] = u * i0;
        r.error[1] = u * (i0 + i1) + eps * r.j[1];
        r.error[2] = 2 * r.error[1] + (u + eps) * i1_over_beta + 2 * eps * abs(r.j[2]);
        return r;
    }
    const T z = 2 * beta, pi = boost::math::constants::pi<T>();
    T term[3] = {T(1), T(0.5), T(0.75)}, sum[3] = {T(0), T(0), T(0)};  // Gamma(n + 1/2) / sqrt(pi), then x c_k (n + 1/2)_k / z^k
    int k = 0;
    for (bool done = false; !done && k < 400; ++k) {
        done = true;
        for (int n = 0; n < 3; ++n) {
            sum[n] += term[n];
            term[n] *= (k + T(0.5)) * (n + k + T(0.5)) / ((k + 1) * z);
            if (term[n] > eps / 16 * sum[n]) done = false;
        }
    }
    T scale = 1 / (sqrt(pi) * sqrt(z)), two_n = 1;
    for (int n = 0; n < 3; ++n, scale *= 2 / z, two_n *= 2) {
        r.j[n] = scale * sum[n];
        // the next term x 4 (u <= 3/4), u in [3/4, 1], the kept terms' integrals past u = 1
        r.error[n] = 4 * scale * term[n] + two_n / pi * (exp_nonpositive(-z * 3 / 4) + k * exp_nonpositive(-z) / (z - n - k)) + 4 * k * eps * r.j[n];
    }
    return r;
}
}  // namespace detail

struct d_beckmann {
    static constexpr std::string_view id = "beckmann";
    static constexpr auto parameters = no_parameters;
    static constexpr const char* formula = "exp(-tan^2 t / a^2) / (pi a^2 cos^4 t)";
    static constexpr const char* literature =
        "Beckmann and Spizzichino 1963; Walter et al. 2007 (Smith G1); Heitz 2014 (Lambda, weak white furnace)";
    static constexpr const char* non_projected_formula = "1 + (sqrt(pi)/2) a e^(1/a^2) erfc(1/a)";
    static constexpr const char* g1_formula = "2 / (1 + erf(m) + e^(-m^2) / (m sqrt(pi))), m = 1 / (a tan t_v)";
    static constexpr bool isotropic = true, has_exact_lambda = true, has_polar_map = true, has_azimuthal_integral = true, has_azimuthal_schlick_integral = false, has_non_projected = true;
    // The non-projected integral, derived here (no published closed form found; Reed 2013, "How Is
    // the NDF Really Defined?", gives "about 1.113" at a = 0.5, which it reproduces): with u = tan^2 t,
    //     integral of D dw = (1/a^2) integral_0^inf e^(-u/a^2) sqrt(1 + u) du
    //                      = a e^(1/a^2) Gamma(3/2, 1/a^2) = 1 + (sqrt(pi)/2) a e^(1/a^2) erfc(1/a),
    // 1 + a^2/2 + O(a^4) for small a. Wants a wide exponent range: e^(1/a^2) overflows double below a = 0.04.
    template <class T>
    static T non_projected(const T& alpha) {
        using boost::math::erfc; using std::exp; using std::sqrt;
        return 1 + sqrt(detail::pi<T>()) / 2 * alpha * exp(1 / (alpha * alpha)) * erfc(1 / alpha);
    }
    // mass below t: 1 - e^(-tan^2 t / a^2) = sin^2 psi, so tan^2 t = -a^2 ln cos^2 psi
    template <class T>
    static void polar(const T& psi, const ndf_params<T>& p, T& c, T& s) {
        using std::cos; using std::log; using std::log1p; using std::sin; using std::sqrt;
        const T sp = sin(psi);
        // -ln cos^2 psi: from sin^2 psi below 45 degrees, from cos psi above (no cancellation either way)
        const T l = psi < T(0.785) ? -log1p(-sp * sp) : -2 * log(cos(psi));
        const T t2 = p.alpha_x * p.alpha_x * l;
        c = 1 / sqrt(1 + t2), s = sqrt(t2) * c;
    }
    template <class T>
    static T theta_to_psi(const T& t, const ndf_params<T>& p) {
        using std::asin; using std::expm1; using std::sqrt; using std::tan;
        const T x = tan(t) / p.alpha_x;
        return asin(sqrt(-expm1(-x * x)));
    }
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        using std::exp;
        if (!(m.z() > 0)) return T(0);
        const T a2 = p.alpha_x * p.alpha_x, c2 = m.z() * m.z();
        return detail::exp_nonpositive(-detail::tan2(m) / a2) / (detail::pi<T>() * p.alpha_x * p.alpha_x * c2 * c2);
    }
    template <class T>
    static T lambda(const vec3<T>& w, const ndf_params<T>& p) { return detail::beckmann_lambda(w, p.alpha_x); }
    // Over L's azimuth phi: with cos^2 t_h = c^2 / (2 s), c = N.L + N.V, s = 1 + L.V = A + B cos phi
    // (A = 1 + N.L N.V, B = sin t_L sin t_V, A^2 - B^2 = c^2), D = 4 s^2 e^(-(2s/c^2 - 1)/a^2) /
    // (pi a^2 c^4). With s = d + B (1 + cos phi), d = A - B = c^2 / (A + B), and J_n of
    // beckmann_azimuth_moments at beta = 2 B / (a^2 c^2):
    //   e^(-E) (8 J_0 / (a^2 (A + B)^2) + 8 beta J_1 / (A + B) + 2 a^2 beta^2 J_2),
    //   E = (2d - c^2) / (a^2 c^2) = (N.L - N.V)^2 / (a^2 (sin t_L + sin t_V)^2),
    // a sum of terms >= 0 for every a, sharp where E is least: at N.L = N.V. Its rounding: the
    // exponent's 8 ulps (E of them in the exponential), 48 ulps of the sum, and the J_n's own.
    template <class T>
    static azimuthal_value<T> azimuthal_integral(const azimuth_point<T>& a, const ndf_params<T>& p) {
        using std::exp; using std::sqrt;
        const T eps = std::numeric_limits<T>::epsilon();
        const T a2 = p.alpha_x * p.alpha_x, c = a.nl + a.nv;
        const T sl = sqrt(a.sl2), sv = sqrt(a.sv2), b = sl * sv, apb = 1 + a.nl * a.nv + b;
        const T ss = sl + sv;
        const T e = ss > 0 ? a.nl_minus_nv * a.nl_minus_nv / (a2 * ss * ss) : T(0);
        const T beta = 2 * b / (a2 * c * c);
        const detail::azimuth_moments<T> j = detail::beckmann_azimuth_moments(beta);
        const T w0 = 8 / (a2 * apb * apb), w1 = 8 * beta / apb, w2 = 2 * a2 * beta * beta;
        const T decay = detail::exp_nonpositive(-e);
        const T value = decay * (w0 * j.j[0] + w1 * j.j[1] + w2 * j.j[2]);
        const T error = (48 + 8 * e) * eps * value + decay * (w0 * j.error[0] + w1 * j.error[1] + w2 * j.error[2]);
        return {value, error};
    }
};

}  // namespace normzoo::microfacet
