// OpenPBR Surface 1.1 (docs/materials.md, "OpenPBR Surface 1.1"): the material (openpbr_model.hpp:
// its inputs, lobes and layering operators), its coat's absorption and darkening
// (openpbr_coat.hpp), its fuzz (openpbr_fuzz.hpp), its albedo with V fixed (openpbr_albedo.hpp),
// and here what the material registry (registry.hpp) reads beside the type: f, albedo,
// claims_preservation and reciprocity_difference.
#pragma once
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "compensation.hpp"
#include "openpbr_albedo.hpp"
#include "openpbr_coat.hpp"
#include "openpbr_fuzz.hpp"
#include "openpbr_model.hpp"

namespace normzoo::material {

inline rgb openpbr::f(const vec3<double>& l, const vec3<double>& v) const {
    rgb sum{};
    if (!(l.z() > 0 && v.z() > 0)) return sum;
    for (const rgb& x : f_lobes(l, v, openpbr_terms(*this, v.z()).values())) sum = sum + x;
    return sum;
}

// Why OpenPBR refuses compensation k, or nullptr: it takes none (its albedo scaling is the model's
// own energy balance, and the specification fixes no multiple-scattering scheme).
inline const char* compensation_error(const openpbr&, compensation_kind k) {
    return k == compensation_kind::none ? nullptr : "openpbr takes no compensation suffix";
}

inline material_albedo<openpbr::lobe_count> albedo(const openpbr& m, double mu, compensation_kind k,
                                                   const albedo_settings& settings = {}) {
    if (const char* why = compensation_error(m, k)) throw std::invalid_argument(why);
    return openpbr_albedo(m, mu, settings);
}

// The configurations the specification's "White furnace testing" lists, as far as reflection
// reaches (its subsurface and translucent bases need transmission): a white base (base_color 1,
// base_weight 1), white specular_color at specular_weight 1, metal, dielectric or any mix; with a
// coat, coat_color white; with fuzz, fuzz_color white; whatever the roughnesses. The specification
// claims them of the ground truth; its reduction's single-scattering metal does not meet the claim
// (it asks for a multiple-scattering compensation it does not specify), which `preserving` shows.
inline bool claims_preservation(const openpbr& m, compensation_kind k) {
    const auto& in = m.in;
    return k == compensation_kind::none && in.base_weight == 1 && in.base_color == grey(1) && in.specular_weight == 1 &&
           in.specular_color == grey(1) && (in.coat_weight == 0 || in.coat_color == grey(1)) &&
           (in.fuzz_weight == 0 || in.fuzz_color == grey(1));
}

// f(L, V) against f(V, L) on the pairs of 8 directions (polar angles 5 to 85 degrees, four
// azimuths), as gltf's: the largest relative difference of a channel. The layering reads its
// albedos at the view only (1 - E_spec(V), 1 - E_coat(V), Delta's K_s = F(N.V), 1 - F E_fuzz(V))
// and the fuzz lobe is an LTC keyed on V, so OpenPBR is non-reciprocal by design: this says by how
// much. The view terms are computed once per direction.
inline double reciprocity_difference(const openpbr& m, compensation_kind) {
    const std::vector<vec3<double>> dirs = reciprocity_directions();
    std::vector<openpbr_view_values> terms;
    for (const auto& d : dirs) terms.push_back(openpbr_terms(m, d.z()).values());
    auto f = [&](std::size_t li, std::size_t vi) {
        rgb sum{};
        for (const auto& x : m.f_lobes(dirs[li], dirs[vi], terms[vi])) sum = sum + x;
        return sum;
    };
    return largest_reciprocity_difference(dirs.size(), f);
}

}  // namespace normzoo::material
