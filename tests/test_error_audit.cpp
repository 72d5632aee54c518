// The error audit (src/verify/audit/, its tables in tables/error_audit.hpp): a small audit on
// its own seed must pass, and the audit must catch an estimator that is dishonest (10x too
// small) or useless (1e7x too large).
#include <catch2/catch.hpp>
#include <normzoo/normzoo.hpp>
#include <verify/audit/cases.hpp>
#include <verify/audit/reference.hpp>
#include <verify/audit/run.hpp>
#include <verify/audit/statistics.hpp>
#include <verify/tables/error_audit.hpp>

using namespace normzoo;
using namespace verify;  // the tables under test

namespace {
audit_settings small_audit() {
    audit_settings s;
    s.seed = 7;  // not the table's seed: other cases than results/error-audit.*
    s.cases = 500;
    return s;
}

// The summary of all families together (the last one).
audit_summary overall(const std::vector<audit_result>& cases, const audit_settings& s) {
    return audit_summaries(cases, s.pessimism_limit).back();
}
}  // namespace

TEST_CASE("a 500-case audit passes in every family") {
    const auto s = small_audit();
    const auto cases = run_audit(s, 2);
    CHECK(cases.size() >= s.cases);
    const auto summaries = audit_summaries(cases, s.pessimism_limit);
    REQUIRE(summaries.size() == std::size(audit_families) + 1);
    for (const auto& m : summaries) {
        CAPTURE(m.family, m.number_type, m.cases, m.failures, m.pessimistic, m.min_ratio, m.max_pessimism);
        CHECK(m.cases > 0);
        CHECK(m.failures == 0);
        CHECK(m.pessimistic == 0);
        CHECK(m.pass());
    }
    for (const auto& r : error_audit_table(summaries)) CHECK_FALSE(r.failed());
}

TEST_CASE("the audit catches an estimate 10x too small") {
    auto s = small_audit();
    s.estimate_scale = 0.1;
    const auto cases = run_audit(s, 2);
    const auto all = overall(cases, s);
    INFO("failing cases: " << all.failures << " of " << all.cases);
    CHECK(all.failures > 0);
    CHECK_FALSE(all.pass());
    bool table_fails = false;
    for (const auto& r : error_audit_table(audit_summaries(cases, s.pessimism_limit))) table_fails = table_fails || r.failed();
    CHECK(table_fails);
}

TEST_CASE("the audit catches an estimate 1e7x too large") {
    auto s = small_audit();
    s.estimate_scale = 1e7;
    const auto all = overall(run_audit(s, 2), s);
    CHECK(all.failures == 0);
    CHECK(all.pessimistic > 0);
    CHECK_FALSE(all.pass());
}

TEST_CASE("a case is judged against the truth and the spacing of its type") {
    audit_result c;
    c.true_error = 1e-20, c.estimate = 1e-21, c.spacing = 1e-16;
    CHECK(c.fails());  // below the true error, however small
    c.estimate = 1e-14;
    CHECK_FALSE(c.fails());
    CHECK(c.pessimism() == Approx(100));  // judged against the spacing, not 1e-20
    c.true_error = 0;
    CHECK(c.exact());
    CHECK(std::isinf(c.ratio_to_true()));
}

TEST_CASE("the draws are fixed by the seed") {
    auto s = small_audit();
    const auto a = audit_cases(s), b = audit_cases(s);
    REQUIRE(a.size() == b.size());
    bool same = true;
    for (std::size_t i = 0; i < a.size(); ++i) same = same && a[i].n == b[i].n && a[i].ratio == b[i].ratio && a[i].tilt_deg == b[i].tilt_deg;
    CHECK(same);
    s.seed += 1;
    const auto c = audit_cases(s);
    bool differs = false;
    for (std::size_t i = 0; i < a.size() && i < c.size(); ++i) differs = differs || a[i].n != c[i].n || a[i].ratio != c[i].ratio;
    CHECK(differs);
    // the lights: half across the horizon, some of them with r0/r far below 1e-100
    std::size_t across = 0, tiny = 0;
    for (const auto& x : a) {
        if (x.family != audit_family::irradiance_sphere && x.family != audit_family::irradiance_disk) continue;
        const double b = x.family == audit_family::irradiance_sphere ? std::asin(x.ratio) : std::atan(x.ratio);
        across += x.tilt_deg > 90 - b * 180 / 3.141592653589793;
        tiny += x.ratio < 1e-100;
    }
    CHECK(across > 20);
    CHECK(tiny > 10);
}

TEST_CASE("the audit's albedo truths agree with the forms' own closed forms") {
    // Two derivations: the audit's in u = (N.H)^2, brdf/*.hpp's in moments of N.H.
    const double n = GENERATE(0.0, 0.5, 1.0, 3.0, 17.25, 1e3, 1e7);
    for_each_zoo_brdf([&](auto form) {
        using Form = decltype(form);
        const wide a = verify::detail::audit_albedo_truth(Form::id, wide(n));
        const wide b = Form::albedo_at_normal(brdf::params<wide>{wide(Form::has_exponent ? n : 0.0)});
        CAPTURE(Form::id, n);
        CHECK(static_cast<double>(abs(a - b) / b) < 1e-45);
    });
}

TEST_CASE("quantiles by nearest rank") {
    std::vector<double> v;
    for (int i = 1; i <= 100; ++i) v.push_back(i);
    CHECK(verify::detail::quantile(v, 0) == 1);
    CHECK(verify::detail::quantile(v, 0.01) == 1);
    CHECK(verify::detail::quantile(v, 0.5) == 50);
    CHECK(verify::detail::quantile(v, 0.99) == 99);
    CHECK(verify::detail::quantile(v, 1) == 100);
}
