// The normal distribution parts D(m) of a microfacet BRDF (docs/microfacet.md): each a small
// value type with its id (the D of a composition id D/G/F), its formula, its literature, and
//   d(m, p)          D of the unit microfacet normal m, in the frame N = z, tangent x, bitangent y
//   lambda(w, p)     Smith's Lambda for the direction w, where it has a closed form
//                    (has_exact_lambda); G1(w) = 1 / (1 + Lambda(w))
// p = ndf_params{alpha_x, alpha_y, gamma}: the roughness of Walter et al. 2007 (alpha_x =
// alpha_y for the isotropic parts, which read alpha_x), and GTR's exponent gamma.
//   blinn-phong     (n+2)/(2 pi) (N.m)^n, n = 2/alpha^2 - 2            Blinn 1977; Walter et al. 2007
//   beckmann        e^(-tan^2 t / a^2) / (pi a^2 cos^4 t)               Beckmann and Spizzichino 1963
//   ggx             a^2 / (pi cos^4 t (a^2 + tan^2 t)^2)                Trowbridge and Reitz 1975; Walter et al. 2007
//   gtr             c / (a^2 cos^2 t + sin^2 t)^gamma                    Burley 2012, appendix B
//   ggx-aniso       1 / (pi ax ay cos^4 t (1 + tan^2 t (cos^2 p / ax^2 + sin^2 p / ay^2))^2)
//   beckmann-aniso  e^(-tan^2 t (cos^2 p / ax^2 + sin^2 p / ay^2)) / (pi ax ay cos^4 t)
// The anisotropic Lambdas are the isotropic ones at the roughness seen along w's azimuth,
// sqrt(cos^2 p ax^2 + sin^2 p ay^2) (Heitz 2014, section 5).
//   polar(psi, p)    (has_polar_map) the polar angle t of m, as (cos t, sin t), below which
//                    D(m) N.m holds the mass sin^2 psi; theta_to_psi(t, p) its inverse. In psi
//                    the projected distribution is flat (the inverse CDF of the importance
//                    samplers of Walter et al. 2007): microfacet/albedo.hpp integrates in it.
//   azimuthal_integral(a, p)  (has_azimuthal_integral) the integral of D(h) over L's azimuth,
//                    h the half vector of L and V, at one polar angle of L (an azimuth_point),
//                    with a bound on its rounding (an azimuthal_value): the albedo with F = 1 is
//                    then a 1D integral (microfacet/azimuthal_albedo.hpp). GGX and Beckmann.
//   azimuthal_schlick_integral(a, p)  (has_azimuthal_schlick_integral) the same of D(h) (1 - V.h)^5,
//                    Schlick's factor, and its rounding bound: the albedo with Schlick's F is then
//                    the same 1D integral (microfacet/ggx_schlick_azimuth.hpp). GGX.
// Where a part's formula is a zoo row's, it calls the row (models/): GGX's D is models::ggx::d,
// Blinn-Phong's D is models::blinn_phong's lobe with the heightfield row's constant, tan^2 and pi
// are the rows' too. The rows include nothing of microfacet/, so the dependence runs one way, as
// brdf/ -> models/. Beckmann's D and the Lambdas stay here: they round differently from the
// rows' (see there), and the tables hold each as it is.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <limits>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "../geometry.hpp"
#include "../models/blinn_phong.hpp"
#include "../models/ggx.hpp"
#include "blinn_phong_polar.hpp"
#include "ggx_schlick_azimuth.hpp"

namespace normzoo::microfacet {

template <class T>
struct ndf_params {
    T alpha_x = T(0.5), alpha_y = T(0.5);
    T gamma = T(2);  // GTR only
};

// A polar angle of L for V fixed, as D's integral over L's azimuth reads it: cos t_L and
// cos t_V, their difference (exact where they are close: the peak of D sits there) and the
// squares of their sines, each from the variable it is integrated in (microfacet/azimuthal_albedo.hpp).
template <class T>
struct azimuth_point {
    T nl, nv;          // cos t_L, cos t_V
    T nl_minus_nv;     // cos t_L - cos t_V
    T sl2, sv2;        // sin^2 t_L, sin^2 t_V
};

// D's integral over L's azimuth and a bound on its rounding error.
template <class T>
struct azimuthal_value {
    T value, error;
};

namespace detail {
using normzoo::pi;
// e^x where x <= 0: in double, 0 without calling the library below x = -746, where its result
// rounds to 0 anyway and it takes its underflow path (errno; 2x to 3x the time of a normal call,
// where Beckmann's tails spend a fifth of their time).
template <class T>
T exp_nonpositive(const T& x) {
    using std::exp;
    if constexpr (std::is_same_v<T, double>)
        if (x < -746) return T(0);
    return exp(x);
}
// tan^2 of m's polar angle from its components (no 1 - cos^2): the rows' (models/ndf_row.hpp).
template <class T>
T tan2(const vec3<T>& m) { return models::tan2_of(m); }
// The roughness seen along w's azimuth: sqrt(cos^2 p ax^2 + sin^2 p ay^2), from w's components.
template <class T>
T projected_alpha(const vec3<T>& w, const ndf_params<T>& p) {
    using std::sqrt;
    const T r2 = w.x() * w.x() + w.y() * w.y();
    if (!(r2 > 0)) return p.alpha_x;
    return sqrt((w.x() * w.x() * p.alpha_x * p.alpha_x + w.y() * w.y() * p.alpha_y * p.alpha_y) / r2);
}
// Smith's Lambda for Beckmann and GGX, w at polar angle t, a the roughness along its azimuth
// (Heitz 2014): m = 1 / (a tan t). Not the rows' lambda (models/): these start from w's
// components, not (cos, sin), and round otherwise (below).
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
template <class T>
T ggx_lambda(const vec3<T>& w, const T& a) {
    using std::sqrt;
    using std::abs;
    // (sqrt(1 + a^2 tan^2) - 1) / 2 without cancellation and with one division (it runs at every
    // node of the albedo integral): with q = a^2 (x^2 + y^2), q / (2 z (z + sqrt(z^2 + q)))
    const T q = a * a * (w.x() * w.x() + w.y() * w.y()), z = abs(w.z());
    return q / (2 * z * (z + sqrt(z * z + q)));
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
        // I_0, I_1 to a few ulps without Boost's promotion of double to long double (as erfc above)
        using no_promotion = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
        const T e = exp(-beta);
        const T i0 = boost::math::cyl_bessel_i(0, beta, no_promotion()) * e;
        const T i1 = boost::math::cyl_bessel_i(1, beta, no_promotion()) * e;
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

struct d_blinn_phong {
    static constexpr std::string_view id = "blinn-phong";
    static constexpr std::string_view parameters = "";  // what it reads beyond alpha (composition::reads)
    static constexpr const char* formula = "(n+2)/(2 pi) (N.m)^n, n = 2/alpha^2 - 2";
    static constexpr const char* literature = "Blinn 1977; the mapping of Walter et al. 2007";
    static constexpr bool isotropic = true, has_exact_lambda = false, has_polar_map = true, has_azimuthal_integral = false, has_azimuthal_schlick_integral = false;
    template <class T>
    static T exponent(const ndf_params<T>& p) { return 2 / (p.alpha_x * p.alpha_x) - 2; }
    // mass below t: 1 - cos^(n+2) t = sin^2 psi (blinn_phong_polar.hpp)
    template <class T>
    static void polar(const T& psi, const ndf_params<T>& p, T& c, T& s) { blinn_phong_polar(psi, exponent(p), c, s); }
    template <class T>
    static T theta_to_psi(const T& t, const ndf_params<T>& p) { return blinn_phong_theta_to_psi(t, exponent(p)); }
    // (N.m)^n with the heightfield row's (n+2)/(2 pi): D (N.m) integrates to 1 (models/blinn_phong.hpp)
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        if (!(m.z() > 0)) return T(0);
        const T n = exponent(p);
        return models::blinn_phong_heightfield::closed_form(n) * models::blinn_phong::lobe(m, n);
    }
};

struct d_beckmann {
    static constexpr std::string_view id = "beckmann";
    static constexpr std::string_view parameters = "";
    static constexpr const char* formula = "e^(-tan^2 t / a^2) / (pi a^2 cos^4 t)";
    static constexpr const char* literature = "Beckmann and Spizzichino 1963; Walter et al. 2007; Heitz 2014 (Lambda)";
    static constexpr bool isotropic = true, has_exact_lambda = true, has_polar_map = true, has_azimuthal_integral = true, has_azimuthal_schlick_integral = false;
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
    // Not models::beckmann::d: that rounds pi a^2 cos^4 as ((pi a) a) c^2 c^2, this as (pi a^2) c^2 c^2.
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        using std::exp;
        if (!(m.z() > 0)) return T(0);
        const T a2 = p.alpha_x * p.alpha_x, c2 = m.z() * m.z();
        return detail::exp_nonpositive(-detail::tan2(m) / a2) / (detail::pi<T>() * a2 * c2 * c2);
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

struct d_ggx {
    static constexpr std::string_view id = "ggx";
    static constexpr std::string_view parameters = "";
    static constexpr const char* formula = "a^2 / (pi cos^4 t (a^2 + tan^2 t)^2)";
    static constexpr const char* literature = "Trowbridge and Reitz 1975; Walter et al. 2007; Heitz 2014 (Lambda)";
    static constexpr bool isotropic = true, has_exact_lambda = true, has_polar_map = true, has_azimuthal_integral = true, has_azimuthal_schlick_integral = true;
    // mass below t: tan^2 t / (a^2 + tan^2 t) = sin^2 psi, so tan t = a tan psi
    template <class T>
    static void polar(const T& psi, const ndf_params<T>& p, T& c, T& s) {
        using std::cos; using std::sin; using std::sqrt;
        const T cp = cos(psi), sp = p.alpha_x * sin(psi), r = sqrt(cp * cp + sp * sp);
        c = cp / r, s = sp / r;
    }
    template <class T>
    static T theta_to_psi(const T& t, const ndf_params<T>& p) {
        using std::atan2; using std::cos; using std::sin;
        return atan2(sin(t), p.alpha_x * cos(t));
    }
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) { return models::ggx::d(m, p.alpha_x); }
    template <class T>
    static T lambda(const vec3<T>& w, const ndf_params<T>& p) { return detail::ggx_lambda(w, p.alpha_x); }
    // Over L's azimuth phi: with h = (L + V) / |L + V|, cos^2 t_h = c^2 / (2 (1 + L.V)), c = N.L +
    // N.V, D = a^2 (2s)^2 / (pi (2s - c^2 (1 - a^2))^2) with s = 1 + L.V = A + B cos phi, a ratio
    // of quadratics in cos phi; the integrals of 1/(R + S cos phi) and of its square over the circle
    // (2 pi / sqrt(R^2 - S^2), 2 pi R / (R^2 - S^2)^(3/2)) give
    //   2 a^2 (1 + 2 c (1 - a^2) / sqrt(Q) + c (1 - a^2)^2 (sin^2 t_L + sin^2 t_V + a^2 c^2) / Q^(3/2)),
    //   Q = (N.L - N.V)^2 + 2 a^2 (sin^2 t_L + sin^2 t_V) + a^4 c^2   ((R^2 - S^2) = c^2 Q),
    // a sum of terms >= 0 for a <= 1 (no cancellation), sharp where Q is least: at N.L = N.V.
    // Its rounding: 16 ulps (a few sums of terms >= 0 and a square root).
    template <class T>
    static azimuthal_value<T> azimuthal_integral(const azimuth_point<T>& a, const ndf_params<T>& p) {
        using std::sqrt;
        const T a2 = p.alpha_x * p.alpha_x, m = 1 - a2, c = a.nl + a.nv, s2 = a.sl2 + a.sv2;
        const T q = a.nl_minus_nv * a.nl_minus_nv + 2 * a2 * s2 + a2 * a2 * c * c;
        const T r = 1 / sqrt(q);
        const T value = 2 * a2 * (1 + 2 * c * m * r + c * m * m * (s2 + a2 * c * c) * (r * r * r));
        return {value, 16 * std::numeric_limits<T>::epsilon() * value};
    }
    // The same of D (1 - V.h)^5: complete elliptic integrals (ggx_schlick_azimuth.hpp), in double.
    static azimuthal_value<double> azimuthal_schlick_integral(const azimuth_point<double>& a, const ndf_params<double>& p) {
        const auto r = detail::ggx_schlick_azimuthal_integrals(a.nl, a.nv, a.nl_minus_nv, a.sl2, a.sv2, p.alpha_x);
        return {r.d5, r.d5_error};
    }
};

// Burley's generalized Trowbridge-Reitz: gamma = 2 is GGX, gamma = 1 Berry's distribution.
struct d_gtr {
    static constexpr std::string_view id = "gtr";
    static constexpr std::string_view parameters = "gamma";
    static constexpr const char* formula =
        "c / (a^2 cos^2 t + sin^2 t)^gamma, c = (gamma - 1)(a^2 - 1) / (pi (1 - a^(2 (1 - gamma)))) "
        "((a^2 - 1) / (pi ln a^2) at gamma = 1; 1/pi at a = 1)";
    static constexpr const char* literature = "Burley 2012, \"Physically-Based Shading at Disney\", appendix B";
    static constexpr bool isotropic = true, has_exact_lambda = false, has_polar_map = false, has_azimuthal_integral = false, has_azimuthal_schlick_integral = false;
    template <class T>
    static T constant(const ndf_params<T>& p) {
        using std::abs;
        using std::exp;
        using std::log;
        const T a2 = p.alpha_x * p.alpha_x, g = p.gamma;
        if (a2 == 1) return 1 / detail::pi<T>();
        if (g == 1) return (a2 - 1) / (detail::pi<T>() * log(a2));
        // 1 - a2^(1 - g) = -(e^x - 1), x = (1 - g) ln a2: by the series of e^x - 1 where x is
        // small (gamma near 1), where 1 - pow(...) would cancel
        const T x = (1 - g) * log(a2);
        T em1 = x;
        if (abs(x) < T(0.5)) {
            T term = x;
            for (int k = 2; abs(term) > std::numeric_limits<T>::epsilon() * abs(em1); ++k) term *= x / k, em1 += term;
        } else {
            em1 = exp(x) - 1;
        }
        return (g - 1) * (a2 - 1) / (detail::pi<T>() * -em1);
    }
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        using std::pow;
        if (!(m.z() > 0)) return T(0);
        const T a2 = p.alpha_x * p.alpha_x, c2 = m.z() * m.z(), s2 = m.x() * m.x() + m.y() * m.y();
        return constant(p) / pow(a2 * c2 + s2, p.gamma);
    }
};

struct d_ggx_aniso {
    static constexpr std::string_view id = "ggx-aniso";
    static constexpr std::string_view parameters = "aspect";
    static constexpr const char* formula = "1 / (pi ax ay cos^4 t (1 + tan^2 t (cos^2 p / ax^2 + sin^2 p / ay^2))^2)";
    static constexpr const char* literature = "Burley 2012; Heitz 2014, section 5 (Lambda)";
    static constexpr bool isotropic = false, has_exact_lambda = true, has_polar_map = false, has_azimuthal_integral = false, has_azimuthal_schlick_integral = false;
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        if (!(m.z() > 0)) return T(0);
        const T c2 = m.z() * m.z();
        const T e = (m.x() * m.x() / (p.alpha_x * p.alpha_x) + m.y() * m.y() / (p.alpha_y * p.alpha_y)) / c2;
        return 1 / (detail::pi<T>() * p.alpha_x * p.alpha_y * c2 * c2 * (1 + e) * (1 + e));
    }
    template <class T>
    static T lambda(const vec3<T>& w, const ndf_params<T>& p) { return detail::ggx_lambda(w, detail::projected_alpha(w, p)); }
};

struct d_beckmann_aniso {
    static constexpr std::string_view id = "beckmann-aniso";
    static constexpr std::string_view parameters = "aspect";
    static constexpr const char* formula = "e^(-tan^2 t (cos^2 p / ax^2 + sin^2 p / ay^2)) / (pi ax ay cos^4 t)";
    static constexpr const char* literature = "Beckmann and Spizzichino 1963; Heitz 2014, section 5 (Lambda)";
    static constexpr bool isotropic = false, has_exact_lambda = true, has_polar_map = false, has_azimuthal_integral = false, has_azimuthal_schlick_integral = false;
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        using std::exp;
        if (!(m.z() > 0)) return T(0);
        const T c2 = m.z() * m.z();
        const T e = (m.x() * m.x() / (p.alpha_x * p.alpha_x) + m.y() * m.y() / (p.alpha_y * p.alpha_y)) / c2;
        return detail::exp_nonpositive(-e) / (detail::pi<T>() * p.alpha_x * p.alpha_y * c2 * c2);
    }
    template <class T>
    static T lambda(const vec3<T>& w, const ndf_params<T>& p) {
        return detail::beckmann_lambda(w, detail::projected_alpha(w, p));
    }
};

// The D parts, one list: a composition id's D is one of these ids.
using distribution_parts = std::tuple<d_blinn_phong, d_beckmann, d_ggx, d_gtr, d_ggx_aniso, d_beckmann_aniso>;

// Calls fn(part) with the part named `id`; false when there is none.
template <class Fn>
bool with_distribution(std::string_view id, Fn&& fn) {
    return std::apply([&](auto... part) { return ((decltype(part)::id == id ? (fn(part), true) : false) || ...); },
                      distribution_parts{});
}

}  // namespace normzoo::microfacet
