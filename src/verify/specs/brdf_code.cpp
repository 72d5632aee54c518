// brdf-code: the BRDF Explorer files of examples/brdfs/ against the built-in forms they write out
// (docs/brdf-code.md).
#include "../table_spec.hpp"

#include "../brdf_examples.hpp"

namespace verify {

table_spec brdf_code_spec() {
    return {"brdf-code",
            "the BRDF Explorer files of examples/brdfs/ compiled and integrated as black boxes, against the "
            "built-in forms they write out (docs/brdf-code.md)",
            {},
            [](const options& o) { return brdf_example_tables(o.jobs); }};
}

}  // namespace verify
