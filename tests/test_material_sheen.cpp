// KHR_materials_sheen and KHR_materials_clearcoat on the glTF material (docs/materials.md): the
// sheen's E against the compositions' integral and a closed form, the sheen-scaled material
// against an independent quadrature over L, the extensions off giving the core, the coat's
// composition. Every expected value is computed by a route that shares no code with the one it
// checks beyond the lobes' formulas.
#include <catch2/catch.hpp>

#include "sanitized.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <vector>

#include <normzoo/material/compensation.hpp>
#include <normzoo/material/sheen_curve.hpp>

namespace {

namespace mat = normzoo::material;
namespace mf = normzoo::microfacet;
using R = long double;

mat::gltf sheened(double metallic, double roughness, mat::rgb base, mat::rgb sheen, double sheen_roughness) {
    mat::gltf m;
    m.in.metallic = metallic, m.in.roughness = roughness, m.in.baseColor = base;
    m.in.sheenColor = sheen, m.in.sheenRoughness = sheen_roughness;
    return m;
}

// The sheen-scaled material's albedo, channel ch, by plain adaptive Gauss-Kronrod in long double:
// over N.L = y (split at mu and 1/2), of the core's f from vectors integrated over L's azimuth,
// times 1 - c max(E_v, E(y)). It shares with gltf_albedo only E (sheen_albedo, checked against
// the compositions' integral below); not the closed azimuthal integrals, the split of the weights,
// nor where E crosses E_v. Asked 1e-12 relative on the two panels.
R plain_sheened_albedo(const mat::gltf& m, std::size_t ch, double mu, std::map<double, double>& e_cache) {
    using gk = boost::math::quadrature::gauss_kronrod<R, 31>;
    const R pi = boost::math::constants::pi<R>();
    mat::gltf core = m;
    core.in.sheenColor = mat::grey(0);
    const double sv = std::sqrt((1 - mu) * (1 + mu)), alpha_s = m.sheen_lobe().alpha, c = m.sheen_scaling().c;
    const normzoo::vec3<double> v(sv, 0, mu);
    const double e_v = mat::sheen_albedo(mu, alpha_s, 1e-13).value;
    auto in_y = [&](R y) {
        const R sy = std::sqrt((1 - y) * (1 + y));
        auto in_phi = [&](R phi) {
            const normzoo::vec3<double> l(double(sy * std::cos(phi)), double(sy * std::sin(phi)), double(y));
            R sum = 0;
            for (const auto& lobe : core.f_lobes(l, v)) sum += lobe[ch];
            return sum;
        };
        const R azimuthal = 2 * gk::integrate(in_phi, R(0), pi, 10, R(1e-13));
        auto [at, fresh] = e_cache.try_emplace(double(y), 0.0);  // the three channels share E(y)
        if (fresh) at->second = mat::sheen_albedo(double(y), alpha_s, 1e-13).value;
        return azimuthal * y * (1 - c * std::max(e_v, at->second));
    };
    // panels at mu, 1/2 and where E(y) crosses E_v (a log grid's sign changes, bisected): E rises
    // toward grazing, falls, then grows like 1/y below ~1e-4 (the fit's Lambda is finite at 0)
    std::vector<R> ends{0, R(mu), 0.5, 1};
    double prev = 1e-9;
    for (double y = 2e-9; y < 1; y *= 2) {
        const double a = prev, b = std::min(y, 1.0);
        auto above = [&](double t) { return mat::sheen_albedo(t, alpha_s, 1e-11).value > e_v; };
        if (above(a) != above(b) && !(a < mu && mu < b)) {
            double lo = a, hi = b;
            for (int i = 0; i < 40; ++i) ((above(lo) == above(0.5 * (lo + hi))) ? lo : hi) = 0.5 * (lo + hi);
            ends.push_back(R(0.5 * (lo + hi)));
        }
        prev = y;
    }
    std::sort(ends.begin(), ends.end());
    R sum = 0;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i)
        if (ends[i + 1] > ends[i])  // a panel within 1e-2 of the horizon holds at most ~1e-4 of the value: 1e-7 of it
            sum += gk::integrate(in_y, ends[i], ends[i + 1], ends[i + 1] < 1e-2 ? 6 : 12, R(ends[i + 1] < 1e-2 ? 1e-7 : 1e-12));
    // the sheen lobe on top: its weight times E_v
    return sum + m.in.sheenColor[ch] * e_v;
}

}  // namespace

TEST_CASE("sheen: E by the 1D azimuthal route is the composition charlie/charlie-sheen/one's albedo") {
    const auto [mu, r] = GENERATE(table<double, double>({{1, 0.5}, {0.5, 1}, {0.2, 0.3}, {0.01, 0.7}, {1e-8, 1}, {0.8, 0.05}}));
    const auto e = mat::sheen_albedo(mu, r * r);
    normzoo::albedo_settings tight;
    tight.tolerance = 1e-12;
    const auto c = mf::directional_albedo(mf::composition::parse("charlie/charlie-sheen/one"), mu, r * r, 1, tight);
    CAPTURE(mu, r, e.value, c.value, e.abs_error, c.abs_error, e.value - c.value);
    CHECK(std::abs(e.value - c.value) <= e.abs_error + c.abs_error);
    CHECK(e.abs_error <= 1e-10);
}

// The curve of E (sheen_curve.hpp) against exact E at points in each of its regions and at their
// joins, below its lowest piece (y < 1e-10: an enclosure) and at 1: within the two bounds, and
// its bound within the tolerance times max(1, E) from 1e-10 up.
TEST_CASE("sheen: E's curve meets exact E within the bounds, from below 1e-10 to 1") {
    const double alpha = GENERATE(normzoo_test::thinned_under_sanitizers(2, values({0.09, 1e-3, 1.0})));
    const double tol = 1e-11;
    const mat::sheen_albedo_curve<> curve(alpha, tol);
    const double points[] = {1e-12, 3e-10, 2e-7, 1e-4, 0.013, 0.124, 0.125, 0.3, 0.5, 0.77, 0.875, 0.93, 1 - 1e-6, 1 - 1e-12, 1};
    for (double y : points) {
        const auto quick = mat::sheen_albedo(y, alpha, 1e-3);
        const auto exact = mat::sheen_albedo(y, alpha, 1e-13 * std::max(1.0, quick.value));
        const auto c = curve(y);
        CAPTURE(alpha, y, c.value, exact.value, c.abs_error, exact.abs_error, c.value - exact.value);
        CHECK(std::abs(c.value - exact.value) <= c.abs_error + exact.abs_error);
        if (y >= mat::sheen_albedo_curve<>::y_lo) CHECK(c.abs_error <= tol * std::max(1.0, exact.value));
    }
}

// The kinks of max(0, E - E_v) are the curve's crossings of E_v (sheen_curve.hpp), all of them:
// on a grid of 20,000 points in ln y, every sign change of E - level has a crossing between its
// two points, at levels of E at several y and just below E's maximum near grazing, where the
// two crossings lie closer together than any fixed grid's step.
TEST_CASE("sheen: the curve's crossings of a level are all of them") {
    const double alpha = GENERATE(normzoo_test::thinned_under_sanitizers(2, values({0.25, 1.0})));
    const auto curve = mat::sheen_curve_for(alpha, 1e-11);
    const int n = 20000;
    std::vector<double> ys(n + 1), es(n + 1);
    for (int i = 0; i <= n; ++i) {
        ys[std::size_t(i)] = std::exp(std::log(1e-10) * (1 - double(i) / n)) * (1 - 1e-9);
        es[std::size_t(i)] = (*curve)(ys[std::size_t(i)]).value;
    }
    // E's maximum near grazing, on the grid (E falls toward 1e-4, then grows like y^-0.93)
    double top = 0;
    for (int i = 0; i <= n; ++i)
        if (ys[std::size_t(i)] > 1e-3 && ys[std::size_t(i)] < 0.5) top = std::max(top, es[std::size_t(i)]);
    for (double level : {(*curve)(1e-6).value, (*curve)(0.02).value, (*curve)(0.3).value, (*curve)(1.0).value, top * (1 - 1e-6),
                         top * (1 - 1e-9)}) {
        const std::vector<double> at = curve->crossings(level);
        int changes = 0, missed = 0;
        for (std::size_t i = 0; i < std::size_t(n); ++i) {
            if ((es[i] > level) == (es[i + 1] > level)) continue;
            ++changes;
            const bool found = std::any_of(at.begin(), at.end(), [&](double y) { return y >= ys[i] && y <= ys[i + 1]; });
            if (!found) ++missed;
        }
        CAPTURE(alpha, level, changes, at.size());
        CHECK(changes > 0);
        CHECK(missed == 0);
    }
}

// With Neubelt's visibility at mu = 1: E = 2^(-r/2) / (r + 4), r = 1/alpha (test_material_parts.cpp
// derives it); and the route against the composition charlie/neubelt/one below normal incidence.
TEST_CASE("sheen: E's route with neubelt's visibility meets the closed form at mu = 1 and the composition") {
    const double alpha = GENERATE(0.01, 0.1, 0.25, 1.0);
    const double r = 1 / alpha, closed = std::exp2(-r / 2) / (r + 4);
    const auto e = mat::sheen_albedo<mf::g_neubelt>(1.0, alpha);
    CAPTURE(alpha, e.value, e.abs_error, closed);
    CHECK(std::abs(e.value - closed) <= e.abs_error + 4e-16 * closed);
    const auto at = mat::sheen_albedo<mf::g_neubelt>(0.3, alpha);
    const auto c = mf::directional_albedo(mf::composition::parse("charlie/neubelt/one"), 0.3, alpha);
    CHECK(std::abs(at.value - c.value) <= at.abs_error + c.abs_error);
}

TEST_CASE("sheen and clearcoat off: the material is the core, bit for bit, whatever their roughness") {
    const double mu = GENERATE(1.0, 0.3, 0.01);
    mat::gltf core;
    core.in.metallic = 0.5, core.in.roughness = 0.4, core.in.baseColor = {0.9, 0.5, 0.2};
    mat::gltf off = core;
    off.in.sheenRoughness = 0.7, off.in.clearcoatRoughness = 0.3;  // sheenColor 0, clearcoat 0: off
    const auto a = mat::albedo(off, mu, mat::compensation_kind::none), b = mat::albedo_of(core, mu);
    for (std::size_t i = 0; i < mat::gltf::lobe_count; ++i) {
        CHECK(a.lobes[i].value == b.lobes[i].value);
        CHECK(a.lobes[i].abs_error == b.lobes[i].abs_error);
    }
    CHECK(a.lobes[3].value == mat::rgb{0, 0, 0});
    CHECK(a.lobes[4].value == mat::rgb{0, 0, 0});
    const normzoo::vec3<double> l = normzoo::direction<double>(0.4, 1.0), v = normzoo::direction<double>(0.9, 0.0);
    CHECK(off.f(l, v) == core.f(l, v));
}

TEST_CASE("sheen: the scaled material against a plain quadrature over L, per channel and lobe, within the bound") {
    const auto [metallic, roughness, mu, sheen_r, base, sheen] =
        GENERATE(normzoo_test::thinned_under_sanitizers(2, table<double, double, double, double, mat::rgb, mat::rgb>({
            {0, 0.5, 0.5, 0.5, mat::grey(1), mat::grey(1)},
            {0.5, 0.75, 0.125, 0.3, mat::rgb{0.9, 0.5, 0.2}, mat::rgb{0.2, 0.8, 0.4}},
            {0, 1, 0.02, 1, mat::grey(1), mat::grey(1)},  // E_v near E's maximum: its support is two-sided
        })));
    const mat::gltf m = sheened(metallic, roughness, base, sheen, sheen_r);
    const auto a = mat::albedo(m, mu, mat::compensation_kind::none);
    std::map<double, double> e_cache;
    for (std::size_t ch = 0; ch < 3; ++ch) {
        const double plain = double(plain_sheened_albedo(m, ch, mu, e_cache));
        CAPTURE(metallic, roughness, mu, sheen_r, ch, a.whole.value[ch], plain, a.whole.abs_error[ch], a.whole.value[ch] - plain);
        CHECK(std::abs(a.whole.value[ch] - plain) <= a.whole.abs_error[ch] + 1e-12);
        CHECK(a.whole.abs_error[ch] <= 1e-10);
        const auto e_v = mat::sheen_albedo(mu, sheen_r * sheen_r, 1e-13);
        CHECK(std::abs(a.lobes[3].value[ch] - sheen[ch] * e_v.value) <= a.lobes[3].abs_error[ch] + sheen[ch] * e_v.abs_error);
        std::ostringstream out;  // the figures docs/materials.md quotes
        out << std::setprecision(3) << "mu " << mu << " ch " << ch << ": bound " << a.whole.abs_error[ch] << ", error "
            << std::abs(a.whole.value[ch] - plain) << ", albedo " << std::setprecision(12) << a.whole.value[ch];
        WARN(out.str());
    }
}

// The coat over a black base (baseColor 0, metallic 0, specular 0: every core lobe weighted 0) is
// its own layer: fc(mu) E_coat(mu), fc = 0.04 + 0.96 (1 - mu)^5, E_coat the composition
// ggx/G/one's albedo at clearcoatRoughness^2. Over a white metal: (1 - fc) E_metal + fc E_coat.
TEST_CASE("clearcoat: the coat over a black base is fc(N.V) times the coat's composition, over a white metal the mix") {
    const auto [mu, cr, form] = GENERATE(table<double, double, mat::smith_form>({
        {1, 0.5, mat::smith_form::separable}, {0.3, 0.1, mat::smith_form::height_correlated}, {0.01, 1, mat::smith_form::separable}}));
    const char* id = form == mat::smith_form::separable ? "ggx/smith-separable/one" : "ggx/smith-height-correlated/one";
    const double fc = 0.04 + 0.96 * std::pow(1 - mu, 5);
    const auto coat = mf::directional_albedo(mf::composition::parse(id), mu, cr * cr);
    mat::gltf black;
    black.in.baseColor = mat::grey(0), black.in.metallic = 0, black.in.specular = 0, black.in.masking = form;
    black.in.clearcoat = 1, black.in.clearcoatRoughness = cr;
    const auto a = mat::albedo(black, mu, mat::compensation_kind::none);
    CAPTURE(mu, cr, a.whole.value[0], fc * coat.value, a.whole.abs_error[0], coat.abs_error);
    CHECK(std::abs(a.whole.value[0] - fc * coat.value) <= a.whole.abs_error[0] + coat.abs_error + 1e-15);
    CHECK(a.lobes[4].value[0] == a.whole.value[0]);
    mat::gltf metal = black;
    metal.in.baseColor = mat::grey(1), metal.in.metallic = 1, metal.in.roughness = 0.6;
    const auto w = mat::albedo(metal, mu, mat::compensation_kind::none);
    const auto e_metal = mf::directional_albedo(mf::composition::parse(id), mu, 0.36);
    const double expected = (1 - fc) * e_metal.value + fc * coat.value;
    CHECK(std::abs(w.whole.value[1] - expected) <= w.whole.abs_error[1] + e_metal.abs_error + coat.abs_error + 1e-15);
    CHECK(w.whole.abs_error[1] <= 1e-10);
}

TEST_CASE("sheen and clearcoat: refused inputs, and a compensation with the sheen") {
    mat::gltf m;
    m.in.sheenColor = mat::grey(0.5);
    CHECK(mat::gltf::input_error(m.in) != nullptr);  // sheenRoughness 0 with a sheen
    m.in.sheenRoughness = 0.05;
    CHECK(mat::gltf::input_error(m.in) == nullptr);
    m.in.clearcoat = 0.5;
    CHECK(mat::gltf::input_error(m.in) != nullptr);  // a mirror coat
    m.in.clearcoatRoughness = 0.2;
    CHECK(mat::gltf::input_error(m.in) == nullptr);
    CHECK_THROWS_AS(mat::albedo(m, 0.5, mat::compensation_kind::turquin), std::invalid_argument);
    // set() by declaration order: sheenColor is parameter 7, clearcoatRoughness 10
    mat::gltf s;
    s.set(7, 1, 0.25), s.set(8, 0, 0.5), s.set(9, 0, 0.75), s.set(10, 0, 0.125);
    CHECK(s.in.sheenColor == mat::rgb{0, 0.25, 0});
    CHECK((s.in.sheenRoughness == 0.5 && s.in.clearcoat == 0.75 && s.in.clearcoatRoughness == 0.125));
}
