// The table material-furnace (docs/materials.md, "The white furnace matrix"): the white furnace
// configurations OpenPBR's specification lists ("White furnace testing": a white metal, a white
// dielectric over a white diffuse base, any mix of them), as their glTF counterparts, each lobe
// alone and the whole, with every multiple-scattering compensation, over roughness and
// incidence, V held (what a furnace shows); then the same configurations of OpenPBR itself, with a
// coat, fuzz and specular_weight 1.5 (openpbr_furnace_record). The verdicts: conserving (the
// largest channel at most 1 within its bound) and preserving (1 within the bound, where the model
// claims it: null where it does not).
#pragma once
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <normzoo/detail/parallel.hpp>
#include <normzoo/material/compensation.hpp>
#include <normzoo/material/openpbr.hpp>

#include "../record.hpp"
#include "grid_text.hpp"

namespace verify {

namespace material_furnace_grid {
struct configuration {
    const char* name;
    double base_color, metallic;
    double sheen = 0, clearcoat = 0;  // KHR_materials_sheen's sheenColor, KHR_materials_clearcoat's clearcoat
};
// OpenPBR's white furnace configurations that a reflection-only albedo can test (its subsurface
// and translucent bases need transmission), as glTF parameters.
inline std::vector<configuration> configurations() {
    return {{"white-metal", 1, 1}, {"white-dielectric", 1, 0}, {"white-mix", 1, 0.5}};
}
// The glTF extensions with lobes of their own (after OpenPBR's rows): a white sheen over the white
// dielectric and a white coat over the white metal and dielectric (KHR_materials_sheen and
// _clearcoat, their roughness the base's).
inline std::vector<configuration> extension_configurations() {
    return {{"white-sheen-dielectric", 1, 0, 1, 0}, {"white-coat-metal", 1, 1, 0, 1}, {"white-coat-dielectric", 1, 0, 0, 1}};
}
// Binary fractions, so that no input rounds (roughness^2 is exact too).
inline std::vector<double> roughnesses() { return {0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1}; }
inline std::vector<double> mus() { return {1, 0.5, 0.125}; }
inline std::vector<std::string> compensations() { return {"none", "kulla-conty", "turquin", "fdez-aguera"}; }
inline std::vector<normzoo::material::smith_form> maskings() {
    return {normzoo::material::smith_form::separable, normzoo::material::smith_form::height_correlated};
}
inline const char* masking_id(normzoo::material::smith_form f) {
    return f == normzoo::material::smith_form::separable ? "smith-separable" : "smith-height-correlated";
}
// OpenPBR's configurations (its "White furnace testing", reflection only): base_color 1 throughout;
// coat_color and fuzz_color white where present; specular_weight 1 but in two (its metal's gain
// above 1; the dielectric's eta' stays finite while specular_weight F0 < 1); a thin film at its
// defaults (0.5 um, index 1.4) in the last two, which the specification says keeps the furnace.
struct openpbr_configuration {
    const char* name;
    double metalness, coat, fuzz, specular_weight;
    double film = 0;  // thin_film_weight
};
inline std::vector<openpbr_configuration> openpbr_configurations() {
    return {{"white-metal", 1, 0, 0, 1},          {"white-dielectric", 0, 0, 0, 1},
            {"white-mix", 0.5, 0, 0, 1},          {"white-dielectric-coat", 0, 1, 0, 1},
            {"white-metal-coat", 1, 1, 0, 1},     {"white-dielectric-fuzz", 0, 0, 1, 1},
            {"white-all", 0.5, 0.5, 0.5, 1},      {"white-metal-weight-1.5", 1, 0, 0, 1.5},
            {"white-dielectric-weight-1.5", 0, 0, 0, 1.5}, {"white-dielectric-film", 0, 0, 0, 1, 1},
            {"white-metal-film", 1, 0, 0, 1, 1}};
}
}  // namespace material_furnace_grid

struct furnace_point {
    material_furnace_grid::configuration config;
    std::string compensation;
    normzoo::material::smith_form masking;
    double roughness, mu;
};

inline record furnace_record(const furnace_point& p) {
    namespace mat = normzoo::material;
    mat::gltf m;
    m.in.baseColor = mat::grey(p.config.base_color);
    m.in.metallic = p.config.metallic;
    m.in.roughness = p.roughness;
    m.in.masking = p.masking;
    m.in.sheenColor = mat::grey(p.config.sheen), m.in.sheenRoughness = p.roughness;
    m.in.clearcoat = p.config.clearcoat, m.in.clearcoatRoughness = p.roughness;
    const mat::compensation_kind k =
        p.compensation == "none" ? mat::compensation_kind::none : mat::parse_compensation(p.compensation);
    const auto a = mat::compensated_albedo_of(m, p.mu, k);
    record r{"material-furnace", {}};
    r.set("material", std::string("gltf") + (k == mat::compensation_kind::none ? "" : "/" + p.compensation))
        .set("configuration", std::string(p.config.name))
        .set("masking", std::string(material_furnace_grid::masking_id(p.masking)))
        .set("roughness", p.roughness)
        .set("mu", p.mu);
    for (std::size_t i = 0; i < mat::gltf::core_lobe_count; ++i)
        r.set("albedo_" + std::string(mat::gltf::lobe_ids[i]), a.lobes[i].largest());
    r.set("albedo", a.whole.largest())
        .set("error_estimate", a.whole.largest_error())
        .set("deviation", a.whole.largest() - 1)
        .set("conserving", mat::conserving(a.whole));
    if (mat::claims_preservation(m, k)) r.set("preserving", mat::preserving(a.whole));
    else r.set("preserving", nullptr);
    // What is checked: the integral met its tolerance, and preservation holds where the model
    // claims it. A model that gains energy (glTF's dielectric does) is a finding, not a failure.
    r.set("pass", a.whole.largest_error() <= 1e-10 && (!mat::claims_preservation(m, k) || mat::preserving(a.whole)));
    // the sheen's and the coat's lobes where on, last: the columns before keep their places
    if (m.sheen_on()) r.set("albedo_sheen", a.lobes[3].largest());
    if (m.coat_on()) r.set("albedo_clearcoat", a.lobes[4].largest());
    return r;
}

// An OpenPBR row: every roughness of the configuration (specular, diffuse, coat, fuzz) at
// `roughness`. pass: the bound met, and preserving where claimed unless a metal is present (its
// single-scattering GGX loses what the specification leaves to a compensation: the finding).
inline record openpbr_furnace_record(const material_furnace_grid::openpbr_configuration& c, double roughness, double mu) {
    namespace mat = normzoo::material;
    mat::openpbr m;
    m.in.base_color = mat::grey(1);
    m.in.base_metalness = c.metalness, m.in.specular_weight = c.specular_weight;
    m.in.coat_weight = c.coat, m.in.fuzz_weight = c.fuzz, m.in.thin_film_weight = c.film;
    m.in.specular_roughness = m.in.base_diffuse_roughness = m.in.coat_roughness = m.in.fuzz_roughness = roughness;
    const auto a = mat::openpbr_albedo(m, mu);
    record r{"material-furnace", {}};
    r.set("material", std::string("openpbr"))
        .set("configuration", std::string(c.name))
        .set("masking", std::string("smith-height-correlated"))
        .set("roughness", roughness)
        .set("mu", mu);
    for (std::size_t i = 0; i < mat::openpbr::lobe_count; ++i)
        r.set("albedo_" + std::string(mat::openpbr::lobe_ids[i]), a.lobes[i].largest());
    const bool claims = mat::claims_preservation(m, mat::compensation_kind::none);
    r.set("albedo", a.whole.largest())
        .set("error_estimate", a.whole.largest_error())
        .set("deviation", a.whole.largest() - 1)
        .set("conserving", mat::conserving(a.whole));
    if (claims) r.set("preserving", mat::preserving(a.whole));
    else r.set("preserving", nullptr);
    r.set("pass", a.whole.largest_error() <= 1e-10 && (!claims || c.metalness > 0 || mat::preserving(a.whole)));
    return r;
}

inline std::vector<record> material_furnace_records(unsigned jobs) {
    namespace g = material_furnace_grid;
    std::vector<furnace_point> points;
    for (const auto& c : g::configurations())
        for (const auto& k : g::compensations())
            for (auto masking : g::maskings())
                for (double r : g::roughnesses())
                    for (double mu : g::mus()) points.push_back({c, k, masking, r, mu});
    struct openpbr_point {
        g::openpbr_configuration c;
        double roughness, mu;
    };
    std::vector<openpbr_point> openpbr_points;
    for (const auto& c : g::openpbr_configurations())
        for (double r : g::roughnesses())
            for (double mu : g::mus()) openpbr_points.push_back({c, r, mu});
    std::vector<furnace_point> extension_points;  // after OpenPBR's rows; no compensation under a sheen
    for (const auto& c : g::extension_configurations())
        for (const auto& k : g::compensations())
            for (auto masking : g::maskings())
                for (double r : g::roughnesses())
                    for (double mu : g::mus())
                        if (c.sheen == 0 || k == "none") extension_points.push_back({c, k, masking, r, mu});
    const std::size_t n_gltf = points.size(), n_openpbr = openpbr_points.size();
    std::vector<record> rows(n_gltf + n_openpbr + extension_points.size());
    normzoo::detail::parallel_for(rows.size(), jobs, [&](std::size_t i) {
        if (i < n_gltf) rows[i] = furnace_record(points[i]);
        else if (i < n_gltf + n_openpbr) {
            const auto& p = openpbr_points[i - n_gltf];
            rows[i] = openpbr_furnace_record(p.c, p.roughness, p.mu);
        } else rows[i] = furnace_record(extension_points[i - n_gltf - n_openpbr]);
    });
    return rows;
}

inline table_info material_furnace_info() {
    table_info t{"material-furnace",
                 "The white furnace matrix: OpenPBR's furnace configurations as glTF materials, each lobe and the whole, "
                 "with each compensation, and as OpenPBR",
                 {"configurations (OpenPBR 1.1, \"White furnace testing\", the reflection-only ones): white-metal = baseColor 1, "
                  "metallic 1; white-dielectric = baseColor 1, metallic 0 (ior 1.5, specular 1); white-mix = metallic 0.5",
                  "white-sheen-dielectric = white-dielectric with sheenColor 1, sheenRoughness = roughness (KHR_materials_sheen; "
                  "no compensation); white-coat-metal, white-coat-dielectric = clearcoat 1, clearcoatRoughness = roughness "
                  "(KHR_materials_clearcoat; a compensation on the base's lobes, the coat single scattering)",
                  "albedo with V held, per lobe (diffuse, specular, metal; sheen, clearcoat where on) and whole, the largest "
                  "channel, by material/albedo.hpp, material/sheen_albedo.hpp and material/compensation.hpp at tolerance 1e-10; "
                  "error_estimate bounds the whole",
                  "conserving: albedo at most 1 within error_estimate (a finding about the model); preserving: 1 within it, "
                  "where the model claims it (a white metal with a compensation), null elsewhere; pass: error_estimate <= "
                  "1e-10, and preserving where claimed",
                  "openpbr (material/openpbr.hpp, no compensation), base_color 1, every roughness (specular, diffuse, coat, "
                  "fuzz) at roughness: white-metal, white-dielectric, white-mix = base_metalness 1, 0, 0.5; -coat = "
                  "coat_weight 1, -fuzz = fuzz_weight 1 (white colours); white-all = base_metalness, coat_weight, fuzz_weight "
                  "0.5; -weight-1.5 = specular_weight 1.5; -film = thin_film_weight 1 at thin_film_thickness 0.5, "
                  "thin_film_ior 1.4; lobes diffuse, specular, metal, coat, fuzz; preserving where "
                  "its specification claims it (specular_weight 1), pass without it where a metal is present (its "
                  "single-scattering GGX)"},
                 {"material", "configuration", "masking", "roughness", "mu", "albedo_diffuse", "albedo_specular", "albedo_metal",
                  "albedo_coat", "albedo_fuzz", "albedo", "deviation", "conserving", "preserving", "pass"},
                 {"albedo"}};
    t.id_keys = {"material", "configuration", "masking", "roughness", "mu"};
    t.check = {{{"albedo", "error_estimate", false},
                {"albedo_diffuse", "error_estimate", false},
                {"albedo_specular", "error_estimate", false},
                {"albedo_metal", "error_estimate", false},
                {"albedo_coat", "error_estimate", false},
                {"albedo_fuzz", "error_estimate", false},
                {"albedo_sheen", "error_estimate", false},
                {"albedo_clearcoat", "error_estimate", false},
                {"deviation", "error_estimate", false}},
               {"error_estimate"}};
    t.md_pivot = pivot_view{{"material", "configuration", "masking", "roughness"}, "mu", material_furnace_grid::mus(), "albedo"};
    return t;
}

inline std::string material_furnace_grid_text() {
    namespace g = material_furnace_grid;
    return "roughness = " + list_text(g::roughnesses()) + "; mu = " + list_text(g::mus()) +
           "; masking = smith-separable (the specification's), smith-height-correlated (openpbr's)";
}

}  // namespace verify
