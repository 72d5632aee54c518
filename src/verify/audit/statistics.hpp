// The error audit's statistics over the results (docs/error-audit.md, "How a case is judged" and
// "The figures"): per family and number type the ratios' quantiles and the failures, the
// histogram of log10(estimate / true error), and per member the extreme cases.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "cases.hpp"
#include "run.hpp"

namespace verify {

struct audit_summary {
    std::string family, number_type;
    std::size_t cases = 0, exact = 0, failures = 0, pessimistic = 0;
    double min_ratio = 0, q01 = 0, q50 = 0, q99 = 0, max_ratio = 0;  // e / t over the inexact cases
    double max_pessimism = 0;                                         // e / max(t, u)
    bool pass() const { return failures == 0 && pessimistic == 0; }
};

namespace detail {
// The q-quantile by nearest rank of sorted values.
inline double quantile(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::size_t rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
    rank = rank < 1 ? 1 : rank > sorted.size() ? sorted.size() : rank;
    return sorted[rank - 1];
}
}  // namespace detail

inline audit_summary summarize_audit(const std::vector<const audit_result*>& results, std::string family,
                                     std::string number_type, double pessimism_limit) {
    audit_summary s{std::move(family), std::move(number_type)};
    std::vector<double> ratios;
    for (const auto* c : results) {
        ++s.cases;
        s.failures += c->fails();
        const double p = c->pessimism();
        s.max_pessimism = std::max(s.max_pessimism, p);
        s.pessimistic += p > pessimism_limit;
        if (c->exact()) ++s.exact;
        else ratios.push_back(c->ratio_to_true());
    }
    std::sort(ratios.begin(), ratios.end());
    s.min_ratio = detail::quantile(ratios, 0);
    s.q01 = detail::quantile(ratios, 0.01);
    s.q50 = detail::quantile(ratios, 0.5);
    s.q99 = detail::quantile(ratios, 0.99);
    s.max_ratio = ratios.empty() ? s.min_ratio : ratios.back();
    return s;
}

// Per family and number type, in the order of audit_families, then all of them together.
inline std::vector<audit_summary> audit_summaries(const std::vector<audit_result>& results, double pessimism_limit) {
    std::vector<audit_summary> out;
    std::vector<const audit_result*> all;
    for (audit_family f : audit_families) {
        std::vector<const audit_result*> part;
        for (const auto& c : results)
            if (c.drawn.family == f) part.push_back(&c);
        if (!part.empty()) out.push_back(summarize_audit(part, audit_family_name(f), audit_number_type(f), pessimism_limit));
    }
    for (const auto& c : results) all.push_back(&c);
    out.push_back(summarize_audit(all, "all", "all", pessimism_limit));
    return out;
}

// The distribution of log10(estimate / true error) of one family, in bins of width 1/4 from -2
// to 10 (the first and last bins also take what lies beyond; exact cases are not binned).
struct audit_histogram {
    static constexpr double low = -2, high = 10, width = 0.25;
    static constexpr int bins = static_cast<int>((high - low) / width);
    audit_family family = audit_family::zoo_1d_quad;
    std::vector<std::int64_t> count = std::vector<std::int64_t>(bins, 0);

    double bin_low(int b) const { return low + width * b; }
    double bin_high(int b) const { return low + width * (b + 1); }
};

// Per family with an inexact case, in the order of audit_families.
inline std::vector<audit_histogram> audit_histograms(const std::vector<audit_result>& results) {
    std::vector<audit_histogram> out;
    for (audit_family f : audit_families) {
        audit_histogram h;
        h.family = f;
        bool any = false;
        for (const auto& c : results) {
            if (c.drawn.family != f || c.exact()) continue;
            any = true;
            int b = static_cast<int>(std::floor((std::log10(c.ratio_to_true()) - h.low) / h.width));
            b = b < 0 ? 0 : b >= h.bins ? h.bins - 1 : b;
            ++h.count[b];
        }
        if (any) out.push_back(std::move(h));
    }
    return out;
}

// Per family and member, the case closest to failing (smallest ratio; none where every case is
// exact) and the most pessimistic one.
struct audit_extremes {
    audit_family family = audit_family::zoo_1d_quad;
    std::string member;
    const audit_result* tightest = nullptr;
    const audit_result* loosest = nullptr;
};

// In the order the families and members first occur; the pointers point into `results`.
inline std::vector<audit_extremes> audit_extreme_cases(const std::vector<audit_result>& results) {
    std::vector<audit_extremes> out;
    for (const auto& c : results) {
        const bool seen = std::any_of(out.begin(), out.end(), [&](const audit_extremes& x) {
            return x.family == c.drawn.family && x.member == c.drawn.member;
        });
        if (!seen) out.push_back({c.drawn.family, c.drawn.member});
    }
    for (auto& x : out)
        for (const auto& c : results) {
            if (c.drawn.family != x.family || c.drawn.member != x.member) continue;
            if (!c.exact() && (!x.tightest || c.ratio_to_true() < x.tightest->ratio_to_true())) x.tightest = &c;
            if (!x.loosest || c.pessimism() > x.loosest->pessimism()) x.loosest = &c;
        }
    return out;
}

}  // namespace verify
