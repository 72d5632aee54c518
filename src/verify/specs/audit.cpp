// audit: every error estimate against the true error over random cases with known answers
// (docs/error-audit.md).
#include "../table_spec.hpp"

#include "../plots.hpp"
#include "../tables/error_audit.hpp"

namespace verify {

namespace {

std::vector<table_output> audit_tables(const options& o) {
    audit_settings audit;
    if (o.seed) audit.seed = *o.seed;
    if (o.cases) audit.cases = *o.cases;
    const auto cases = run_audit(audit, o.jobs);
    const std::string grid = "seed " + std::to_string(audit.seed) + ", " + std::to_string(cases.size()) + " cases";
    const std::string command = "./verify audit";
    std::vector<table_output> out;
    out.push_back({error_audit_info(audit),
                   error_audit_table(audit_summaries(cases, audit.pessimism_limit)), grid, command});
    out.push_back({error_audit_histogram_info(), error_audit_histogram(audit_histograms(cases)),
                   grid, command, plot_error_audit});
    out.push_back({error_audit_extremes_info(),
                   error_audit_extremes(audit_extreme_cases(cases)), grid, command});
    return out;
}

}  // namespace

table_spec audit_spec() {
    return {"audit",
            "every error estimate against the true error over 10,000 random cases with known answers (~10 s of "
            "work: only when named)",
            {"--seed", "--cases"}, audit_tables, false, "cases"};
}

}  // namespace verify
