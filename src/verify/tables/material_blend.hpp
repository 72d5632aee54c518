// The table material-blend (docs/materials.md, "The blend engines get wrong"): a material that mixes
// a metal (F0 = its base colour c) and a dielectric (F0 = 0.04) by metallic m, with a
// multiple-scattering compensation C(F0) on the specular lobe, computed two ways:
//     mixing results  m C(c) + (1 - m) C(0.04)           (what the mixture of two BRDFs is)
//     mixing F0       C(m c + (1 - m) 0.04)              (what Bevy and three.js computed)
// Single scattering is linear in F0 (the split-sum pair: E_ss = F0 A + B), so the two agree
// without a compensation; every compensation is nonlinear in F0 (Kulla-Conty's F_avg^2 factor,
// Turquin's F0 times E_ss, Fdez-Aguera's division by 1 - F_avg (1 - E)), so they part. The diffuse lobe is the same either way and left out.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <normzoo/detail/parallel.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>

#include "../record.hpp"
#include "grid_text.hpp"

namespace verify {

namespace material_blend_grid {
// Binary fractions, so that no input rounds: the perceptual roughness r (alpha = r^2), metallic,
// the base colour (one channel) and mu.
inline std::vector<double> roughnesses() { return {0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1}; }
inline std::vector<double> metallics() { return {0.25, 0.5, 0.75}; }
inline std::vector<double> base_colors() { return {1, 0.5}; }
inline std::vector<double> mus() { return {1, 0.5, 0.125}; }
inline std::vector<std::string> compensations() { return {"kulla-conty", "turquin", "fdez-aguera"}; }
// The dielectric's F0: glTF's ior 1.5, ((1.5 - 1) / (1.5 + 1))^2 = 0.04, whose rounding to double
// moves C by at most C'(F0) 0.04 2^-53 < 1e-17 (C' < 2 here).
inline constexpr double dielectric_f0 = 0.04;
inline constexpr double f0_rounding = 1e-17;
inline const char* composition_base = "ggx/smith-height-correlated/schlick/";
}  // namespace material_blend_grid

// One (compensation, roughness, base colour): C at the F0s both ways read, for every mu.
struct blend_group {
    std::string compensation;
    double roughness = 0, base_color = 0;
    // [f0 index][mu index]: F0 = 0.04, c, then the mixed F0 of each metallic
    std::vector<std::vector<normzoo::quadrature::estimate<double>>> c;
};

inline std::vector<double> blend_f0s(double base_color) {
    namespace g = material_blend_grid;
    std::vector<double> f0s = {g::dielectric_f0, base_color};
    for (double m : g::metallics()) f0s.push_back(m * base_color + (1 - m) * g::dielectric_f0);
    return f0s;
}

inline blend_group blend_group_at(const std::string& comp, double roughness, double base_color) {
    namespace mf = normzoo::microfacet;
    const mf::composition c = mf::composition::parse(material_blend_grid::composition_base + comp);
    const double alpha = roughness * roughness;
    const normzoo::albedo_settings s;
    blend_group g{comp, roughness, base_color, {}};
    // Kulla-Conty's E_avg and lost energy are of F = 1, so of alpha alone: computed once for every
    // F0 and mu, each F0 taking its own F_avg (multiple_scattering.hpp)
    const bool kc = c.compensation == mf::composition::compensation_kind::kulla_conty;
    const mf::kulla_conty_terms shared = kc ? mf::kulla_conty_at(c, alpha, 1, s) : mf::kulla_conty_terms{};
    for (double f0 : blend_f0s(base_color)) {
        mf::kulla_conty_terms t = shared;
        if (kc) t.f0 = f0, t.f_avg = mf::fresnel_average(c, f0);
        std::vector<normzoo::quadrature::estimate<double>> row;
        for (double mu : material_blend_grid::mus())
            row.push_back(mf::compensated_albedo(c, mu, alpha, f0, s, kc ? &t : nullptr));
        g.c.push_back(std::move(row));
    }
    return g;
}

inline record blend_record(const blend_group& g, std::size_t m_index, std::size_t mu_index) {
    namespace grid = material_blend_grid;
    const double m = grid::metallics()[m_index];
    const auto& dielectric = g.c[0][mu_index];
    const auto& metal = g.c[1][mu_index];
    const auto& mixed = g.c[2 + m_index][mu_index];
    const double results = m * metal.value + (1 - m) * dielectric.value;
    const double results_error = m * metal.abs_error + (1 - m) * dielectric.abs_error + grid::f0_rounding;
    const double difference = mixed.value - results;
    const double error = results_error + mixed.abs_error + grid::f0_rounding + 4e-16;
    record r{"material-blend", {}};
    r.set("compensation", g.compensation)
        .set("roughness", g.roughness)
        .set("alpha", g.roughness * g.roughness)
        .set("base_color", g.base_color)
        .set("metallic", m)
        .set("mu", grid::mus()[mu_index])
        .set("albedo_mixing_results", results)
        .set("albedo_mixing_f0", mixed.value)
        .set("difference", difference)
        .set("relative_difference", difference / results)
        .set("error_estimate", error)
        .set("apart", std::abs(difference) > error);
    return r;
}

inline table_info material_blend_info() {
    namespace grid = material_blend_grid;
    table_info t{"material-blend",
                 "A metal/dielectric mix with a multiple-scattering compensation, computed by mixing results and by "
                 "mixing F0",
                 {std::string("specular lobe ") + grid::composition_base + "COMPENSATION (microfacet/multiple_scattering.hpp); "
                  "dielectric F0 = 0.04 (ior 1.5), metal F0 = base_color; the diffuse lobe is the same both ways and left out",
                  "albedo_mixing_results = metallic C(base_color) + (1 - metallic) C(0.04); albedo_mixing_f0 = "
                  "C(metallic base_color + (1 - metallic) 0.04); difference = albedo_mixing_f0 - albedo_mixing_results",
                  "each C by quadrature at tolerance 1e-10; error_estimate bounds the difference (the sum of the three "
                  "bounds); apart: |difference| > error_estimate"},
                 {"compensation", "roughness", "base_color", "metallic", "mu", "albedo_mixing_results",
                  "albedo_mixing_f0", "difference", "apart"},
                 {"albedo_mixing_results", "albedo_mixing_f0"}};
    t.id_keys = {"compensation", "roughness", "base_color", "metallic", "mu"};
    // the view to read: the difference by mu (CSV and JSON hold both albedos and the bounds)
    t.md_pivot = pivot_view{{"compensation", "roughness", "base_color", "metallic"}, "mu", grid::mus(), "difference"};
    t.check = {{{"albedo_mixing_results", "error_estimate", false},
                {"albedo_mixing_f0", "error_estimate", false},
                {"difference", "error_estimate", false}},
               {"error_estimate", "relative_difference", "apart"}};
    return t;
}

inline std::string material_blend_grid_text() {
    namespace grid = material_blend_grid;
    return "r = " + list_text(grid::roughnesses()) + " (alpha = r^2); metallic = " + list_text(grid::metallics()) +
           "; base_color = " + list_text(grid::base_colors()) + "; mu = " + list_text(grid::mus());
}

inline std::vector<record> material_blend_records(unsigned jobs) {
    namespace grid = material_blend_grid;
    struct key {
        std::string comp;
        double r, c;
    };
    std::vector<key> keys;
    for (const auto& comp : grid::compensations())
        for (double r : grid::roughnesses())
            for (double c : grid::base_colors()) keys.push_back({comp, r, c});
    std::vector<blend_group> groups(keys.size());
    normzoo::detail::parallel_for(keys.size(), jobs, [&](std::size_t i) {
        groups[i] = blend_group_at(keys[i].comp, keys[i].r, keys[i].c);
    });
    std::vector<record> rows;
    for (const auto& g : groups)
        for (std::size_t m = 0; m < grid::metallics().size(); ++m)
            for (std::size_t u = 0; u < grid::mus().size(); ++u) rows.push_back(blend_record(g, m, u));
    return rows;
}

}  // namespace verify
