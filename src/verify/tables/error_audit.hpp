// The error audit's tables (docs/error-audit.md): error-audit (per family and number type),
// error-audit-histogram and error-audit-extremes, built from the typed results of audit/: the
// cases (audit/cases.hpp), their truths (audit/reference.hpp), their run (audit/run.hpp) and the
// statistics (audit/statistics.hpp).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <normzoo/real.hpp>

#include "../audit/cases.hpp"
#include "../audit/statistics.hpp"
#include "../record.hpp"

namespace verify {

inline table_info error_audit_info(const audit_settings& s) {
    table_info info{
        "error-audit",
        "Error bars audited: the suite's error estimate against the true error over random cases with known answers",
        {"cases: " + std::to_string(s.cases) + " or more, seed " + std::to_string(s.seed) +
             ", std::mt19937_64 one stream per family (seed + family index), uniforms from the top 53 bits",
         "exponents log-uniform on [1e-6, 1e7], one in seven exact in {0, 0.5, ..., 64}; lights: r0/r log-uniform "
         "on [1e-300, 0.999] (sphere) or [1e-300, 10] (disk), half the cases across the horizon (r0/r >= 1e-12)",
         "zoo-1d: zoo_norm_1d in binary128 and double; zoo-2d: zoo_norm_2d in long double; truth: the zoo's closed "
         "forms in cpp_bin_float<50>",
         "irradiance: cap_irradiance in binary128; truth: pi sin^2 b cos t_c, or Snyder's formula in its original "
         "form across the horizon, in cpp_bin_float<100>",
         "albedo-normal: albedo() at theta = 0 (tolerance 1e-10) in double; truth: closed forms derived in u = (N.H)^2, "
         "in cpp_bin_float<50>",
         "ratio = estimate / true error (both relative to the truth); exact: true error 0 (ratio infinite, apart)",
         "failures: estimate < true error; pessimistic: estimate / max(true error, spacing of the value's type) > " +
             to_decimal(s.pessimism_limit, 1) + "; pass: neither"},
        {"family", "number_type", "cases", "exact", "failures", "min_ratio", "ratio_q01", "ratio_q50", "ratio_q99",
         "max_ratio", "max_pessimism", "pessimistic", "pass"}};
    info.id_keys = {"family", "number_type"};
    return info;
}

inline std::vector<record> error_audit_table(const std::vector<audit_summary>& summaries) {
    std::vector<record> out;
    for (const auto& s : summaries) {
        record r{"error-audit", {}};
        r.set("family", s.family)
            .set("number_type", s.number_type)
            .set("cases", static_cast<std::int64_t>(s.cases))
            .set("exact", static_cast<std::int64_t>(s.exact))
            .set("failures", static_cast<std::int64_t>(s.failures))
            .set("min_ratio", s.min_ratio)
            .set("ratio_q01", s.q01)
            .set("ratio_q50", s.q50)
            .set("ratio_q99", s.q99)
            .set("max_ratio", s.max_ratio)
            .set("max_pessimism", s.max_pessimism)
            .set("pessimistic", static_cast<std::int64_t>(s.pessimistic))
            .set("pass", s.pass());
        out.push_back(std::move(r));
    }
    return out;
}

// Per family and member, the case closest to failing and the most pessimistic one.
inline table_info error_audit_extremes_info() {
    return {"error-audit-extremes",
            "Error audit: per family and member, the case with the smallest ratio and the most pessimistic one",
            {"as error-audit; n, ratio, tilt_deg are the case's parameters (0 where they do not apply)"},
            {"family", "number_type", "member", "which", "n", "ratio", "tilt_deg", "true_error", "estimate", "spacing",
             "estimate_over_true"},
            {"n", "ratio", "tilt_deg"}};
}

inline std::vector<record> error_audit_extremes(const std::vector<audit_extremes>& extremes) {
    std::vector<record> out;
    for (const auto& x : extremes) {
        auto add = [&](const audit_result* c, const char* which) {
            if (!c) return;
            record r{"error-audit-extremes", {}};
            r.set("family", std::string(audit_family_name(x.family)))
                .set("number_type", std::string(audit_number_type(x.family)))
                .set("member", x.member)
                .set("which", std::string(which))
                .set("n", c->drawn.n)
                .set("ratio", c->drawn.ratio)
                .set("tilt_deg", c->drawn.tilt_deg)
                .set("true_error", c->true_error)
                .set("estimate", c->estimate)
                .set("spacing", c->spacing)
                .set("estimate_over_true", c->exact() ? field_value(nullptr) : field_value(c->ratio_to_true()))
                .set("pessimism", c->pessimism())
                .set("value", c->value)
                .set("truth", c->truth)
                .set("fails", c->fails());
            out.push_back(std::move(r));
        };
        add(x.tightest, "smallest ratio");
        add(x.loosest, "most pessimistic");
    }
    return out;
}

// The distribution of log10(estimate / true error) per family and number type (exact cases
// apart, in `exact` of error-audit).
inline table_info error_audit_histogram_info() {
    return {"error-audit-histogram",
            "Error audit: histogram of log10(estimate / true error) per family and number type",
            {"bins of width 0.25 from -2 to 10; the end bins hold what lies beyond; exact answers are not binned"},
            {"family", "number_type", "log10_low", "log10_high", "count"}};
}

inline std::vector<record> error_audit_histogram(const std::vector<audit_histogram>& histograms) {
    std::vector<record> out;
    for (const auto& h : histograms)
        for (int b = 0; b < h.bins; ++b) {
            record r{"error-audit-histogram", {}};
            r.set("family", std::string(audit_family_name(h.family)))
                .set("number_type", std::string(audit_number_type(h.family)))
                .set("log10_low", h.bin_low(b))
                .set("log10_high", h.bin_high(b))
                .set("count", h.count[static_cast<std::size_t>(b)]);
            out.push_back(std::move(r));
        }
    return out;
}

}  // namespace verify
