// A BRDF given as code (code/): its albedo found without knowing its lobe, against closed forms
// and references computed here independently; what it returns that is not a reflectance; RGB;
// reciprocity, float against double, normalization; and, in miniature, the audit of the
// black-box integrator against the built-in forms (docs/brdf-code.md#the-audit).
#include <catch2/catch.hpp>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <limits>

#include <normzoo/albedo.hpp>
#include <normzoo/code/code_albedo.hpp>
#include <normzoo/code/code_checks.hpp>
#include <normzoo/real.hpp>
#include <normzoo/registry.hpp>

using namespace normzoo;

namespace {

const double pi_d = std::acos(-1.0);

// A built-in form as an opaque callable: only f(L, V), in whatever scalar it is called with.
template <class Form>
auto opaque(const brdf::params<double>& p) {
    return [p](const auto& l, const auto& v, const auto& /*n*/, const auto& /*x*/, const auto& /*y*/) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        return Form::f(l, v, brdf::params<T>{T(p.n), T(p.specular), T(p.roughness)});
    };
}

// The modified Phong lobe written as a shader writes it: (n+2)/(2 pi) max(R.V, 0)^n.
struct shader_phong {
    double n;
    template <class V>
    auto operator()(const V& l, const V& v, const V& nrm, const V&, const V&) const {
        using T = typename V::Scalar;
        const V r = T(2) * nrm.dot(l) * nrm - l;
        return T((n + 2) / (2 * pi_d)) * std::pow(std::max(r.dot(v), T(0)), T(n));
    }
};

}  // namespace

TEST_CASE("a clamped cosine lobe: the albedo of max(R.V, 0) against its closed form") {
    // The integral of max(R.V, 0) max(N.V, 0) over the sphere, R at angle g from N, is
    // 2 (sin g + (pi - g) cos g) / 3; with (n+2)/(2 pi) = 3/(2 pi) at n = 1 the albedo is
    // (sin g + (pi - g) cos g) / pi. The lobe's kink at R.V = 0 crosses the hemisphere.
    const double t = GENERATE(0.0, 20.0, 45.0, 60.0, 80.0);
    const double g = t * pi_d / 180;
    const double truth = (std::sin(g) + (pi_d - g) * std::cos(g)) / pi_d;
    const auto a = code::code_albedo(shader_phong{1}, degrees_angle<quad>(t));
    CAPTURE(t, a.largest().value, truth, a.largest().abs_error, a.evaluations);
    CHECK(std::abs(a.largest().value - truth) <= a.largest().abs_error);
    CHECK(a.largest().abs_error <= 1e-10);
    CHECK(!a.found.non_finite);
    CHECK(!a.found.negative);
}

TEST_CASE("Lambert as code: albedo 1 at every angle, in one channel or three") {
    const double t = GENERATE(0.0, 45.0, 89.0, 89.99);
    auto grey = [](const auto& l, const auto&, const auto&, const auto&, const auto&) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        return T(1 / pi_d);
    };
    const auto a = code::code_albedo(grey, degrees_angle<quad>(t));
    CHECK(std::abs(a.largest().value - 1) <= a.largest().abs_error);
    CHECK(!a.triple);
    auto coloured = [](const auto& l, const auto&, const auto&, const auto&, const auto&) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        return std::array<T, 3>{T(0.2 / pi_d), T(0.5 / pi_d), T(1 / pi_d)};
    };
    const auto c = code::code_albedo(coloured, degrees_angle<quad>(t));
    CHECK(c.triple);
    const double expected[3] = {0.2, 0.5, 1};
    for (int k = 0; k < 3; ++k) CHECK(std::abs(c.channel[k].value - expected[k]) <= c.channel[k].abs_error + 1e-15);
    CHECK(c.largest().value == c.channel[2].value);
}

TEST_CASE("Ashikhmin-Shirley's kink at N.V = N.L: built-in and code against a reference in (N.V, phi)") {
    // The reference integrates in mu = N.V and phi, split at mu = N.L where max(N.L, N.V) has its
    // kink, by Boost's Gauss-Kronrod 61: smooth pieces, so its estimate can be trusted.
    const double t = GENERATE(30.0, 60.0);
    const auto p = brdf::params_at<brdf::ashikhmin_shirley>(1);
    const degrees_angle<quad> angle(t);
    const vec3<double> l(static_cast<double>(angle.sin_t), 0, static_cast<double>(angle.cos_t));
    using boost::math::quadrature::gauss_kronrod;
    auto over_phi = [&](double mu) {
        auto g = [&](double phi) {
            const double s = std::sqrt(1 - mu * mu);
            return brdf::ashikhmin_shirley::f(l, vec3<double>(s * std::cos(phi), s * std::sin(phi), mu), p) * mu;
        };
        return 2 * gauss_kronrod<double, 61>::integrate(g, 0.0, pi_d, 15, 1e-14);
    };
    const double reference = gauss_kronrod<double, 61>::integrate(over_phi, 0.0, l.z(), 15, 1e-14) +
                             gauss_kronrod<double, 61>::integrate(over_phi, l.z(), 1.0, 15, 1e-14);
    const auto built_in = albedo<brdf::ashikhmin_shirley>(t, p.n, p.specular);
    const auto code = code::code_albedo(opaque<brdf::ashikhmin_shirley>(p), angle);
    CAPTURE(t, reference, built_in.value, built_in.abs_error, code.largest().value, code.largest().abs_error);
    CHECK(std::abs(built_in.value - reference) <= built_in.abs_error + 1e-14);
    CHECK(std::abs(code.largest().value - reference) <= code.largest().abs_error + 1e-14);
}

TEST_CASE("what code returns that is not a reflectance is found, with where") {
    // NaN beyond 60 degrees from N, the lobe of a Phong that forgot its clamp negative
    auto nan_at_grazing = [](const auto& l, const auto& v, const auto&, const auto&, const auto&) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        return v.z() < T(0.5) ? std::numeric_limits<T>::quiet_NaN() : T(1 / pi_d);
    };
    const auto a = code::code_albedo(nan_at_grazing, degrees_angle<quad>(30.0));
    REQUIRE(a.found.non_finite);
    CHECK(a.found.non_finite.first->z() < 0.5);
    CHECK(!a.finite());
    CHECK(!a.usable());  // NaN on a region: no albedo
    CHECK(a.found.non_finite_spread);
    auto unclamped = [](const auto& l, const auto& v, const auto& n, const auto&, const auto&) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        const auto r = T(2) * n.dot(l) * n - l;
        return T(3 / (2 * pi_d)) * r.dot(v);
    };
    const auto b = code::code_albedo(unclamped, degrees_angle<quad>(30.0));
    REQUIRE(b.found.negative);
    const vec3<double> r(-0.5, 0, std::sqrt(0.75));
    CHECK(r.dot(*b.found.negative.first) < 0);
}

TEST_CASE("reciprocity: Blinn-Phong over N.L is not reciprocal, the modified form is") {
    const auto p = brdf::params_at<brdf::blinn_phong>(16);
    CHECK(!code::check_reciprocity(opaque<brdf::blinn_phong>(p)).reciprocal());
    const auto q = code::check_reciprocity(opaque<brdf::blinn_phong_modified>(p));
    CAPTURE(q.worst.relative);
    CHECK(q.reciprocal());
}

TEST_CASE("float against double: pow(R.V, n) breaks down in float at high exponents") {
    const vec3<double> l(0, 0, 1);
    const auto low = code::compare_float(shader_phong{10}, l, l);
    const auto high = code::compare_float(shader_phong{1e5}, l, l);
    CAPTURE(low.worst.relative, high.worst.relative);
    CHECK(!low.breaks_down());
    CHECK(high.breaks_down());
}

TEST_CASE("normalization: the modified Phong's albedo at normal incidence does not move with n, Phong's does") {
    std::vector<quadrature::estimate<double>> modified, plain;
    for (double n : {1.0, 10.0, 100.0}) {
        modified.push_back(code::code_albedo(shader_phong{n}, degrees_angle<quad>(0.0)).largest());
        plain.push_back(code::code_albedo(opaque<brdf::phong>(brdf::params_at<brdf::phong>(n)), degrees_angle<quad>(0.0)).largest());
    }
    CHECK(code::check_normalization(modified).normalized());
    const auto p = code::check_normalization(plain);
    CHECK(!p.normalized());
    CHECK(p.lowest == 0);  // (n+1)/(n+2) grows with n
}

TEST_CASE("the black box against every built-in form, in miniature") {
    // The audit (docs/brdf-code.md#the-audit) takes the whole energy grid; here one value of each
    // form's parameter and three angles.
    for_each_brdf([](auto form) {
        using Form = decltype(form);
        double x = 0;
        if constexpr (brdf::has_swept_parameter<Form>()) x = brdf::swept_parameter<Form>().sweep.values[1];
        const auto p = brdf::params_at<Form>(x);
        for (double t : {0.0, 45.0, 85.0}) {
            const auto built_in = albedo<Form>(t, p.n, p.specular, {}, p.roughness);
            const auto code = code::code_albedo(opaque<Form>(p), degrees_angle<quad>(t));
            CAPTURE(Form::id, x, t, built_in.value, built_in.abs_error, code.largest().value, code.largest().abs_error);
            CHECK(std::abs(code.largest().value - built_in.value) <= code.largest().abs_error + built_in.abs_error);
        }
    });
}

TEST_CASE("isolated non-finite directions: the albedo over the others, flagged, and none where a region is not finite") {
    // Lambert, NaN at V = N only (a normalize of V's projection on the surface), or on the plane
    // y = 0 through N and L (a curve of directions): sets of measure zero, the albedo 1 without them
    auto at_normal = [](const auto& l, const auto& v, const auto& n, const auto&, const auto&) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        const auto p = (v - n * n.dot(v)).eval();
        return T(1 / pi_d) + T(0) * (p / p.norm()).x();
    };
    auto on_plane = [](const auto& l, const auto& v, const auto&, const auto&, const auto&) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        return v.y() == T(0) ? std::numeric_limits<T>::quiet_NaN() : T(1 / pi_d);
    };
    const double t = GENERATE(0.0, 60.0);
    for (const auto& a : {code::code_albedo(at_normal, degrees_angle<quad>(t)), code::code_albedo(on_plane, degrees_angle<quad>(t)),
                          code::code_albedo<float>(at_normal, degrees_angle<quad>(t))}) {
        CAPTURE(t, a.largest().value, a.largest().abs_error, a.found.non_finite.count);
        REQUIRE(a.found.non_finite);  // found: N and the plane are where the search looks
        CHECK(!a.finite());
        CHECK(a.found.non_finite_isolated());
        CHECK(a.usable());
        CHECK(std::abs(a.largest().value - 1) <= a.largest().abs_error + 1e-15);
    }
    // NaN within 1e-4 rad of N is no set of measure zero: the probes at 1e-5 and 1e-7 rad find it
    auto cap = [](const auto& l, const auto& v, const auto&, const auto&, const auto&) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        return v.z() > T(std::cos(1e-4)) ? std::numeric_limits<T>::quiet_NaN() : T(1 / pi_d);
    };
    const auto c = code::code_albedo(cap, degrees_angle<quad>(t));
    CHECK(c.found.non_finite);
    CHECK(!c.usable());
}

TEST_CASE("the direction held: a lobe times a factor of N.V alone, with L held and with V held, against integrals in (mu, phi)") {
    // f = (n + 8)/(8 pi) (N.H)^n (1 + c (1 - N.V)): not reciprocal, as engines' multiple-scattering
    // factors of N.V are not. The references integrate over the free direction in (mu, phi) by
    // Boost's Gauss-Kronrod 61, on smooth integrands (N.H > 0 over the hemisphere: no kink).
    auto f = [](const auto& l, const auto& v, const auto& nrm, const auto&, const auto&) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        const auto h = (l + v).normalized();
        return T(28 / (8 * pi_d)) * std::pow(nrm.dot(h), T(20)) * (T(1) + T(0.5) * (T(1) - nrm.dot(v)));
    };
    const double t = GENERATE(30.0, 75.0);
    const degrees_angle<quad> angle(t);
    const vec3<double> held(static_cast<double>(angle.sin_t), 0, static_cast<double>(angle.cos_t)), n(0, 0, 1);
    using boost::math::quadrature::gauss_kronrod;
    auto over_hemisphere = [&](const auto& g) {
        auto over_phi = [&](double mu) {
            const double s = std::sqrt(1 - mu * mu);
            auto at = [&](double phi) { return g(vec3<double>(s * std::cos(phi), s * std::sin(phi), mu)) * mu; };
            return 2 * gauss_kronrod<double, 61>::integrate(at, 0.0, pi_d, 15, 1e-14);
        };
        return gauss_kronrod<double, 61>::integrate(over_phi, 0.0, 1.0, 15, 1e-14);
    };
    const double light_ref = over_hemisphere([&](const vec3<double>& v) { return f(held, v, n, n, n); });
    const double view_ref = over_hemisphere([&](const vec3<double>& l) { return f(l, held, n, n, n); });
    const auto light = code::code_albedo(f, angle, {}, code::fixed_direction::light);
    const auto view = code::code_albedo(f, angle, {}, code::fixed_direction::view);
    CAPTURE(t, light_ref, view_ref, light.largest().value, light.largest().abs_error, view.largest().value, view.largest().abs_error);
    CHECK(std::abs(light.largest().value - light_ref) <= light.largest().abs_error + 1e-12);
    CHECK(std::abs(view.largest().value - view_ref) <= view.largest().abs_error + 1e-12);
    CHECK(std::abs(light_ref - view_ref) > 1e-3);
    CHECK(!code::check_reciprocity(f).reciprocal());
    CHECK(code::check_reciprocity(f, 12, 24, 1.0).reciprocal());
}
