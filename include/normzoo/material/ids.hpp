// The materials, one line each (docs/materials.md): each name is a material type in this namespace
// whose `id` is that name (registry.hpp checks it). The command's options, help and messages take
// the ids from this list without compiling the materials.
#pragma once
#include <string>

#define NORMZOO_MATERIALS(X) X(gltf) X(openpbr)

namespace normzoo::material {

// The ids, "gltf, openpbr", for messages and help.
inline std::string material_ids() {
    std::string out;
#define NORMZOO_MATERIAL_ID(M) out += (out.empty() ? "" : ", ") + std::string(#M);
    NORMZOO_MATERIALS(NORMZOO_MATERIAL_ID)
#undef NORMZOO_MATERIAL_ID
    return out;
}

}  // namespace normzoo::material
