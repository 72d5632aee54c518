// The materials of ids.hpp's list as types: `energy --material`, `--brdf --against`, their help and
// the docs' key lists derive from that list. A material is a value type with the members
// material.hpp lists, and four free functions found beside it: albedo(m, mu, compensation,
// settings), compensation_error(m, compensation) (why it refuses one at its inputs, or nullptr),
// claims_preservation(m, compensation) and reciprocity_difference(m, compensation).
#pragma once
#include <string>
#include <string_view>

#include "compensation.hpp"
#include "ids.hpp"
#include "gltf.hpp"
#include "openpbr.hpp"

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

// Each type's id is its name in the list (material_ids() stringifies the list).
#define NORMZOO_MATERIAL_ID_MATCHES(M) static_assert(std::string_view(M::id) == #M, "a material's id is its name in ids.hpp");
NORMZOO_MATERIALS(NORMZOO_MATERIAL_ID_MATCHES)
#undef NORMZOO_MATERIAL_ID_MATCHES

}  // namespace normzoo::material
