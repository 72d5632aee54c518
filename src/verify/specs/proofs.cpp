// proofs: the Blinn-Phong bounds proved for every real n in [0, 1e7] by MPFI (docs/certified.md).
#include "../table_spec.hpp"

#include "../tables/proofs.hpp"

namespace verify {

table_spec proofs_spec() {
    return {"proofs",
            "the Blinn-Phong bounds proved for every real n in [0, 1e7] by branch and bound (MPFI)",
            {},  // every n in [0, 1e7]: --n does not apply
            [](const options&) {
                return std::vector<table_output>{{verify::certify::proofs_info(), verify::certify::proofs_table(),
                                                  verify::certify::proofs_grid_text(), "./verify proofs"}};
            },
            false};
}

}  // namespace verify
