// What every BRDF form has: one shape for all of them (docs/energy.md, docs/models.md).
//
// A form is a small value type, its code beside its formula and its literature (pbrt-v4 style):
//   id, formula, literature   strings for tables and docs
//   parameters                its parameters declared: a constexpr std::array of `parameter`
//                             (name "n", "alpha", "r" or "specular"; meaning; range; the grid of
//                             values the energy sweep takes, or none and the value it is held
//                             at). The first one with a grid is the one the energy table sweeps;
//                             a form without one appears once (parameter "none").
//   f(L, V, p)                the BRDF from unit vectors, p = params{n, specular, roughness}
//   lobe                      where its peak lies, so the albedo integral can centre its
//                             coordinates there: normal (around N), mirror ((R.V)^n around R),
//                             half ((N.H)^n, over H)
//   has_exponent              the integrator places its nodes with the lobe exponent p.n (for
//                             the forms indexed by alpha, the Phong-Beckmann exponent of alpha)
//   has_specular              f reads p.specular (c_spec, k_s, R_s)
//   inverse_lh_power, fresnel how f depends on L.H (a factor 1/(L.H)^k, a Schlick term): the
//                             albedo integral sizes its rounding error from them near grazing
//   reciprocal                Helmholtz: f(L, V) = f(V, L)
//   monte_carlo_case          the (value, incident angle) of its Monte Carlo cross-check, away
//                             from the extremes where Monte Carlo's variance explodes
//   albedo_at_normal(p)       where derived: the directional albedo at L = N, in closed form,
//                             for the params p (the tables' cross-check and the tests)
//   albedo_at(cos t)          where derived: the directional albedo at every incidence
// The forms normalized by a zoo row also have
//   zoo_row                   the row (docs/method.md) whose normalization its constant comes from
//   constant(n), exact_constant(n)   the factor in front of the lobe, and the exact one (they
//             differ for blinn-phong-modified-approx only); a shader's own expression replaces
//             constant(n), and the albedo scales with it
//   lobe_factor(nl, lh, p)   where f = constant(n) (N.H)^n x a factor of N.L (L's) and L.H alone:
//             that factor; the albedo is then integrated in the lobe's own mass (lobe_albedo.hpp). A
//             form derived from one of these that changes f must hide lobe_factor as well
// Adding a form: its header and one line in registry.hpp; the energy tables read the rest.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include "../geometry.hpp"
#include "../parameter.hpp"
#include "../zoo/zoo_row.hpp"

namespace normzoo::brdf {

using normzoo::pi;

enum class lobe_kind { normal, mirror, half };

template <class T>
struct params {
    T n = 0;         // the exponent
    T specular = 1;  // c_spec or k_s where the form has one
    T roughness = 0; // alpha (Ward) or the Disney roughness r, for the forms indexed by one
};

// The parameters a form declares (parameter.hpp: one representation for forms and parts).
using normzoo::parameter;
using normzoo::value_list;

// The grids the forms declare. The exponents: powers of two to 2048, then 1e4 and 1e5 (the energy
// sweep of docs/energy.md); alpha and r as docs/models.md sweeps them.
inline constexpr double energy_exponents[] = {1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 1e4, 1e5};
inline constexpr double anisotropic_phong_exponents[] = {1, 10, 100, 1000};
inline constexpr double ward_alphas[] = {0.1, 0.3, 0.5, 0.7, 1};
inline constexpr double disney_roughnesses[] = {0, 0.5, 1};

inline constexpr parameter exponent_n{"n", "the lobe exponent", 0, 1e9, energy_exponents};
inline constexpr parameter specular_ks{"specular", "c_spec or k_s, Schlick's F0", 0, 1, {}, 1};

// The Monte Carlo cross-check of a form: its parameter's value and the incident angle.
struct check_point {
    double value, theta_deg;
};

// Whether the energy sweep takes a parameter of the form: the first declared with a grid.
template <class Form>
constexpr bool has_swept_parameter() {
    for (const parameter& p : Form::parameters)
        if (!p.sweep.empty()) return true;
    return false;
}

// That parameter (only where has_swept_parameter).
template <class Form>
constexpr const parameter& swept_parameter() {
    static_assert(has_swept_parameter<Form>(), "the form sweeps no parameter");
    std::size_t i = 0;
    while (Form::parameters[i].sweep.empty()) ++i;
    return Form::parameters[i];
}

// Its name in the tables: n, alpha, r, or none.
template <class Form>
constexpr std::string_view swept_parameter_name() {
    if constexpr (has_swept_parameter<Form>()) return swept_parameter<Form>().name;
    else return "none";
}

namespace detail {
template <class F, class = void>
struct has_albedo_at_normal : std::false_type {};
template <class F>
struct has_albedo_at_normal<F, std::void_t<decltype(F::albedo_at_normal(std::declval<const params<double>&>()))>>
    : std::true_type {};
template <class F, class = void>
struct has_albedo_at : std::false_type {};
template <class F>
struct has_albedo_at<F, std::void_t<decltype(F::albedo_at(std::declval<const double&>()))>> : std::true_type {};
template <class F, class = void>
struct has_zoo_row : std::false_type {};
template <class F>
struct has_zoo_row<F, std::void_t<decltype(F::zoo_row)>> : std::true_type {};
template <class F, class = void>
struct has_node_exponent : std::false_type {};
template <class F>
struct has_node_exponent<F, std::void_t<decltype(F::node_exponent(0.0))>> : std::true_type {};
}  // namespace detail

// Whether a form has a closed-form albedo at L = N, at every incidence, and a zoo row.
template <class Form>
inline constexpr bool has_albedo_at_normal = detail::has_albedo_at_normal<Form>::value;
template <class Form>
inline constexpr bool has_albedo_at = detail::has_albedo_at<Form>::value;

// Whether a form's lobe has tails that fall slower than e^(-n theta^2) (GGX's fall like
// 1/tan^4): the albedo integral then does not cut the lobe where (N.H)^n is below e^-150.
namespace detail {
template <class F, class = void>
struct heavy_tailed : std::false_type {};
template <class F>
struct heavy_tailed<F, std::void_t<decltype(F::heavy_tail)>> : std::bool_constant<F::heavy_tail> {};
}  // namespace detail
template <class Form>
inline constexpr bool heavy_tailed = detail::heavy_tailed<Form>::value;

// Whether f has a kink where N.V = N.L (a max(N.L, N.V)): the adaptive rules' |K - G| cannot see
// a kink inside a panel (quadrature/adaptive.hpp), so the albedo integral makes it a breakpoint.
namespace detail {
template <class F, class = void>
struct kinked : std::false_type {};
template <class F>
struct kinked<F, std::void_t<decltype(F::kink_where_cosines_equal)>> : std::bool_constant<F::kink_where_cosines_equal> {};
}  // namespace detail
template <class Form>
inline constexpr bool kink_where_cosines_equal = detail::kinked<Form>::value;
// Whether a form chosen at run time can have kinks along curves where V.h takes given values
// (model.kink_vm(): a function writing them, or nullptr; a composition with Cook-Torrance's G;
// and model.critical_vh(): one constant value, or 0; F's critical angle of total internal
// reflection): the albedo integral finds them at each azimuth and makes them breakpoints.
namespace detail {
template <class F, class = void>
struct kinks_at_run_time : std::false_type {};
template <class F>
struct kinks_at_run_time<F, std::void_t<decltype(std::declval<const F&>().kink_vm())>> : std::true_type {};
}  // namespace detail
template <class Form>
inline constexpr bool kinks_at_run_time = detail::kinks_at_run_time<Form>::value;
// Whether f carries 1/sqrt(N.V) (Ward's normalization): f N.V then vanishes like the square root
// of the distance to V's horizon, a singularity at the end of the albedo integral's inner panels
// that its |K - G| meets only after many bisections; the albedo integral takes it in a variable
// where it is smooth (docs/energy.md, "The scales, and grading").
namespace detail {
template <class F, class = void>
struct sqrt_at_horizon : std::false_type {};
template <class F>
struct sqrt_at_horizon<F, std::void_t<decltype(F::inverse_sqrt_nv)>> : std::bool_constant<F::inverse_sqrt_nv> {};
}  // namespace detail
template <class Form>
inline constexpr bool sqrt_at_horizon = detail::sqrt_at_horizon<Form>::value;
template <class Form>
inline constexpr bool zoo_normalized = detail::has_zoo_row<Form>::value;

// Whether f depends on the azimuths of L and V apart, not only on their difference (an
// anisotropic lobe: a form's static `anisotropic`, or a run-time form's anisotropic_lobe()).
// At normal incidence the albedo of every other form is one integral in the polar angle.
namespace detail {
template <class F, class = void>
struct static_anisotropic : std::false_type {};
template <class F>
struct static_anisotropic<F, std::void_t<decltype(F::anisotropic)>> : std::bool_constant<F::anisotropic> {};
template <class F, class = void>
struct asks_anisotropic : std::false_type {};
template <class F>
struct asks_anisotropic<F, std::void_t<decltype(std::declval<const F&>().anisotropic_lobe())>> : std::true_type {};
}  // namespace detail
template <class Form>
bool anisotropic(const Form& form) {
    if constexpr (detail::asks_anisotropic<Form>::value) return form.anisotropic_lobe();
    else return detail::static_anisotropic<Form>::value;
}

// The params of a form at value x of its swept parameter, the others held. n sets the exponent;
// a roughness (alpha, r) sets p.roughness, and p.n is then the exponent the integrator places its
// nodes with (the form's node_exponent(x), or 0). `specular` replaces a held specular.
template <class Form>
params<double> params_at(double x, double specular = 1) {
    params<double> p;
    p.specular = Form::has_specular ? specular : 1.0;
    if constexpr (has_swept_parameter<Form>()) {
        if (swept_parameter<Form>().name == "n") {
            p.n = x;
        } else {
            p.roughness = x;
            if constexpr (detail::has_node_exponent<Form>::value) p.n = Form::node_exponent(x);
        }
    }
    return p;
}

// Schlick's approximation, F(c, x) = c + (1 - c)(1 - x)^5, x = L.H.
template <class T>
T fresnel_schlick(const T& c, const T& x) {
    const T m = 1 - x;
    const T m2 = m * m;
    return c + (1 - c) * m2 * m2 * m;
}

namespace detail {

// P(k) = integral of c^k over c in [1/sqrt 2, 1] = (1 - 2^(-(k+1)/2)) / (k+1); ln(2)/2 at k = -1.
template <class T>
T half_power_moment(const T& k) {
    using std::expm1;
    using std::log;
    const T ln2 = log(T(2));
    if (k + 1 == 0) return ln2 / 2;
    return -expm1(-(k + 1) * ln2 / 2) / (k + 1);
}

// At L = N: V is the mirror of N about H, N.V = 2c^2 - 1 with c = N.H = L.H, H runs over
// theta_h < 45 degrees, and d(omega_V) = 4 c d(omega_H). A form g(c) c^m then has albedo
//     2 pi * 4 * integral of g c^m (2c^2 - 1) c dc = 8 pi J(m + 1),   J(j) = 2 P(j+2) - P(j).
template <class T>
T half_vector_albedo_moment(const T& m) {
    return 8 * pi<T>() * (2 * half_power_moment(m + 3) - half_power_moment(m + 1));
}

}  // namespace detail

}  // namespace normzoo::brdf
