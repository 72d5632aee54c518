// Materials (docs/materials.md): the glTF material's albedo per lobe and whole against
// independent integrals and the compositions, its compensations, its verdicts.
#include <catch2/catch.hpp>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <thread>
#include <tuple>

#include <normzoo/material/compensation.hpp>
#include <normzoo/material/gltf.hpp>

namespace {

namespace mat = normzoo::material;
namespace mf = normzoo::microfacet;

mat::gltf material(double metallic, double roughness, mat::rgb base = mat::grey(1),
                   mat::smith_form form = mat::smith_form::separable) {
    mat::gltf m;
    m.in.metallic = metallic, m.in.roughness = roughness, m.in.baseColor = base, m.in.masking = form;
    return m;
}

const char* g_of(mat::smith_form form) {
    return form == mat::smith_form::separable ? "ggx/smith-separable/schlick" : "ggx/smith-height-correlated/schlick";
}

// Lobe i's albedo, channel ch, by plain adaptive Gauss-Kronrod over L in long double (theta_L,
// split at the mirror's polar angle; phi_L over [0, pi], twice), independent of the half-vector
// map. f is evaluated in double, so its noise (1e-16 relative) stops Gauss-Kronrod's estimate
// near 1e-14: asked 1e-13, its own error is taken to be below 1e-13 where the lobe is not narrow
// (roughness >= 0.5).
long double plain_albedo(const mat::gltf& m, std::size_t lobe, std::size_t ch, double mu) {
    using boost::math::quadrature::gauss_kronrod;
    const long double pi = boost::math::constants::pi<long double>();
    const double sv = std::sqrt((1 - mu) * (1 + mu));
    const normzoo::vec3<double> v(sv, 0, mu);
    const long double tv = std::acos((long double)mu);
    auto over_phi = [&](long double t) {
        auto g = [&](long double phi) {
            const normzoo::vec3<double> l = normzoo::direction<double>(double(t), double(phi));
            return (long double)m.f_lobes(l, v)[lobe][ch] * std::cos(t) * std::sin(t);
        };
        return 2 * gauss_kronrod<long double, 31>::integrate(g, 0.0L, pi, 8, 1e-13L);
    };
    long double sum = 0;
    const long double ends[] = {0, tv, pi / 2};
    for (int i = 0; i < 2; ++i)
        if (ends[i + 1] > ends[i]) sum += gauss_kronrod<long double, 31>::integrate(over_phi, ends[i], ends[i + 1], 8, 1e-13L);
    return sum;
}

}  // namespace

TEST_CASE("gltf: a white metal is the composition ggx/G/schlick at F0 = 1, to 1e-10 within both bounds") {
    const auto [roughness, mu] = GENERATE(table<double, double>({{0.01, 1}, {0.1, 0.5}, {0.3, 0.01}, {0.5, 1e-4},
                                                                 {0.7, 0.3}, {1, 1}, {1, 1e-3}, {0.2, 0.9}}));
    const auto form = GENERATE(mat::smith_form::separable, mat::smith_form::height_correlated);
    const auto a = mat::albedo_of(material(1, roughness, mat::grey(1), form), mu);
    normzoo::albedo_settings tight;
    tight.tolerance = 1e-12;
    const auto c = mf::directional_albedo(mf::composition::parse(g_of(form)), mu, roughness * roughness, 1, tight);
    CAPTURE(roughness, mu, a.whole.value[0], c.value, a.whole.abs_error[0], c.abs_error);
    for (std::size_t ch = 0; ch < 3; ++ch) {
        CHECK(std::abs(a.whole.value[ch] - c.value) <= a.whole.abs_error[ch] + c.abs_error);
        CHECK(a.whole.abs_error[ch] <= 1e-10);
    }
    CHECK(a.lobes[0].value == mat::rgb{0, 0, 0});  // no diffuse, no dielectric in a metal
    CHECK(a.lobes[1].value == mat::rgb{0, 0, 0});
}

TEST_CASE("gltf: the dielectric's specular lobe and a coloured metal's channels are the compositions at their F0") {
    const auto [roughness, mu] = GENERATE(table<double, double>({{0.05, 1}, {0.25, 0.2}, {0.6, 0.02}, {1, 0.7}}));
    normzoo::albedo_settings tight;
    tight.tolerance = 1e-12;
    const mf::composition c = mf::composition::parse(g_of(mat::smith_form::separable));
    const double alpha = roughness * roughness;
    // the dielectric: F0 = ((1.5 - 1) / 2.5)^2 = 0.04 as the specification computes it
    const auto d = mat::albedo_of(material(0, roughness, {0.9, 0.5, 0.1}), mu);
    const auto cd = mf::directional_albedo(c, mu, alpha, mf::f0_of_eta(1.5), tight);
    const mat::rgb base{0.9, 0.5, 0.1};
    const auto metal = mat::albedo_of(material(1, roughness, base), mu);
    for (std::size_t ch = 0; ch < 3; ++ch) {
        CAPTURE(roughness, mu, ch);
        CHECK(std::abs(d.lobes[1].value[ch] - cd.value) <= d.lobes[1].abs_error[ch] + cd.abs_error);
        const auto cm = mf::directional_albedo(c, mu, alpha, base[ch], tight);
        CHECK(std::abs(metal.lobes[2].value[ch] - cm.value) <= metal.lobes[2].abs_error[ch] + cm.abs_error);
    }
}

TEST_CASE("gltf: each lobe against plain Gauss-Kronrod over L in long double, the bound above the true error") {
    const auto [metallic, roughness, mu] =
        GENERATE(table<double, double, double>({{0, 1, 1}, {0, 0.7, 0.3}, {0.5, 0.5, 0.8}, {0.25, 1, 0.05}, {0, 0.02, 0.6}}));
    mat::gltf m = material(metallic, roughness, {0.8, 0.4, 0.2});
    m.in.specular = 0.75, m.in.specularColor = {1, 2, 0.5}, m.in.ior = 1.4;
    const bool by_nodes = GENERATE(false, true);  // both routes: the 1D integrals, node by node
    const auto a = by_nodes ? mat::albedo_by_nodes(m, mu) : mat::albedo_of(m, mu);
    double worst_ratio = 0;
    for (std::size_t lobe = 0; lobe < 3; ++lobe) {
        // the peaked lobes only where the plain integral resolves them
        if (lobe > 0 && roughness < 0.5) continue;
        for (std::size_t ch = 0; ch < 3; ++ch) {
            const long double plain = plain_albedo(m, lobe, ch, mu);
            const double error = double(std::abs((long double)a.lobes[lobe].value[ch] - plain));
            CAPTURE(by_nodes, metallic, roughness, mu, lobe, ch, a.lobes[lobe].value[ch], double(plain), a.lobes[lobe].abs_error[ch]);
            CHECK(error <= a.lobes[lobe].abs_error[ch] + 1e-13);  // the plain integral's own error: below 1e-13
            CHECK(a.lobes[lobe].abs_error[ch] <= 1e-10);
            if (a.lobes[lobe].abs_error[ch] > 0) worst_ratio = std::max(worst_ratio, error / a.lobes[lobe].abs_error[ch]);
        }
    }
    WARN("largest |albedo - plain| / bound: " << worst_ratio);
}

TEST_CASE("gltf: the albedo by the lobes' 1D integrals and node by node in GGX's map agree within both bounds") {
    const auto [metallic, roughness, mu] = GENERATE(table<double, double, double>(
        {{0, 0.01, 1}, {0, 0.1, 1e-4}, {0.5, 0.3, 0.1}, {1, 0.05, 0.02}, {0.3, 0.8, 1e-3}, {0.7, 1, 0.6}, {0, 1e-4, 0.5}}));
    const auto form = GENERATE(mat::smith_form::separable, mat::smith_form::height_correlated);
    mat::gltf m = material(metallic, roughness, {0.9, 0.5, 0.05}, form);
    m.in.specular = 0.5, m.in.specularColor = {0.5, 1, 3}, m.in.ior = 1.7;
    const auto a = mat::albedo_of(m, mu), b = mat::albedo_by_nodes(m, mu);
    for (std::size_t lobe = 0; lobe < 3; ++lobe)
        for (std::size_t ch = 0; ch < 3; ++ch) {
            CAPTURE(metallic, roughness, mu, lobe, ch, a.lobes[lobe].value[ch], b.lobes[lobe].value[ch]);
            CHECK(std::abs(a.lobes[lobe].value[ch] - b.lobes[lobe].value[ch]) <=
                  a.lobes[lobe].abs_error[ch] + b.lobes[lobe].abs_error[ch]);
        }
    for (std::size_t ch = 0; ch < 3; ++ch) {
        CHECK(a.whole.abs_error[ch] <= 1e-10);
        CHECK(b.whole.abs_error[ch] <= 1e-10);
    }
}

TEST_CASE("gltf: the diffuse lobe in closed form at F0 = 0 and specular = 0 (Lambert's 1 - metallic) x baseColor") {
    const double mu = GENERATE(1.0, 0.5, 1e-3);
    mat::gltf m = material(0.25, 0.3, {0.8, 0.4, 0.2});
    m.in.specular = 0;  // no dielectric layer: the base is weighted 1
    const auto a = mat::albedo_of(m, mu);
    for (std::size_t ch = 0; ch < 3; ++ch) {
        CAPTURE(mu, ch);
        CHECK(std::abs(a.lobes[0].value[ch] - 0.75 * m.in.baseColor[ch]) <= a.lobes[0].abs_error[ch]);
        CHECK(a.lobes[1].value[ch] == 0);
    }
}

TEST_CASE("gltf: a white metal with a compensation is 1 within its bound, and the dielectric conserves") {
    const auto kind = GENERATE(mat::compensation_kind::kulla_conty, mat::compensation_kind::turquin, mat::compensation_kind::fdez_aguera);
    const auto [roughness, mu] = GENERATE(table<double, double>({{0.3, 1}, {0.8, 0.1}, {1, 0.5}}));
    const auto white = material(1, roughness);
    const auto a = mat::compensated_albedo_of(white, mu, kind);
    CAPTURE(roughness, mu, a.whole.value[0], a.whole.abs_error[0]);
    CHECK(mat::claims_preservation(white, kind));
    CHECK(mat::preserving(a.whole));
    CHECK(a.whole.abs_error[0] <= 1e-10);
    const auto plastic = material(0, roughness, {0.8, 0.8, 0.8});
    CHECK_FALSE(mat::claims_preservation(plastic, kind));
    CHECK(mat::conserving(mat::compensated_albedo_of(plastic, mu, kind).whole));
    CHECK(mat::conserving(mat::albedo_of(plastic, mu).whole));
}

TEST_CASE("gltf: a compensated material's lobes are each channel's compensated composition, weighted") {
    // the material shares two albedos among its six channels (F0 E(F = 1) + (1 - F0) E(F = s));
    // the composition computes each channel's at its F0 by its own quadrature
    namespace mf = normzoo::microfacet;
    const auto kind = GENERATE(mat::compensation_kind::kulla_conty, mat::compensation_kind::turquin, mat::compensation_kind::fdez_aguera);
    const auto [roughness, mu] = GENERATE(table<double, double>({{0.6, 0.2}, {0.2, 0.9}}));
    const auto m = material(0.4, roughness, {0.9, 0.5, 0.2});
    const auto a = mat::compensated_albedo_of(m, mu, kind);
    const mf::composition c = mat::detail::gltf_specular_composition(m, kind);
    const mat::rgb f0_dielectric = m.weight_terms();
    for (std::size_t ch = 0; ch < 3; ++ch) {
        const double weights[2] = {(1 - m.in.metallic) * m.in.specular, m.in.metallic}, f0s[2] = {f0_dielectric[ch], m.in.baseColor[ch]};
        for (std::size_t j = 0; j < 2; ++j) {
            const auto own = mf::compensated_albedo(c, mu, m.alpha(), f0s[j]);
            const auto& lobe = a.lobes[1 + j];
            CAPTURE(int(kind), roughness, mu, ch, j, lobe.value[ch], weights[j] * own.value);
            CHECK(std::abs(lobe.value[ch] - weights[j] * own.value) <= lobe.abs_error[ch] + weights[j] * own.abs_error);
            CHECK(lobe.abs_error[ch] <= 1e-10);
        }
    }
}

TEST_CASE("gltf: single scattering and Kulla-Conty are reciprocal to rounding, and Turquin's factor is not") {
    const auto m = material(0.5, 0.4, {0.9, 0.6, 0.3});
    CHECK(mat::reciprocity_difference(m, mat::compensation_kind::none) < 1e-14);
    CHECK(mat::reciprocity_difference(m, mat::compensation_kind::kulla_conty) < 1e-14);
    CHECK(mat::reciprocity_difference(m, mat::compensation_kind::turquin) > 1e-3);
}

TEST_CASE("gltf/kulla-conty: a sweep's later points, reading the kept E_avg and loss, are a cold point's") {
    // each thread keeps the last eight terms computed (detail::kulla_conty_kept): a point of a
    // sweep, after points at this and at other alphas, against the same point on a thread that
    // has kept nothing, value and bound bit for bit, and its work counted only where computed
    const auto m = material(0.4, 0.55, {0.9, 0.5, 0.2}), other = material(0.4, 0.65, {0.9, 0.5, 0.2});
    const auto kc = mat::compensation_kind::kulla_conty;
    // both on threads of their own, so that no earlier test's kept terms enter
    mat::material_albedo<mat::gltf::lobe_count> cold, first, again, later;
    std::thread([&] { cold = mat::compensated_albedo_of(m, 0.3, kc); }).join();
    std::thread([&] {
        first = mat::compensated_albedo_of(m, 0.9, kc);
        mat::compensated_albedo_of(other, 0.9, kc);
        later = mat::compensated_albedo_of(m, 0.3, kc);
        again = mat::compensated_albedo_of(m, 0.9, kc);
    }).join();
    for (std::size_t j = 0; j < mat::gltf::lobe_count; ++j)
        for (std::size_t ch = 0; ch < 3; ++ch) {
            CAPTURE(j, ch);
            CHECK(later.lobes[j].value[ch] == cold.lobes[j].value[ch]);
            CHECK(later.lobes[j].abs_error[ch] == cold.lobes[j].abs_error[ch]);
        }
    normzoo::albedo_settings s;  // what compensated_albedo_of asks the terms at
    s.tolerance = s.tolerance * 0.8;
    const auto terms = mf::kulla_conty_at(mat::detail::gltf_specular_composition(m, kc), m.alpha(), 1, s);
    CHECK(later.evaluations + terms.lost.evaluations + terms.e_avg.evaluations == cold.evaluations);
    CHECK(first.evaluations == again.evaluations + cold.evaluations - later.evaluations);
}
