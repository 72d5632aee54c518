// The materials, one line each (docs/materials.md): `energy --material`, `--brdf --against`, their
// help and the docs' key lists derive from this list. A material is a value type with the members
// material.hpp lists, and four free functions found beside it: albedo(m, mu, compensation,
// settings), compensation_error(m, compensation) (why it refuses one at its inputs, or nullptr),
// claims_preservation(m, compensation) and reciprocity_difference(m, compensation).
#pragma once
#include <string>
#include <string_view>

#include "compensation.hpp"
#include "gltf.hpp"
#include "openpbr.hpp"

#define NORMZOO_MATERIALS(X) X(gltf) X(openpbr)

namespace normzoo::material {

// Calls f(M{}) for the material whose id is `id`; false when there is none.
template <class F>
bool visit_material(std::string_view id, F&& f) {
#define NORMZOO_VISIT_MATERIAL(M) \
    if (id == M::id) {            \
        f(M{});                   \
        return true;              \
    }
    NORMZOO_MATERIALS(NORMZOO_VISIT_MATERIAL)
#undef NORMZOO_VISIT_MATERIAL
    return false;
}

// The ids, "gltf, openpbr", for messages and help.
inline std::string material_ids() {
    std::string out;
#define NORMZOO_MATERIAL_ID(M) out += (out.empty() ? "" : ", ") + std::string(M::id);
    NORMZOO_MATERIALS(NORMZOO_MATERIAL_ID)
#undef NORMZOO_MATERIAL_ID
    return out;
}

}  // namespace normzoo::material
