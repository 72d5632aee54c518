// The directional albedo of a form whose lobe is Blinn-Phong's (N.H)^n (docs/energy.md, "Forms
// with Blinn-Phong's lobe: the integral in its mass"): f = constant(n) (N.H)^n x lobe_factor,
// lobe_factor a function of N.L and L.H (brdf/brdf.hpp). With the normalized lobe
// D = (n+2)/(2 pi) (N.H)^n, whose D (N.H) is a density of H,
//     rho = integral over V of f N.V d(omega_V) = integral of D (N.H) * w(H) d(omega_H),
//     w = constant(n) 2 pi / (n+2) x lobe_factor x 4 (L.H) N.V / (N.H),
// the integral of microfacet/stretched.hpp in the lobe's mass (the roles of L and V swapped:
// there V is fixed). H is a node, never formed from L + V, so the ill-conditioning of H at
// grazing incidence that the generic integral meets (albedo.hpp) does not arise, nor (N.H)^n's.
//
// A node's rounding: N.V = 2 (L.H)(N.H) - N.L and L.H are sums of O(1) terms, absolutely accurate
// to a few ulps (L's own rounding to double included); w is linear in N.V and carries L.H to the
// power 1 - inverse_lh_power, and Schlick's term 5 min(1/F0, 1/(1 - L.H)) times L.H's error.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "brdf/brdf.hpp"
#include "microfacet/blinn_phong_polar.hpp"
#include "microfacet/stretched.hpp"
#include "quadrature/estimate.hpp"

namespace normzoo {

namespace detail {

template <class F, class = void>
struct has_lobe_factor : std::false_type {};
template <class F>
struct has_lobe_factor<F, std::void_t<decltype(F::lobe_factor(1.0, 1.0, brdf::params<double>{}))>> : std::true_type {};

}  // namespace detail

// Whether a form's f is constant(n) (N.H)^n x lobe_factor(N.L, L.H, p).
template <class Form>
inline constexpr bool has_blinn_phong_lobe = detail::has_lobe_factor<Form>::value;

// Where the integral in the lobe's mass is taken: exponents up to 1e6 (the lobe down to
// alpha = sqrt(2/(n+2)) = 1.4e-3) and incidence up to cos t = 1e-4 (89.994 degrees), the ranges
// its bounds were validated in against the generic integral (docs/energy.md); at normal incidence
// the generic integral is one integral in theta, and faster.
inline bool in_lobe_mass(double n, double cos_t) { return n >= 0 && n <= 1e6 && cos_t >= 1e-4 && cos_t < 1; }

namespace detail {

// w at a node (V is the direction integrated over: the node's nl is N.V and its vh is L.H), with
// its rounding bound.
template <class Form>
struct lobe_weight {
    double cos_t, n, specular;
    brdf::params<double> p{n, specular, 0};
    double scale = Form::constant(n) * 8 * pi<double>() / (n + 2);  // 2 pi / (n+2) x 4

    quadrature::estimate<double> operator()(const microfacet::half_vector_node& x) const {
        using std::abs;
        const double eps = std::numeric_limits<double>::epsilon();
        const double value = scale * Form::lobe_factor(cos_t, x.vh, p) * x.nl * x.vh * x.inv_muct * cos_t;
        const double lh_error = 16 * (x.st + cos_t * x.ct);  // absolute, on L.H
        double relative = 40 + 16 * (2 * x.vh * x.ct + cos_t + x.st) / x.nl + (1 + Form::inverse_lh_power) * lh_error / x.vh;
        if (Form::fresnel && specular < 1) relative += 5 * std::min(1 / specular, 1 / std::max(1 - x.vh, eps)) * lh_error;
        return {value, eps * relative * abs(value), 1};
    }
};

}  // namespace detail

// rho at incidence cos t = cos_t, sin t = sin_t (each rounded from the same angle), exponent n, to
// tolerance tol (absolute up to rho = 1, relative beyond), at most max_panels panels per adaptive
// integral.
template <class Form>
quadrature::estimate<double> lobe_albedo(double cos_t, double sin_t, double n, double specular, double tol,
                                         std::size_t max_panels) {
    using std::abs;
    using std::sqrt;
    const detail::lobe_weight<Form> w{cos_t, n, specular};
    const microfacet::stretched_lobe lobe{sqrt(2 / (n + 2)), false, true};
    auto at = [&](double t, double size) {
        return microfacet::detail::stretched_integral<microfacet::blinn_phong_lobe, 15, false>(n, cos_t, sin_t, lobe, t, max_panels, w, size);
    };
    // A factor that can exceed 1 (1/N.L, a power of 1/L.H) can make rho > 1, where the tolerance
    // is relative: a rough pass finds rho's size first.
    if (Form::inverse_lh_power > 0 || abs(Form::lobe_factor(cos_t, 1.0, w.p)) > 1) {
        const auto rough = at(std::max(tol, 1e-3), 1);
        return at(tol, std::max(1.0, abs(rough.value) - rough.abs_error));
    }
    return at(tol, 1);
}

}  // namespace normzoo
