// What the seed texts claim about energy, each shown by the sweep's numbers (docs/energy.md).
// A claim that holds is a finding; only the two identities (albedo 1 at normal incidence for
// the exactly normalized forms) are checks, since failing them would mean a wrong integral.
// The claims read the sweep's typed points and summaries, never their records.
#pragma once
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "energy.hpp"

namespace verify {

namespace detail {

constexpr const char* zoo_post = "The Blinn-Phong Normalization Zoo";
constexpr const char* adopting_post = "Adopting a physically based shading model";

struct claim_data {
    std::vector<const albedo_point*> sweep;
    std::vector<const albedo_summary*> summary;  // of one model
    bool empty() const { return sweep.empty(); }
};

inline claim_data claim_rows(std::string_view model, const std::vector<albedo_point>& sweep,
                             const std::vector<albedo_summary>& summary) {
    claim_data d;
    for (const auto& a : sweep)
        if (a.model == model) d.sweep.push_back(&a);
    for (const auto& g : summary)
        if (g.model == model) d.summary.push_back(&g);
    return d;
}

// The number that decides a claim, its bound, and where (the form's value and the angle).
struct claim_evidence {
    double value, error, at_value, at_theta_deg;
};
inline claim_evidence evidence(const albedo_point& a) { return {a.albedo.value, a.albedo.abs_error, a.value, a.theta_deg}; }
inline claim_evidence evidence(const albedo_summary& g) {
    return {g.max_albedo, g.max_albedo_error, g.value, g.argmax_theta_deg};
}

inline record claim_record(const std::string& claim, const char* source, const std::string& model, bool holds,
                           const claim_evidence& at, std::string detail) {
    record r{"energy-claims", {}};
    r.set("claim", claim)
        .set("source", std::string(source))
        .set("model", model)
        .set("holds", holds)
        .set("value", at.value)
        .set("error_estimate", at.error)
        .set("at_n", at.at_value)
        .set("at_theta_deg", at.at_theta_deg)
        .set("detail", std::move(detail));
    return r;
}

// Albedo 1 at normal incidence for every exponent swept: the largest |albedo - 1| and where.
inline void normal_incidence_identity(std::vector<record>& out, const std::string& model, const std::string& claim,
                                      const claim_data& d) {
    const albedo_point* worst = nullptr;
    bool holds = true;
    std::size_t count = 0;
    for (const albedo_point* a : d.sweep) {
        if (a->theta_deg != 0) continue;
        ++count;
        const double dev = std::abs(a->albedo.value - 1);
        holds = holds && dev <= a->albedo.abs_error + 4 * eps<double>();
        if (!worst || dev > std::abs(worst->albedo.value - 1)) worst = a;
    }
    if (!worst) return;
    record r = claim_record(claim, zoo_post, model, holds, evidence(*worst),
                            "largest deviation from 1 at normal incidence over " + std::to_string(count) +
                                " exponents: " + format_number(std::abs(worst->albedo.value - 1)));
    r.set("pass", holds);
    out.push_back(std::move(r));
}

// Gains energy somewhere in the sweep: the largest albedo and the angles from which it gains.
inline void gains_somewhere(std::vector<record>& out, const std::string& model, const std::string& claim,
                            const char* source, const claim_data& d, std::string extra = "") {
    const albedo_summary* top = nullptr;
    std::size_t gaining = 0;
    double from_lo = INFINITY, from_hi = -INFINITY, n_lo = 0, n_hi = 0;
    for (const albedo_summary* s : d.summary) {
        if (!top || s->max_albedo > top->max_albedo) top = s;
        if (s->verdict() != albedo_verdict::gains) continue;
        ++gaining;
        const double from = s->first_gain_theta_deg.value_or(std::nan(""));
        if (from < from_lo) from_lo = from, n_lo = s->value;
        if (from > from_hi) from_hi = from, n_hi = s->value;
    }
    if (!top) return;
    std::string detail = "gains at " + std::to_string(gaining) + " of " + std::to_string(d.summary.size()) +
                         " exponents";
    if (gaining && from_lo == from_hi)
        detail += ", each first at " + format_number(from_lo) + " deg";
    else if (gaining)
        detail += ", first at angles from " + format_number(from_lo) + " deg (n = " + format_number(n_lo) + ") to " +
                  format_number(from_hi) + " deg (n = " + format_number(n_hi) + ")";
    detail += "; largest albedo " + format_number(top->max_albedo);
    if (top->rising_at_last_angle) detail += " at the most grazing angle swept, still rising";
    out.push_back(claim_record(claim, source, model, gaining > 0, evidence(*top), detail + extra));
}

// The albedo at the most grazing angle swept, for each exponent, as text.
inline std::string grazing_values(const claim_data& d) {
    double last = -1;
    for (const albedo_point* a : d.sweep) last = std::max(last, a->theta_deg);
    std::string s = "at " + format_number(last) + " deg:";
    for (const albedo_point* a : d.sweep)
        if (a->theta_deg == last) s += " n = " + format_number(a->value) + ": " + format_number(a->albedo.value) + ";";
    s.pop_back();
    return s;
}

}  // namespace detail

inline std::vector<record> energy_claims(const std::vector<albedo_point>& sweep, const std::vector<albedo_summary>& summary,
                                         const energy_settings& s = {}) {
    using namespace detail;
    std::vector<record> out;
    auto rows = [&](const char* model) { return claim_rows(model, sweep, summary); };

    if (auto d = rows("phong-modified"); !d.empty())
        normal_incidence_identity(out, "phong-modified", "modified Phong has albedo 1 at normal incidence", d);
    if (auto d = rows("blinn-phong-modified"); !d.empty())
        normal_incidence_identity(out, "blinn-phong-modified",
                                  "modified Blinn-Phong with the exact factor has albedo 1 at normal incidence", d);
    if (auto d = rows("phong"); !d.empty())
        gains_somewhere(out, "phong", "original Phong (over N.L) does not conserve energy", zoo_post, d);
    if (auto d = rows("blinn-phong"); !d.empty())
        gains_somewhere(out, "blinn-phong", "original Blinn-Phong (over N.L) does not conserve energy", zoo_post, d);

    if (auto d = rows("blinn-phong-modified-approx"); !d.empty()) {
        // At normal incidence the gain is a function of n alone: its maximum, by Brent in ln n.
        using form = brdf::blinn_phong_modified_approx;
        auto minus_gain = [&](double ln_n) { return -albedo<form>(0, std::exp(ln_n), 1.0, s.albedo()).value; };
        const auto best = boost::math::tools::brent_find_minima(minus_gain, 0.0, std::log(1e3), 24);
        const double n_star = std::exp(best.first);
        const auto at = albedo<form>(0, n_star, 1.0, s.albedo());
        gains_somewhere(out, "blinn-phong-modified-approx", "the (n+8)/(8 pi) factor gains energy", zoo_post, d,
                        "; at normal incidence the gain peaks at " + format_number(at.value - 1) + " +- " +
                            format_number(at.abs_error) + " for n = " + format_number(n_star));
    }

    if (auto d = rows("minimalist-cook-torrance"); !d.empty()) {
        const albedo_point* top = nullptr;
        bool holds = true;
        for (const albedo_point* a : d.sweep) {
            if (a->theta_deg != 0) continue;
            holds = holds && a->albedo.value - a->albedo.abs_error <= 1;
            if (!top || a->albedo.value > top->albedo.value) top = a;
        }
        if (top)
            out.push_back(claim_record("the minimalist Cook-Torrance at k_s = 1 conserves energy at normal incidence",
                                       zoo_post, "minimalist-cook-torrance", holds, evidence(*top),
                                       "largest albedo at normal incidence over the exponents swept"));
        gains_somewhere(out, "minimalist-cook-torrance",
                        "the minimalist Cook-Torrance at k_s = 1 gains energy towards grazing incidence", zoo_post, d,
                        "; " + grazing_values(d));
    }

    for (const char* model : {"microfacet-blinn", "cook-torrance-ksk"}) {
        auto d = rows(model);
        if (d.empty()) continue;
        const albedo_summary* top = nullptr;
        for (const albedo_summary* g : d.summary)
            if (!top || g->max_albedo > top->max_albedo) top = g;
        const bool conserves = top->verdict() != albedo_verdict::gains;
        out.push_back(claim_record(std::string("white furnace (F = 1): ") + model + " conserves energy",
                                   std::string(model) == "microfacet-blinn" ? adopting_post : zoo_post, model,
                                   conserves, evidence(*top),
                                   "largest albedo over the sweep " + format_number(top->max_albedo) + "; " +
                                       grazing_values(d)));
    }
    return out;
}

inline table_info energy_claims_info() {
    table_info info{
        "energy-claims",
        "The seeds' claims about energy conservation, shown by the sweep's numbers",
        {"sources by title: \"The Blinn-Phong Normalization Zoo\" (both versions), \"Adopting a physically "
         "based shading model\"",
         "value, at_n, at_theta_deg: the number that decides the claim (largest albedo, or largest deviation "
         "from 1) and where; error_estimate is its bound",
         "holds: what the numbers say; only the normal-incidence identities are checks (pass)"},
        {"claim", "holds", "value", "error_estimate", "at_n", "at_theta_deg", "detail"},
        {"value"}};
    info.id_keys = {"claim", "model"};
    info.check = {{{"value", "error_estimate", false}}, {"error_estimate"}};
    return info;
}

}  // namespace verify
