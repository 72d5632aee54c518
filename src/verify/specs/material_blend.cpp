// material-blend: a metal/dielectric mix with a multiple-scattering compensation, computed by
// mixing results and by mixing F0 (docs/materials.md, "The blend engines get wrong").
#include "../table_spec.hpp"

#include "../plots.hpp"
#include "../tables/material_blend.hpp"

namespace verify {

table_spec material_blend_spec() {
    return {"material-blend",
            "a metal/dielectric mix with a multiple-scattering compensation, by mixing the two results and by "
            "compensating the mixed F0, side by side over roughness, metallic and incidence",
            {},
            [](const options& o) {
                return std::vector<table_output>{{material_blend_info(), material_blend_records(o.jobs),
                                                  material_blend_grid_text(), "./verify material-blend",
                                                  plot_material_blend}};
            }};
}

}  // namespace verify
