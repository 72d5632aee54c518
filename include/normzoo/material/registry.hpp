// The materials, one line each (docs/materials.md): `energy --material`, `--brdf --against`, their
// help and the docs' key lists derive from this list. A material is a value type with the members
// material.hpp lists, and three free functions found beside it: albedo(m, mu, compensation,
// settings), claims_preservation(m, compensation) and reciprocity_difference(m, compensation).
#pragma once
#include <string>
#include <string_view>
#include <type_traits>

#include "compensation.hpp"
#include "gltf.hpp"
#include "openpbr.hpp"

#define NORMZOO_MATERIALS(X) X(gltf) X(openpbr)

namespace normzoo::material {

// Whether a material takes a compensation suffix: true unless it declares `compensable = false`.
template <class M, class = void>
struct takes_compensation : std::true_type {};
template <class M>
struct takes_compensation<M, std::void_t<decltype(M::compensable)>> : std::bool_constant<M::compensable> {};

// Why material m refuses compensation k at its inputs, or nullptr (the command's exit 2): a
// material's own overload beside it (compensation.hpp: glTF's sheen), this one otherwise.
template <class M>
const char* compensation_error(const M&, compensation_kind) {
    return nullptr;
}

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
