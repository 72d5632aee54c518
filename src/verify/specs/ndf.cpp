// ndf: Beckmann and GGX by roughness: normalization, Smith G1, the weak white furnace, the
// Phong-Beckmann mapping.
#include "../table_spec.hpp"

#include "../plots.hpp"
#include "../tables/grid.hpp"
#include "../tables/ndf.hpp"

namespace verify {

table_spec ndf_spec() {
    return {"ndf",
            "Beckmann and GGX by roughness alpha: normalization, non-projected integral, Smith G1 and the weak "
            "white furnace; the Phong-Beckmann mapping",
            {"--n"},
            [](const options& o) {
                const std::string command = "./verify ndf";
                const auto alpha_inputs = default_ndf_alphas();
                const std::string grid = "alpha = " + list_text(alpha_inputs);
                const auto alphas = doubles_of(alpha_inputs);
                const auto n = o.exponents.empty() ? default_mapping_exponents() : o.exponents;
                return std::vector<table_output>{
                    {ndf_info(), ndf_table(alphas, o.jobs), grid, command, plot_ndf},
                    {furnace_info(),
                     furnace_table(alphas, default_furnace_angles(), o.jobs),
                     grid + "; theta_v = " + list_text(default_furnace_angles()) + " degrees", command,
                     plot_ndf_furnace},
                    {mapping_info(), mapping_table(n, o.jobs),
                     grid_text(o, "default exponents " + list_text(default_mapping_exponents())), command}};
            }};
}

}  // namespace verify
