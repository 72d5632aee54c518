// code-audit: the black-box integrator against every built-in form as an opaque callable
// (docs/brdf-code.md).
#include "../table_spec.hpp"

#include "../brdf_examples.hpp"

namespace verify {

table_spec code_audit_spec() {
    return {"code-audit",
            "the black-box integrator of BRDFs given as code against every built-in form passed as an "
            "opaque callable (minutes: only when named)",
            {},
            [](const options& o) { return code_audit_tables(o.jobs); },
            false};
}

}  // namespace verify
