// stability: every integrand to the ends of its domain, and where the naive formulations break
// (docs/stability.md).
#include "../table_spec.hpp"

#include "../tables/stability.hpp"
#include "../tables/stability_naive.hpp"

namespace verify {

table_spec stability_spec() {
    return {"stability",
            "every integrand to the ends of its domain (n to 1e9, incidence to 90 - 1e-6 deg, r0/r to "
            "5e-324), and where the naive formulations break; run only when named",
            {},
            [](const options& o) {
                const std::string grid = "the stress grids (fixed)";
                return std::vector<table_output>{
                    {stability_info(), stability_table(o.jobs), grid, "./verify stability"},
                    {stability_naive_info(), stability_naive_table(o.jobs), grid,
                     "./verify stability"}};
            },
            false};
}

}  // namespace verify
