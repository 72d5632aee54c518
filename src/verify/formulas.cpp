#include "formulas.hpp"

#include <normzoo/registry.hpp>

#include <set>
#include <string_view>

namespace verify {

namespace {

std::string zoo_row_formula(std::string_view id) {
    std::string s;
    normzoo::with_zoo_row(id, [&](auto row) {
        using Row = decltype(row);
        // The NDF rows are distributions of normals h (their expression says "over h"), the others RDFs.
        const std::string expression = Row::expression;
        const bool over_h = expression.find("over h") != std::string::npos;
        s = expression + (over_h ? "" : " (an RDF, V = N)") + "; normalization " + Row::normalization;
    });
    return s;
}

std::string brdf_formula(std::string_view id) {
    std::string s;
    normzoo::with_brdf(id, [&](auto form) { s = "f(L, V) = " + std::string(decltype(form)::formula); });
    return s;
}

std::string ndf_formula(std::string_view id) {
    std::string s;
    normzoo::with_ndf(id, [&](auto ndf) {
        using Ndf = decltype(ndf);
        s = "D(h) = " + std::string(Ndf::formula) + "; Smith G1 = " + Ndf::g1_formula;
    });
    return s;
}

}  // namespace

std::vector<std::string> formula_lines(const std::vector<record>& records) {
    std::vector<std::string> lines;
    std::set<std::string> seen;
    for (const auto& r : records) {
        for (const char* key : {"row", "model", "ndf"}) {
            const std::string id = r.text(key);
            if (id.empty() || !seen.insert(id).second) continue;
            // "model" names a BRDF form, or in a scene a zoo row that is no form (a distribution).
            std::string f = std::string(key) == "row"   ? zoo_row_formula(id)
                            : std::string(key) == "ndf" ? ndf_formula(id)
                                                        : brdf_formula(id);
            if (f.empty() && std::string(key) == "model") f = zoo_row_formula(id);
            if (!f.empty()) lines.push_back("`" + id + "`: " + f);
        }
    }
    return lines;
}

}  // namespace verify
