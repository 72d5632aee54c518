// bounds: the Blinn-Phong normalization's bounds decided in 50 digits.
#include "../table_spec.hpp"

#include "../plots.hpp"
#include "../tables/bounds.hpp"
#include "../tables/grid.hpp"

namespace verify {

table_spec bounds_spec() {
    return {"bounds", "the Blinn-Phong bounds decided in 50 digits", {"--n"}, [](const options& o) {
                const auto n = o.exponents.empty() ? default_bounds_exponents() : o.exponents;
                return std::vector<table_output>{
                    {bounds_info(), bounds_table(n),
                     grid_text(o, "default exponents n = " + default_bounds_grid.text()), "./verify bounds",
                     plot_bounds}};
            }};
}

}  // namespace verify
