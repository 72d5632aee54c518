// The glTF material's albedo with V fixed under KHR_materials_sheen where its lobes are integrated
// node by node: a thin film (iridescence.hpp) or anisotropy (anisotropy.hpp), whose weights or D
// have no azimuthal integral in closed form (docs/materials.md, "The sheen's albedo scaling, over
// a film or anisotropy"). As sheen_albedo.hpp's, each core lobe's albedo under the scaling
// s = 1 - c max(E_v, E(N.L)) is
//     (1 - c E_v) A - c integral_0^1 max(0, E(y) - E_v) g(y) dy,
// A its albedo unscaled (about_v.hpp) and g(y) its integrand at N.L = y over L's azimuth, here
// by adaptive Gauss-Kronrod in the azimuth phi' from the mirror plane, L = (-s_y cos phi',
// s_y sin phi', y): the specular peak at phi' = 0 and y = N.V, graded from there, the film's kinks
// in V.H breakpoints in phi' (cos phi' = (sin^2 t_v + s_y^2 + (y + mu)^2 - 4 V.H^2) / (2 sin t_v s_y)).
// The outer integral in y is split as microfacet/azimuthal_albedo.hpp's: y itself on [0, mu/2],
// the offset u = y - mu beyond, so that the peak is exact relative to the nodes, and L + V's
// tangential part (sin t_v - s_y) + 2 s_y sin^2(phi'/2), sin t_v - s_y = u (y + mu) / (sin t_v + s_y),
// does not cancel. E(y) from the sheen's curve, as sheen_albedo.hpp's. Cost: the film's Fresnel
// at each node of the azimuthal integral at each node of y, 0.85 to 12 s a point.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "../microfacet/azimuthal_albedo.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/channels.hpp"
#include "about_v.hpp"
#include "gltf.hpp"
#include "sheen.hpp"
#include "sheen_albedo.hpp"

namespace normzoo::material {

namespace detail {

using core_channels = quadrature::channels<double, 9>;  // the diffuse's, specular's and metal's RGB

// g(y) of the core's three lobes, each channel: integral over phi' of weight x lobe x N.L, at
// N.L = y = mu + u (u exact), to tol absolute.
inline quadrature::estimate<core_channels> core_lobes_at(const gltf& m, double mu, double y, double u,
                                                         const std::vector<double>& kinks, double tol,
                                                         std::size_t max_panels) {
    using std::abs;
    using estimate = quadrature::estimate<core_channels>;
    const double eps = std::numeric_limits<double>::epsilon();
    const double sv = std::sqrt((1 - mu) * (1 + mu)), sy = std::sqrt((1 - y) * (1 + y)), ypm = y + mu;
    const double gap = sv + sy > 0 ? u * ypm / (sv + sy) : 0.0;  // sin t_v - s_y
    const vec3<double> v(sv, 0, mu);
    const auto lobe = m.specular_lobe();
    const double lambda_v = lobe.lambda(v);
    const auto terms = m.weight_terms();
    auto f = [&](double p) -> estimate {
        estimate e{core_channels{}, core_channels{}, 1};
        if (!(y > 0)) return e;
        const double sh = std::sin(p / 2), ch = std::cos(p / 2), bend = 2 * sy * sh * sh;
        const vec3<double> l(-sy * (1 - 2 * sh * sh), 2 * sy * sh * ch, y);
        const double sx = gap + bend, sy_ = 2 * sy * sh * ch;  // L + V: (sx, sy_, y + mu)
        const double len = std::sqrt(sx * sx + sy_ * sy_ + ypm * ypm);
        const vec3<double> h(sx / len, sy_ / len, ypm / len);
        const double vh = len / 2;
        const cosines c{y, mu, h.z(), vh};
        const auto w = m.weights(c, terms);
        const auto r = m.weight_rounding(c, terms);
        const double spec = lobe.d(h) * lobe.g(lobe.lambda(l), lambda_v) / (4 * mu);  // V D N.L
        // the specular's relative rounding: D's tan^2 from L + V's tangential part (its terms'
        // magnitudes: gap to 4 ulps, the bend to 6), G's Lambda of N.L exact, a few ulps more
        const double s2 = sx * sx + sy_ * sy_;
        const double sx_error = 4 * eps * abs(gap) + 6 * eps * bend + eps * abs(sx);
        const double d_rel = s2 > 0 ? 2 * (2 * abs(sx) * sx_error + 6 * eps * s2) / s2 + 32 * eps : 32 * eps;
        const double values[3] = {y / pi<double>(), spec, spec}, rel[3] = {8 * eps, d_rel, d_rel};
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t k = 0; k < 3; ++k) {
                e.value[3 * i + k] = w[i][k] * values[i];
                e.abs_error[3 * i + k] = rel[i] * abs(e.value[3 * i + k]) + (8 * eps + r[i][k]) * abs(values[i]);
            }
        return e;
    };
    // the peak at phi' = 0: |L + V|'s tangential part there is |gap|, growing like s_y phi'
    const double alpha = narrowest_alpha(lobe), pi_ = pi<double>();
    std::vector<double> half{0, pi_};
    if (sy > 0)
        for (double w = std::max(alpha * ypm, abs(gap)) / sy; w < pi_; w *= 4) half.push_back(w);
    if (sv > 0 && sy > 0)
        for (double k : kinks) {
            const double cp = (sv * sv + sy * sy + ypm * ypm - 4 * k * k) / (2 * sv * sy);
            if (cp > -1 && cp < 1) half.push_back(std::acos(cp));
        }
    // the anisotropic ridge: (L + V).b = s_y sin r cos phi' + s_y cos r sin phi' - sin t_v sin r
    const std::vector<double> ridge = ridge_breaks(lobe, -sv * lobe.sin_r, sy * lobe.sin_r, sy * lobe.cos_r);
    return over_the_arc(symmetric_in_g(lobe), half, f, tol, max_panels, !kinks.empty(), ridge);
}

// max(0, E(N.L) - E_v) as a factor of N.L on the lobes (about_v.hpp): E from the sheen's curve,
// its kinks where E(y) crosses E_v (y = mu, and the curve's crossings: all of them unless the
// curve says otherwise, sheen_curve.hpp).
struct sheen_excess_factor {
    const sheen_albedo_curve<>& e;
    quadrature::estimate<double> e_v;
    bool complete = true;
    std::vector<double> crossings;
    sheen_excess_factor(const sheen_albedo_curve<>& e_, const quadrature::estimate<double>& e_v_, double mu)
        : e(e_), e_v(e_v_), crossings(e_.crossings(e_v_.value, &complete)) {
        crossings.push_back(mu);
        std::sort(crossings.begin(), crossings.end());
    }
    quadrature::estimate<double> operator()(double nl) const {
        const node_excess x = sheen_excess_at(nl, e, e_v);
        return {x.value, x.error, 0};
    }
    // max(0, .) moves by at most what E does
    double slope(double nl) const { return e.slope(nl); }
    const std::vector<double>& kinks() const { return crossings; }
    bool kinks_complete() const { return complete; }
};

// integral_0^1 max(0, E(y) - E_v) g(y) dy for the core's lobes, each channel: y on [0, mu/2], the
// offset u = y - mu on [-mu/2, 1 - mu].
inline quadrature::estimate<core_channels> core_sheen_excess(const gltf& m, double mu,
                                                             const quadrature::estimate<double>& e_v,
                                                             const sheen_albedo_curve<>& e_of, double tol,
                                                             std::size_t max_panels) {
    using estimate = quadrature::estimate<core_channels>;
    const double eps = std::numeric_limits<double>::epsilon();
    const std::vector<double> kinks = m.weight_kinks();
    auto at = [&](double y, double u) -> estimate {
        estimate r{core_channels{}, core_channels{}, 1};
        if (!(y > 0)) return r;
        const node_excess x = sheen_excess_at(y, e_of, e_v);
        if (x.zero) return r;
        const double excess = x.value, excess_error = x.error;
        const auto g = core_lobes_at(m, mu, y, u, kinks, tol / 4, max_panels);
        r.evaluations += g.evaluations;
        for (std::size_t k = 0; k < 9; ++k) {
            r.value[k] = g.value[k] * excess;
            r.abs_error[k] = std::abs(g.value[k]) * excess_error + g.abs_error[k] * excess + 4 * eps * std::abs(r.value[k]);
        }
        return r;
    };
    // breakpoints: the lobes' (the peak at u = 0, the horizon), E's (its branch at 1/2, graded
    // toward the horizon)
    const microfacet::detail::azimuthal_breaks b(mu, narrowest_alpha(m.specular_lobe()));
    std::vector<double> in_u = b.x, in_y = b.nl;
    for (double y : {0.5, 0.125, 0.03125, 0.0078125, 0.001953125, 0.00048828125}) (y < mu / 2 ? in_y : in_u).push_back(y < mu / 2 ? y : y - mu);
    in_u = microfacet::detail::azimuthal_breaks::kept(in_u, -mu / 2, 1 - mu);
    in_y = microfacet::detail::azimuthal_breaks::kept(in_y, 0.0, mu / 2);
    const quadrature::adaptive_kronrod<double, 15> rule(max_panels, true);
    auto e = rule.integrate([&](double u) { return at(mu + u, u); }, in_u, tol / 2, 0.0);
    const auto near = rule.integrate([&](double y) { return at(y, y - mu); }, in_y, tol / 2, 0.0);
    e.value += near.value, e.abs_error += near.abs_error, e.evaluations += near.evaluations;
    return e;
}

}  // namespace detail

// The albedo of a glTF material with a sheen over a film or anisotropy, without its coat
// (coat_albedo.hpp scales this), each lobe and the whole per channel, to about settings.tolerance.
inline material_albedo<gltf::lobe_count> sheen_albedo_by_nodes(const gltf& coated, double mu, const albedo_settings& settings = {}) {
    const double eps = std::numeric_limits<double>::epsilon();
    gltf m = coated;
    m.in.clearcoat = 0;
    const double c = m.sheen_scaling().c, alpha_s = m.sheen_lobe().alpha;
    bool built = false;
    const auto e_of = sheen_curve_for(alpha_s, detail::sheen_curve_tolerance(settings.tolerance), &built);
    const auto e_v = (*e_of)(mu);
    const double keep = 1 - c * e_v.value;
    gltf bare = m;
    bare.in.sheenColor = grey(0);
    albedo_settings s = settings;
    s.tolerance = settings.tolerance / (2 * std::max(1.0, std::abs(keep)));
    material_albedo<gltf::lobe_count> r = albedo_about_v(bare, mu, s);
    // the excess: about V as the unscaled albedo (the film's weights once a node of V.H), the
    // factor max(0, E(N.L) - E_v) on the lobes; an anisotropic lobe by the azimuth from the mirror
    // plane (the route about V errs beyond its bound for a narrow anisotropic lobe, docs/materials.md)
    detail::core_channels excess{}, excess_error{};
    if (!m.specular_lobe().anisotropic()) {
        albedo_settings se = settings;
        se.tolerance = settings.tolerance / (2 * c);
        const auto x = albedo_about_v(bare, mu, se, detail::sheen_excess_factor(*e_of, e_v, mu));
        r.evaluations += x.evaluations;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t ch = 0; ch < 3; ++ch)
                excess[3 * i + ch] = x.lobes[i].value[ch], excess_error[3 * i + ch] = x.lobes[i].abs_error[ch];
    } else {
        const auto x = detail::core_sheen_excess(m, mu, e_v, *e_of, settings.tolerance / (8 * c), settings.max_panels);
        r.evaluations += x.evaluations;
        excess = x.value, excess_error = x.abs_error;
    }
    r.evaluations += built ? e_of->evaluations() : 0;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t ch = 0; ch < 3; ++ch) {
            auto& lobe = r.lobes[i];
            const double unscaled = lobe.value[ch], lost = excess[3 * i + ch];
            lobe.value[ch] = keep * unscaled - c * lost;
            lobe.abs_error[ch] = std::abs(keep) * lobe.abs_error[ch] + c * e_v.abs_error * std::abs(unscaled) +
                                 c * excess_error[3 * i + ch] + 4 * eps * (std::abs(keep * unscaled) + std::abs(c * lost));
        }
    for (std::size_t ch = 0; ch < 3; ++ch) {
        r.lobes[3].value[ch] = m.in.sheenColor[ch] * e_v.value;
        r.lobes[3].abs_error[ch] = m.in.sheenColor[ch] * e_v.abs_error + 2 * eps * r.lobes[3].value[ch];
    }
    detail::sum_lobes(r);
    return r;
}

}  // namespace normzoo::material
