// brdf-file: a BRDF given as shader code, checked (docs/brdf-code.md). Planned by --brdf FILE,
// never named; its tables are brdf and brdf-checks, printed, or written only to --out.
#include "../table_spec.hpp"

#include "../brdf_run.hpp"

namespace verify {

table_spec brdf_file_spec() {
    table_spec s{"brdf-file",
                 "a BRDF given as shader code (--brdf FILE): its albedo against incidence, with verdicts (docs/brdf-code.md)",
                 {"--brdf", "--param", "--define", "--include-dir", "--steps", "--theta", "--mu", "--tolerance", "--time-limit",
                  "--fixed", "--reciprocity-tolerance", "--texture", "--layout", "--against", "--map",
                  "--against-tolerance"},
                 brdf_file_tables,
                 false,
                 "shader"};
    s.check_options = [](const options& o) { brdf_request_of(o); };
    s.writes_by_default = false;
    s.planned_by = "--brdf";
    return s;
}

}  // namespace verify
