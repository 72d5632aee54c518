// shader-precision: every shader formula in fp16 and fp32 against its exact value
// (docs/shader-precision.md).
#include "../table_spec.hpp"

#include "../plots.hpp"
#include "../tables/shader_precision.hpp"

namespace verify {

table_spec shader_precision_spec() {
    return {"shader-precision",
            "every shader formula (zoo normalizations, (n+8)/(8 pi), gloss, Schlick and its exp2 "
            "form, the lobe and its spherical Gaussian) in fp16 and fp32 against its exact value",
            {},
            [](const options& o) {
                // The audits once: the records summarize them, the figure draws their curves.
                auto audits = shader_precision_audits(o.jobs);
                auto records = shader_precision_table(audits);
                return std::vector<table_output>{
                    {shader_precision_info(), std::move(records),
                     shader_precision_grid_text(), "./verify shader-precision",
                     [audits = std::move(audits)](const table_output&, file_set& files) {
                         return plot_shader_precision(audits, files);
                     }}};
            }};
}

}  // namespace verify
