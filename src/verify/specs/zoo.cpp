// zoo: every zoo row by 1D and 2D quadrature and closed form, the shader constants, 8-bit gloss.
#include "../table_spec.hpp"

#include "../tables/constants.hpp"
#include "../tables/grid.hpp"
#include "../tables/zoo.hpp"

namespace verify {

table_spec zoo_spec() {
    return {"zoo", "every zoo row by 1D and 2D quadrature and closed form; shader constants; 8-bit gloss", {"--n"},
            [](const options& o) {
                const auto n = o.exponents.empty() ? default_zoo_exponents() : o.exponents;
                const std::string grid =
                    grid_text(o, "default exponents " + list_text(default_zoo_exponents()));
                return std::vector<table_output>{
                    {zoo_info(), zoo_table(n, o.jobs), grid, "./verify zoo"},
                    {zoo_constants_info(), zoo_constants_table(n, o.jobs), grid, "./verify zoo"},
                    {gloss_info(), gloss_table(), "codes 0 to 255", "./verify zoo"}};
            }};
}

}  // namespace verify
