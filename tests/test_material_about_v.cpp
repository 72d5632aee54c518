// The albedo with the half vector about V (material/about_v.hpp, docs/materials.md, "Weights of
// V.H: the half vector about V"): its kernels against the composition's 1D albedo and Lambert's 1,
// and the film materials (glTF's, OpenPBR's specular and metal) and an anisotropic lobe against
// GGX's map or the anisotropic lobe's, a different parametrization of the same integral
// (material/albedo.hpp, albedo_by_nodes).
#include <catch2/catch.hpp>

#include "sanitized.hpp"

#include <cmath>
#include <cstddef>
#include <tuple>

#include <normzoo/material/about_v.hpp>
#include <normzoo/material/coat_albedo.hpp>
#include <normzoo/material/gltf.hpp>
#include <normzoo/material/openpbr_albedo.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/composition.hpp>

namespace {

namespace mat = normzoo::material;
namespace mf = normzoo::microfacet;
using two = normzoo::quadrature::channels<double, 2>;

// The two kernels alone, F = 1: the specular lobe's albedo and Lambert's.
normzoo::quadrature::estimate<two> kernels(const mat::specular_brdf& lobe, double mu) {
    return mat::about_v_integral(lobe, mu, {}, 1e-10, 400, [](const mat::about_v_node& x) {
        normzoo::quadrature::estimate<two> e{two{}, two{}, x.evaluations};
        e.value[0] = x.specular, e.abs_error[0] = x.specular_error;
        e.value[1] = x.diffuse, e.abs_error[1] = x.diffuse_error;
        return e;
    });
}

}  // namespace

TEST_CASE("about V: the specular kernel is the composition's albedo, Lambert's integrates to 1", "[material][about-v]") {
    using std::get;
    const auto [masking, mu, roughness] = GENERATE(normzoo_test::thinned_under_sanitizers(
        3, table<int, double, double>({{0, 1e-6, 1e-4}, {0, 0.1, 0.01}, {0, 0.5, 0.5}, {0, 1, 0.01}, {0, 0.9, 1},
                                       {1, 1e-6, 0.01}, {1, 0.1, 1}, {1, 0.5, 1e-4}, {1, 1, 0.1}, {1, 0.3, 0.3},
                                       {0, 1e-8, 1e-4}, {1, 1e-8, 0.003}})));
    CAPTURE(masking, mu, roughness);
    const mat::specular_brdf lobe{roughness * roughness, masking == 0 ? mat::smith_form::separable : mat::smith_form::height_correlated};
    const auto e = kernels(lobe, mu);
    const auto c = mf::composition::parse(masking == 0 ? "ggx/smith-separable/schlick" : "ggx/smith-height-correlated/schlick");
    const auto ref = mf::directional_albedo(c, mu, lobe.alpha, 1.0, {});
    CHECK(std::abs(e.value[0] - ref.value) <= e.abs_error[0] + ref.abs_error);
    CHECK(e.abs_error[0] < 1e-10);
    CHECK(std::abs(e.value[1] - 1) <= e.abs_error[1] + 4e-16);
}

TEST_CASE("about V: a glTF film's lobes as in GGX's map, per channel", "[material][about-v]") {
    // mu = 1 and roughness 1 are the map route's cheap points; one grazing, one narrow
    const auto [metallic, roughness, mu, thickness] = GENERATE(normzoo_test::thinned_under_sanitizers(
        2, table<double, double, double, double>({{0.5, 0.5, 1, 400}, {0, 1, 0.5, 250}, {1, 0.05, 1, 700}, {0.3, 1, 0.05, 400}})));
    CAPTURE(metallic, roughness, mu, thickness);
    mat::gltf m;
    m.in.baseColor = {0.8, 0.4, 0.2}, m.in.metallic = metallic, m.in.roughness = roughness;
    m.in.iridescence = 1, m.in.iridescenceThickness = thickness, m.in.transmission = 0.3;
    const auto a = mat::albedo_about_v(m, mu), b = mat::albedo_by_nodes(m, mu);
    for (std::size_t i = 0; i < mat::gltf::lobe_count; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            CAPTURE(i, k, a.lobes[i].value[k], b.lobes[i].value[k]);
            CHECK(std::abs(a.lobes[i].value[k] - b.lobes[i].value[k]) <= a.lobes[i].abs_error[k] + b.lobes[i].abs_error[k]);
            CHECK(a.lobes[i].abs_error[k] < 1e-10);
        }
    // the route a film takes from the material's albedo
    const auto c = mat::coated_albedo_by_nodes(m, mu);
    CHECK(c.whole.value == a.whole.value);
}

TEST_CASE("about V: an anisotropic lobe as in its own map, per lobe and channel", "[material][about-v]") {
    const auto [roughness, strength, rotation, mu] = GENERATE(normzoo_test::thinned_under_sanitizers(
        2, table<double, double, double, double>({{0.5, 0.5, 0.7, 0.5}, {1, 1, 2.2, 0.1}, {0.3, 0.8, -0.4, 1}})));
    CAPTURE(roughness, strength, rotation, mu);
    mat::gltf m;
    m.in.baseColor = {0.8, 0.4, 0.2}, m.in.metallic = 0.5, m.in.roughness = roughness;
    m.in.anisotropyStrength = strength, m.in.anisotropyRotation = rotation;
    const auto a = mat::albedo_about_v(m, mu), b = mat::albedo_by_nodes(m, mu);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            CAPTURE(i, k, a.lobes[i].value[k], b.lobes[i].value[k]);
            CHECK(std::abs(a.lobes[i].value[k] - b.lobes[i].value[k]) <= a.lobes[i].abs_error[k] + b.lobes[i].abs_error[k]);
            CHECK(a.lobes[i].abs_error[k] < 1e-10);
        }
}

TEST_CASE("about V: OpenPBR's film specular and metal as in GGX's map", "[material][about-v]") {
    const auto [roughness, mu] = GENERATE(normzoo_test::thinned_under_sanitizers(2, table<double, double>({{0.3, 1}, {1, 0.5}, {0.1, 1}})));
    CAPTURE(roughness, mu);
    mat::openpbr m;
    m.in.specular_roughness = roughness, m.in.thin_film_weight = 1, m.in.thin_film_thickness = 0.5, m.in.thin_film_ior = 1.4;
    const auto kinks = m.film_kinks();
    for (const bool metal : {false, true}) {
        auto f = [&](double vh) { return metal ? m.metal_fresnel(vh) : m.specular_fresnel(vh); };
        auto r = [&](double vh) { return metal ? m.metal_rounding(vh) : m.specular_rounding(vh); };
        std::size_t n = 0;
        const auto a = mat::detail::ggx_albedo_rgb(m.alpha(), mu, f, kinks, 1e-11, 400, n, r, true);
        const auto b = mat::detail::ggx_albedo_rgb(m.alpha(), mu, f, kinks, 1e-11, 400, n, r, false);
        for (std::size_t k = 0; k < 3; ++k) {
            CAPTURE(metal, k, a.value[k], b.value[k]);
            CHECK(std::abs(a.value[k] - b.value[k]) <= a.abs_error[k] + b.abs_error[k]);
        }
    }
}
