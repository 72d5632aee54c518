// ndf: Beckmann and GGX by roughness: normalization, Smith G1, the weak white furnace, the
// Phong-Beckmann mapping.
#include "../table_spec.hpp"

#include "../plots.hpp"
#include "../tables/ndf.hpp"

namespace verify {

table_spec ndf_spec() {
    return {"ndf",
            "Beckmann and GGX by roughness alpha: normalization, non-projected integral, Smith G1 and the weak "
            "white furnace; the Phong-Beckmann mapping",
            {"--n"},
            [](const options& o) {
                const std::string command = "./verify ndf";
                const std::string grid = "alpha = 1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1, 2, 5, 10";
                const auto alphas = default_ndf_alphas();
                const auto n = o.exponents.empty() ? default_mapping_exponents() : o.exponents;
                return std::vector<table_output>{
                    {ndf_info(), ndf_table(alphas, o.jobs), grid, command, plot_ndf},
                    {furnace_info(),
                     furnace_table(alphas, default_furnace_angles(), o.jobs),
                     grid + "; theta_v = 0, 30, 60, 80, 85, 89, 89.9 degrees", command, plot_ndf_furnace},
                    {mapping_info(), mapping_table(n, o.jobs),
                     grid_text(o, "default exponents 1, 2, 4, ..., 128, 512, 2048, 1e4, 1e5"), command}};
            }};
}

}  // namespace verify
