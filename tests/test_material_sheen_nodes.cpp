// A sheen over a film or anisotropy (material/sheen_nodes.hpp, docs/materials.md, "The sheen's
// albedo scaling, over a film or anisotropy"): the lobes' integrand over L's azimuth at N.L = y
// against plain Gauss-Kronrod in long double over f, and the whole scaled material, at a film or
// an anisotropy too small to move it, against the core's route with D's azimuthal integral in
// closed form (material/sheen_albedo.hpp).
#include <catch2/catch.hpp>

#include "sanitized.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <algorithm>
#include <cmath>
#include <vector>
#include <cstddef>
#include <string>
#include <tuple>

#include <normzoo/material/coat_albedo.hpp>
#include <normzoo/material/sheen_albedo.hpp>
#include <normzoo/material/sheen_nodes.hpp>

namespace {

namespace mat = normzoo::material;

mat::gltf sheened(double roughness, double film, double strength) {
    mat::gltf m;
    m.in.baseColor = {0.8, 0.4, 0.2}, m.in.metallic = 0.3, m.in.roughness = roughness;
    m.in.sheenColor = {0.9, 0.6, 0.3}, m.in.sheenRoughness = 0.5;
    m.in.iridescence = film, m.in.iridescenceThickness = 400, m.in.iridescenceIor = 1.6;
    m.in.anisotropyStrength = strength, m.in.anisotropyRotation = 0.7;
    return m;
}

// Lobe i's channel k at N.L = y, integrated over L's azimuth by Gauss-Kronrod in long double on f
// without the sheen, the film's kinks not given (tolerance 1e-13: a kink costs it panels only).
long double plain_at(const mat::gltf& m, std::size_t i, std::size_t k, double mu, double y) {
    mat::gltf bare = m;
    bare.in.sheenColor = mat::grey(0);
    const double sv = std::sqrt((1 - mu) * (1 + mu)), sy = std::sqrt((1 - y) * (1 + y));
    const normzoo::vec3<double> v(sv, 0, mu);
    auto f = [&](long double p) {
        const normzoo::vec3<double> l(sy * std::cos(double(p)), sy * std::sin(double(p)), y);
        return (long double)bare.f_lobes(l, v)[i][k] * y;
    };
    const long double pi = boost::math::constants::pi<long double>();
    return boost::math::quadrature::gauss_kronrod<long double, 61>::integrate(f, -pi, pi, 20, 1e-13L);
}

}  // namespace

TEST_CASE("sheen over a film or anisotropy: the lobes at N.L = y over L's azimuth against plain Gauss-Kronrod",
          "[material][sheen-nodes]") {
    const auto [roughness, film, strength, mu, y] = GENERATE(table<double, double, double, double, double>(
        {{0.5, 1, 0, 0.5, 0.45}, {0.7, 0, 0.8, 0.3, 0.6}, {0.6, 0.8, 0.5, 0.8, 0.8}, {1, 1, 1, 0.2, 0.05}}));
    CAPTURE(roughness, film, strength, mu, y);
    const mat::gltf m = sheened(roughness, film, strength);
    const auto g = mat::detail::core_lobes_at(m, mu, y, y - mu, m.weight_kinks(), 1e-12, 400);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            const long double ref = plain_at(m, i, k, mu, y);
            CAPTURE(i, k, g.value[3 * i + k], double(ref));
            CHECK(std::abs((long double)g.value[3 * i + k] - ref) <= g.abs_error[3 * i + k] + 1e-13L);
        }
}

TEST_CASE("sheen over a film or anisotropy: at a film or an anisotropy too small to move it, the core's sheen route",
          "[material][sheen-nodes]") {
    // iridescence 1e-13 moves the weights by about that; anisotropyStrength 1e-7 moves alpha_t by 1e-14
    const auto [roughness, mu, film] = GENERATE(normzoo_test::thinned_under_sanitizers(
        3, table<double, double, bool>({{0.3, 0.3, true}, {0.7, 0.8, false}, {0.5, 0.6, true}})));
    CAPTURE(roughness, mu, film);
    const mat::gltf core = sheened(roughness, 0, 0), m = sheened(roughness, film ? 1e-13 : 0, film ? 0 : 1e-7);
    REQUIRE(m.by_nodes());
    // the command's route for a film; the anisotropic one, which the command refuses, directly
    const auto a = film ? mat::coated_albedo_by_nodes(m, mu) : mat::sheen_albedo_by_nodes(m, mu), b = mat::gltf_albedo(core, mu);
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            CAPTURE(i, k, a.lobes[i].value[k], b.lobes[i].value[k]);
            CHECK(std::abs(a.lobes[i].value[k] - b.lobes[i].value[k]) <= a.lobes[i].abs_error[k] + b.lobes[i].abs_error[k] + 1e-12);
            CHECK(a.lobes[i].abs_error[k] <= 1e-10);
        }
    // the sheen takes light from the lobes below it: the scaled lobes under the bare ones
    mat::gltf bare = m;
    bare.in.sheenColor = mat::grey(0);
    const auto unscaled = mat::albedo_about_v(bare, mu);
    for (std::size_t i = 0; i < 3; ++i) CHECK(a.lobes[i].value[0] < unscaled.lobes[i].value[0]);
}

// At V = N the lobes are symmetric about N, so a lobe's loss to the sheen is a 1D integral over
// N.L = y: 2 pi integral_0^1 f(y) y max(0, E(y) - E_v) dy, here by Boost's adaptive Gauss-Kronrod
// 61 on f from vectors, in ln y below 1/2 and ln(1 - y) above (where E - E_v goes like y^-0.93
// and (1 - y)^c: smooth in those), the film's kinks in V.H = sqrt((1 + y) / 2) as breakpoints. E is
// from the same curve: what is checked is the integral over L. A real film (400 nm) under a narrow
// lobe (roughness 0.01). The azimuthal route the film took before missed the diffuse's loss here
// by 2.3e-11 against a bound of 3.7e-12.
TEST_CASE("sheen over a film at normal incidence: each lobe against a 1D integral over N.L", "[material][sheen-nodes]") {
    mat::gltf m;
    m.in.baseColor = {0.8, 0.4, 0.2}, m.in.metallic = 0.5, m.in.roughness = 0.01;
    m.in.sheenColor = mat::grey(1), m.in.sheenRoughness = 0.5, m.in.iridescence = 1, m.in.iridescenceThickness = 400;
    mat::gltf bare = m;
    bare.in.sheenColor = mat::grey(0);
    const auto a = mat::coated_albedo_by_nodes(m, 1.0), unscaled = mat::albedo_about_v(bare, 1.0);
    const auto curve = mat::sheen_curve_for(0.25, mat::gltf::sheen_curve_tolerance);
    const auto e_v = (*curve)(1.0);
    std::vector<double> in_y, in_z;  // ln y on [1e-12, 1/2], ln(1 - y) on [2^-52, 1/2]
    for (int k = 0; k <= 4; ++k) in_y.push_back(std::log(1e-12) + (std::log(0.5) - std::log(1e-12)) * k / 4);
    for (int k = 0; k <= 8; ++k) in_z.push_back(std::log(0x1p-52) + (std::log(0.5) - std::log(0x1p-52)) * k / 8);
    for (double vh : bare.weight_kinks()) {
        const double y = 2 * vh * vh - 1;
        if (y > 1e-12 && y < 0.5) in_y.push_back(std::log(y));
        if (y >= 0.5 && y < 1) in_z.push_back(std::log1p(-y));
    }
    std::sort(in_y.begin(), in_y.end()), std::sort(in_z.begin(), in_z.end());
    using gk = boost::math::quadrature::gauss_kronrod<double, 61>;
    const normzoo::vec3<double> v(0, 0, 1);
    for (std::size_t i = 0; i < 3; ++i) {
        auto at = [&](double y, double dy) {  // the integrand times dy/ds
            const auto lobes = bare.f_lobes(normzoo::vec3<double>(std::sqrt((1 - y) * (1 + y)), 0, y), v);
            return 2 * M_PI * lobes[i][0] * y * std::max(0.0, (*curve)(y).value - e_v.value) * dy;
        };
        double loss = 0, loss_error = 0, err = 0;
        for (std::size_t p = 0; p + 1 < in_y.size(); ++p, loss_error += err)
            loss += gk::integrate([&](double s) { return at(std::exp(s), std::exp(s)); }, in_y[p], in_y[p + 1], 10, 1e-14, &err);
        for (std::size_t p = 0; p + 1 < in_z.size(); ++p, loss_error += err)
            loss += gk::integrate([&](double s) { return at(1 - std::exp(s), std::exp(s)); }, in_z[p], in_z[p + 1], 10, 1e-14, &err);
        const double expected = (1 - e_v.value) * unscaled.lobes[i].value[0] - loss;
        CAPTURE(i, a.lobes[i].value[0], expected, a.lobes[i].abs_error[0], loss_error, a.lobes[i].value[0] - expected);
        CHECK(std::abs(a.lobes[i].value[0] - expected) <=
              a.lobes[i].abs_error[0] + unscaled.lobes[i].abs_error[0] + e_v.abs_error + loss_error);
        CHECK(loss_error < 1e-14);
    }
}

TEST_CASE("sheen with transmission is refused naming the sheen, with anisotropy naming anisotropyStrength", "[material][sheen-nodes]") {
    mat::gltf m = sheened(0.5, 1, 0);
    CHECK(mat::gltf::input_error(m.in) == nullptr);
    m.in.transmission = 0.5;
    const char* why = mat::gltf::input_error(m.in);
    REQUIRE(why != nullptr);
    CHECK(std::string(why).find("sheenColor") != std::string::npos);
    const mat::gltf a = sheened(0.5, 0, 0.5);
    REQUIRE(mat::gltf::input_error(a.in) != nullptr);
    CHECK(std::string(mat::gltf::input_error(a.in)).find("anisotropyStrength") != std::string::npos);
}
