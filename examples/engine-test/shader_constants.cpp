// How an engine checks its shaders' BRDF constants in its own Catch2 tests: the constant as the
// shader computes it, the form it multiplies, the exponent range the engine uses. normzoo
// returns the verdict with its numbers (largest relative error and where, largest albedo).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
#include <normzoo/brdf/blinn_phong.hpp>
#include <normzoo/brdf/microfacet.hpp>
#include <normzoo/check.hpp>

#include <cmath>

namespace {
const double pi = 3.14159265358979323846;
const std::vector<double> angles = {0, 30, 60, 80, 89};  // a few incident angles keep the test fast
}  // namespace

TEST_CASE("our modified Blinn-Phong constant is the exact one and conserves energy") {
    auto shader = [](double n) { return (n + 2) * (n + 4) / (8 * pi * (std::exp2(-n / 2) + n)); };
    const auto v = normzoo::check_shader_normalization<normzoo::brdf::blinn_phong_modified>(shader, 1, 2048, 1, angles);
    INFO(v.describe());
    CHECK(std::abs(v.max_rel_error) < 1e-12);
    CHECK(v.conserving);
}

TEST_CASE("the (n+8)/(8 pi) shortcut is caught: 7.5 % off and gaining energy") {
    auto shader = [](double n) { return (n + 8) / (8 * pi); };
    const auto v = normzoo::check_shader_normalization<normzoo::brdf::blinn_phong_modified>(shader, 1, 2048, 1, angles);
    INFO(v.describe());
    CHECK(v.max_rel_error > 0.07);
    CHECK_FALSE(v.conserving);
}

TEST_CASE("the microfacet constant (n+2)/(8 pi) with Schlick at 0.04 conserves energy") {
    auto shader = [](double n) { return (n + 2) / (8 * pi); };
    const auto v = normzoo::check_shader_normalization<normzoo::brdf::microfacet_blinn>(shader, 2, 2048, 0.04, angles);
    INFO(v.describe());
    CHECK(std::abs(v.max_rel_error) < 1e-12);
    CHECK(v.conserving);
}

TEST_CASE("a baked albedo table entry is checked against the exact albedo and its bound") {
    // What an engine's lookup table holds for blinn-phong-modified at n = 64 and 60 degrees, in
    // float: right to float precision, and 1e-4 off where a baker cut its sample count.
    const auto exact = normzoo::albedo<normzoo::brdf::blinn_phong_modified>(60, 64, 1, {});
    const float baked = static_cast<float>(exact.value);
    const auto good = normzoo::check_value(baked, exact, 1e-7);
    INFO(good.describe());
    CHECK(good.within());
    const auto bad = normzoo::check_value(baked + 1e-4, exact, 1e-7);
    INFO(bad.describe());
    CHECK_FALSE(bad.within());
}
