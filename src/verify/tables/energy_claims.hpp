// What the seed texts claim about energy, each shown by the sweep's numbers (issue 3, point 4).
// A claim that holds is a finding; only the two identities (albedo 1 at normal incidence for
// the exactly normalized forms) are checks, since failing them would mean a wrong integral.
#pragma once
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "energy.hpp"

namespace normzoo {

namespace detail {

constexpr const char* zoo_post = "The Blinn-Phong Normalization Zoo";
constexpr const char* adopting_post = "Adopting a physically based shading model";

struct claim_data {
    std::vector<const record*> sweep, summary;  // of one model
    bool empty() const { return sweep.empty(); }
};

inline claim_data claim_rows(const std::string& model, const std::vector<record>& sweep,
                             const std::vector<record>& summary) {
    claim_data d;
    for (const auto& r : sweep)
        if (text_field(r, "model") == model) d.sweep.push_back(&r);
    for (const auto& r : summary)
        if (text_field(r, "model") == model) d.summary.push_back(&r);
    return d;
}

inline record claim_record(const std::string& claim, const char* source, const std::string& model, bool holds,
                           const record& at, const std::string& value_key, const std::string& error_key,
                           const std::string& theta_key, std::string detail) {
    record r{"energy-claims", {}};
    r.set("claim", claim)
        .set("source", std::string(source))
        .set("model", model)
        .set("holds", holds)
        .set("value", number_field(at, value_key))
        .set("error_estimate", number_field(at, error_key))
        .set("at_n", number_field(at, "n"))
        .set("at_theta_deg", number_field(at, theta_key))
        .set("detail", std::move(detail));
    return r;
}

// Albedo 1 at normal incidence for every exponent swept: the largest |albedo - 1| and where.
inline void normal_incidence_identity(std::vector<record>& out, const std::string& model, const std::string& claim,
                                      const claim_data& d) {
    const record* worst = nullptr;
    bool holds = true;
    std::size_t count = 0;
    for (const record* r : d.sweep) {
        if (number_field(*r, "theta_deg") != 0) continue;
        ++count;
        const double dev = std::abs(number_field(*r, "albedo") - 1);
        holds = holds && dev <= number_field(*r, "error_estimate") + 4 * eps<double>();
        if (!worst || dev > std::abs(number_field(*worst, "albedo") - 1)) worst = r;
    }
    if (!worst) return;
    record r = claim_record(claim, zoo_post, model, holds, *worst, "albedo", "error_estimate", "theta_deg",
                            "largest deviation from 1 at normal incidence over " + std::to_string(count) +
                                " exponents: " + format_number(std::abs(number_field(*worst, "albedo") - 1)));
    r.set("pass", holds);
    out.push_back(std::move(r));
}

// Gains energy somewhere in the sweep: the largest albedo and the angles from which it gains.
inline void gains_somewhere(std::vector<record>& out, const std::string& model, const std::string& claim,
                            const char* source, const claim_data& d, std::string extra = "") {
    const record* top = nullptr;
    std::size_t gaining = 0;
    double from_lo = INFINITY, from_hi = -INFINITY, n_lo = 0, n_hi = 0;
    for (const record* s : d.summary) {
        if (!top || number_field(*s, "max_albedo") > number_field(*top, "max_albedo")) top = s;
        if (text_field(*s, "verdict") != "gains") continue;
        ++gaining;
        const double from = number_field(*s, "first_gain_theta_deg");
        if (from < from_lo) from_lo = from, n_lo = number_field(*s, "n");
        if (from > from_hi) from_hi = from, n_hi = number_field(*s, "n");
    }
    if (!top) return;
    std::string detail = "gains at " + std::to_string(gaining) + " of " + std::to_string(d.summary.size()) +
                         " exponents";
    if (gaining && from_lo == from_hi)
        detail += ", each first at " + format_number(from_lo) + " deg";
    else if (gaining)
        detail += ", first at angles from " + format_number(from_lo) + " deg (n = " + format_number(n_lo) + ") to " +
                  format_number(from_hi) + " deg (n = " + format_number(n_hi) + ")";
    detail += "; largest albedo " + format_number(number_field(*top, "max_albedo"));
    if (bool_field(*top, "rising_at_last_angle")) detail += " at the most grazing angle swept, still rising";
    out.push_back(claim_record(claim, source, model, gaining > 0, *top, "max_albedo", "max_albedo_error",
                               "argmax_theta_deg", detail + extra));
}

// The albedo at the most grazing angle swept, for each exponent, as text.
inline std::string grazing_values(const claim_data& d) {
    double last = -1;
    for (const record* r : d.sweep) last = std::max(last, number_field(*r, "theta_deg"));
    std::string s = "at " + format_number(last) + " deg:";
    for (const record* r : d.sweep)
        if (number_field(*r, "theta_deg") == last)
            s += " n = " + format_number(number_field(*r, "n")) + ": " + format_number(number_field(*r, "albedo")) + ";";
    s.pop_back();
    return s;
}

}  // namespace detail

inline std::vector<record> energy_claims(const std::vector<record>& sweep, const std::vector<record>& summary,
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
        const record* top = nullptr;
        bool holds = true;
        for (const record* r : d.sweep) {
            if (number_field(*r, "theta_deg") != 0) continue;
            holds = holds && number_field(*r, "albedo") - number_field(*r, "error_estimate") <= 1;
            if (!top || number_field(*r, "albedo") > number_field(*top, "albedo")) top = r;
        }
        if (top)
            out.push_back(claim_record("the minimalist Cook-Torrance at k_s = 1 conserves energy at normal incidence",
                                       zoo_post, "minimalist-cook-torrance", holds, *top, "albedo", "error_estimate",
                                       "theta_deg", "largest albedo at normal incidence over the exponents swept"));
        gains_somewhere(out, "minimalist-cook-torrance",
                        "the minimalist Cook-Torrance at k_s = 1 gains energy towards grazing incidence", zoo_post, d,
                        "; " + grazing_values(d));
    }

    for (const char* model : {"microfacet-blinn", "cook-torrance-ksk"}) {
        auto d = rows(model);
        if (d.empty()) continue;
        const record* top = nullptr;
        for (const record* sr : d.summary)
            if (!top || number_field(*sr, "max_albedo") > number_field(*top, "max_albedo")) top = sr;
        const bool conserves = text_field(*top, "verdict") != "gains";
        out.push_back(claim_record(std::string("white furnace (F = 1): ") + model + " conserves energy",
                                   std::string(model) == "microfacet-blinn" ? adopting_post : zoo_post, model,
                                   conserves, *top, "max_albedo", "max_albedo_error", "argmax_theta_deg",
                                   "largest albedo over the sweep " + format_number(number_field(*top, "max_albedo")) +
                                       "; " + grazing_values(d)));
    }
    return out;
}

inline table_info energy_claims_info() {
    return {"energy-claims",
            "The seeds' claims about energy conservation, shown by the sweep's numbers",
            {"sources by title: \"The Blinn-Phong Normalization Zoo\" (both versions), \"Adopting a physically "
             "based shading model\"",
             "value, at_n, at_theta_deg: the number that decides the claim (largest albedo, or largest deviation "
             "from 1) and where; error_estimate is its bound",
             "holds: what the numbers say; only the normal-incidence identities are checks (pass)"},
            {"claim", "holds", "value", "error_estimate", "at_n", "at_theta_deg", "detail"},
            {"value"}};
}

}  // namespace normzoo
