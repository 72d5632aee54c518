// material-furnace: the white furnace matrix of the materials (docs/materials.md, "The white
// furnace matrix").
#include "../table_spec.hpp"

#include "../plots.hpp"
#include "../tables/material_furnace.hpp"

namespace verify {

table_spec material_furnace_spec() {
    return {"material-furnace",
            "the white furnace matrix: OpenPBR's furnace configurations as glTF materials, each lobe alone and the "
            "whole, with each multiple-scattering compensation, over roughness and incidence; and OpenPBR's own",
            {},
            [](const options& o) {
                return std::vector<table_output>{{material_furnace_info(), material_furnace_records(o.jobs),
                                                  material_furnace_grid_text(), "./verify material-furnace",
                                                  plot_material_furnace}};
            }};
}

}  // namespace verify
