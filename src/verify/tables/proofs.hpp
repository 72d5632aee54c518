// The proofs table: each Blinn-Phong bound claim (bound_claims.hpp) proved for every real n in
// [0, N] by branch and bound (branch_and_bound.hpp), and, as controls that must fail, the same
// claims with the bound tightened by 1e-6 (relative): the prover must refute each of them.
// Before the proof, the margin form is checked against the row's closed form at a few points
// (norm/bound - 1 in 50 digits), so the form proved is the claim's.
#pragma once
#include <mpfi.h>
#include <cmath>
#include <string>
#include <vector>

#include <normzoo/certify/bound_claims.hpp>
#include <normzoo/certify/branch_and_bound.hpp>
#include <normzoo/zoo/blinn_phong.hpp>
#include <normzoo/real.hpp>
#include <normzoo/wide.hpp>

#include "../record.hpp"
#include "grid_text.hpp"

namespace verify::certify {

// The certified tables read the library's certified core unqualified.
using namespace normzoo::certify;

// Where each margin's form is checked against the closed form.
inline std::vector<double> closed_form_check_points() { return {0, 0.5, 3, 40, 1000}; }

// How much the controls tighten each bound (relative): the prover must refute them.
inline constexpr double control_tightening = 1e-6;

// |form(n) - (norm/bound - 1 or 1 - norm/bound)| < 1e-45 at each n, the naive side from the
// row's closed form in 50 digits (absolute: the naive side cancels to that).
inline bool form_matches_closed_form(const bound_claim& c, const std::vector<double>& at = closed_form_check_points()) {
    for (double n : at) {
        const wide nw = n;
        const wide norm = std::string(c.row) == "blinn-phong" ? zoo::blinn_phong::closed_form(nw)
                                                              : zoo::blinn_phong_modified::closed_form(nw);
        const wide bound = (nw + c.bound_offset) / (8 * pi<wide>());
        const wide naive = c.is_upper ? 1 - norm / bound : norm / bound - 1;
        const interval form = c.margin(interval(n, 200));
        // The form's interval, widened by the naive side's rounding, must hold the naive value.
        const interval naive_iv = interval::parse(to_decimal(naive, 50), 200);
        interval slack(-1e-45, 1e-45, 200);
        if (!(form + slack).overlaps(naive_iv)) return false;
    }
    return true;
}

struct proof_case {
    const bound_claim* claim;
    double tighten;  // 0: the claim itself; > 0: a control that must be refuted
};

inline record proof_record(const proof_case& pc, const proof_settings& base = {}) {
    proof_settings s = base;
    s.tighten = pc.tighten;
    const bound_claim& c = *pc.claim;
    const bool matches = form_matches_closed_form(c);
    const proof_result r = prove_positive(c.margin, c.margin_dual, c.equality_at_zero, s);
    const bool control = pc.tighten != 0;
    std::string method = "bisection on [0, " + to_decimal(s.domain_hi, 1) + "], interval of " + c.form + " > 0";
    if (r.monotone > 0)
        method += "; on [0, " + to_decimal(r.monotone_hi, 6) + "]: margin(0) = 0 exactly and d margin/dn > 0";
    std::string result = to_string(r.outcome);
    if (r.outcome != proof_outcome::proved)
        result += " at box [" + to_decimal(r.at_lo, 6) + ", " + to_decimal(r.at_hi, 6) + "]: " + r.detail;
    record rec{"proofs", {}};
    rec.set("claim", std::string(c.id) + (control ? " tightened by " + to_decimal(pc.tighten, 1) + " (false)" : ""))
        .set("row", std::string(c.row))
        .set("statement", std::string(c.statement))
        .set("margin_form", std::string(c.form))
        .set("form_matches_closed_form", matches)
        .set("method", method)
        .set("boxes", static_cast<std::int64_t>(r.boxes))
        .set("boxes_direct", static_cast<std::int64_t>(r.direct))
        .set("boxes_monotone", static_cast<std::int64_t>(r.monotone))
        .set("max_depth", static_cast<std::int64_t>(r.max_depth))
        .set("smallest_box", r.smallest_box)
        .set("expected", std::string(control ? "refuted" : "proved"))
        .set("result", result)
        .set("seconds", r.seconds)
        .set("pass", matches && r.outcome == (control ? proof_outcome::refuted : proof_outcome::proved));
    return rec;
}

inline table_info proofs_info(const proof_settings& s = {}) {
    table_info info{
        "proofs",
        "The Blinn-Phong bounds proved for every real n in [0, " + value_text(s.domain_hi) +
            "] by branch and bound in interval arithmetic",
        {"interval arithmetic: MPFI " + std::string(mpfi_get_version()) + " (MPFR endpoints, rounded outward) at " +
             std::to_string(s.prec) + " bits",
         "margins written so that n does not cancel against itself, p = 2^(-n/2); each form checked against "
             "norm/bound - 1 from the closed form in 50 digits at n = " + list_text(closed_form_check_points()),
         "a box is settled when the margin's interval over it is > 0 (direct), or, for the box at n = 0 where "
         "the margin is exactly 0, when its derivative's interval (forward-mode) over the box is > 0 (monotone)",
         "boxes: all boxes visited (settled or bisected); smallest_box: the narrowest settled; max depth " +
             std::to_string(s.max_depth) + ", at most " + std::to_string(s.max_boxes) + " boxes",
         "controls: each bound tightened by " + value_text(control_tightening) + " (margin > " +
             value_text(control_tightening) + "), which is false; pass means refuted with a counterexample box",
         "seconds: wall time of the branch and bound"},
        {"claim", "method", "boxes", "max_depth", "smallest_box", "result", "seconds", "pass"}};
    info.id_keys = {"claim"};
    info.check = {{}, {"seconds"}};
    return info;
}

inline std::vector<record> proofs_table(const proof_settings& s = {}) {
    std::vector<record> out;
    for (const auto& c : bound_claims()) out.push_back(proof_record({&c, 0}, s));
    for (const auto& c : bound_claims()) out.push_back(proof_record({&c, control_tightening}, s));
    return out;
}

// "n in [0, 1e7]; controls tightened by 1e-6": the proofs' domain in the table's head.
inline std::string proofs_grid_text(const proof_settings& s = {}) {
    return "n in [0, " + value_text(s.domain_hi) + "]; controls tightened by " + value_text(control_tightening);
}

}  // namespace verify::certify
