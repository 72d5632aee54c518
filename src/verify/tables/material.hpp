// The table material (docs/materials.md): a material's albedo with V fixed, per lobe and whole,
// per channel, with its bound and verdicts, one record per parameter values and incidence
// (`./verify energy --material NAME[/COMPENSATION] --param NAME=VALUE|LO..HI --mu LIST`).
#pragma once
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <normzoo/material/albedo.hpp>

#include "../record.hpp"

namespace verify {

// One point's typed result: what a record is made of.
struct material_point {
    std::string material;                                   // "gltf", "gltf/kulla-conty"
    std::vector<std::pair<std::string, field_value>> params;  // param_NAME -> its value as recorded
    double mu = 1;
    normzoo::material::rgb_estimate whole;                    // its bound includes the inputs' rounding
    std::vector<std::pair<std::string, double>> lobes;        // lobe name -> its largest channel
    std::optional<bool> preserving;                           // empty: the model does not claim it
    double reciprocity = 0;                                   // the largest relative difference f(L,V), f(V,L)
};

// f(L, V) and f(V, L) of a material in double differ by rounding only, far below this, where
// it is reciprocal (docs/materials.md, "Verdicts").
inline constexpr double material_reciprocity_tolerance = 1e-12;

inline std::string json_number(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

inline record material_record(const material_point& p) {
    namespace mat = normzoo::material;
    record r{"material", {}};
    r.set("material", p.material);
    for (const auto& [k, v] : p.params) r.set(k, v);
    std::string lobes = "{";
    for (const auto& [name, value] : p.lobes) lobes += (lobes.size() > 1 ? ", \"" : "\"") + name + "\": " + json_number(value);
    const double largest = p.whole.largest(), error = p.whole.largest_error();
    r.set("mu", p.mu)
        .set("albedo", largest)
        .set("albedo_rgb", json_text{"[" + json_number(p.whole.value[0]) + ", " + json_number(p.whole.value[1]) + ", " +
                                     json_number(p.whole.value[2]) + "]"})
        .set("error_estimate", error)
        .set("lobes", json_text{lobes + "}"})
        .set("conserving", mat::conserving(p.whole))
        .set("preserving", p.preserving ? field_value(*p.preserving) : field_value(nullptr))
        .set("reciprocal", json_text{std::string("{\"holds\": ") +
                                     (p.reciprocity <= material_reciprocity_tolerance ? "true" : "false") +
                                     ", \"largest_relative_difference\": " + json_number(p.reciprocity) + "}"});
    return r;
}

// `params`: the param_NAME keys of the material, in its declaration order.
inline table_info material_info(const std::vector<std::string>& params) {
    std::vector<std::string> columns = {"material"};
    columns.insert(columns.end(), params.begin(), params.end());
    for (const char* k : {"mu", "albedo", "error_estimate", "lobes", "conserving", "preserving", "reciprocal"}) columns.push_back(k);
    table_info t{"material",
                 "A material's directional albedo with V fixed, per lobe and whole, per channel (docs/materials.md)",
                 {"E(mu) = integral over L of f(L, V) N.L, V at cos t = mu; albedo its largest channel, albedo_rgb "
                  "each channel, lobes each lobe's largest channel",
                  "each lobe a x E(F = 1) + b x E(F = (1 - V.H)^5) of its composition (the weight a + b (1 - V.H)^5), "
                  "each E to 1/8 of 1e-10 by the 1D integral with D's azimuthal integral in closed form; a compensation "
                  "per microfacet lobe and channel (microfacet/multiple_scattering.hpp), then mixed",
                  "error_estimate: the largest channel's bound, with what the inputs' rounding to double can move "
                  "(slope over a relative step of 1e-6, doubled, times the rounding)",
                  "conserving: albedo - error_estimate <= 1; preserving: every channel 1 within its bound, where the "
                  "model claims it (a white metal with a compensation), else null; reciprocal: f(L, V) against f(V, L) "
                  "on 28 pairs of directions, holds when the largest relative difference is at most 1e-12"},
                 columns,
                 {"albedo"}};
    t.id_keys = {"material"};
    t.id_keys.insert(t.id_keys.end(), params.begin(), params.end());
    t.id_keys.push_back("mu");
    t.check = {{{"albedo", "error_estimate", false}}, {"error_estimate", "albedo_rgb", "lobes"}};
    return t;
}

}  // namespace verify
