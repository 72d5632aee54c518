// enclosures: every zoo row's integral enclosed rigorously by Arb (docs/certified.md).
#include "../table_spec.hpp"

#include "../plots.hpp"
#include "../tables/enclosures.hpp"
#include "../tables/grid.hpp"

namespace verify {

table_spec enclosures_spec() {
    return {"enclosures",
            "every zoo row's integral enclosed rigorously (Arb), beside the quadrature and the closed form",
            {"--n"},
            [](const options& o) {
                const auto n = o.exponents.empty() ? default_zoo_exponents() : o.exponents;
                return std::vector<table_output>{
                    {verify::certify::enclosures_info(), verify::certify::enclosures_table(n, o.jobs),
                     grid_text(o, "default exponents " + list_text(default_zoo_exponents())),
                     "./verify enclosures", plot_enclosures}};
            },
            false};  // its tables carry timings: a default run stays byte-identical without them
}

}  // namespace verify
