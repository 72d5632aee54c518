// Proves margin(n) > 0 for every real n in [0, N] (or in (0, N] with margin(0) = 0) by
// branch and bound in interval arithmetic (MPFI). Boxes are bisected at their midpoint, depth first,
// left first; each box is settled by one of:
//   direct      the margin's interval over the whole box is > 0;
//   monotone    the box starts at 0, margin(0) is exactly 0 (the point interval [0, 0]), and
//               the derivative's interval over the whole box is > 0, so margin(n) > margin(0) = 0
//               for every n in (0, hi] (the mean value theorem);
// and refuted when the margin is <= 0 on the whole box or at its midpoint (a counterexample).
// A box that is none of these after max_depth bisections leaves the claim undecided.
#pragma once
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "../real.hpp"
#include "dual.hpp"

namespace normzoo::certify {

enum class proof_outcome { proved, refuted, undecided };

inline const char* to_string(proof_outcome o) {
    return o == proof_outcome::proved ? "proved" : o == proof_outcome::refuted ? "refuted" : "undecided";
}

struct proof_settings {
    double domain_hi = 1e7;
    mpfr_prec_t prec = 128;
    int max_depth = 80;
    std::size_t max_boxes = 1000000;
    double tighten = 0;  // prove margin > tighten instead (a bound tightened by this, relative)
};

struct proof_result {
    proof_outcome outcome = proof_outcome::undecided;
    std::size_t boxes = 0, direct = 0, monotone = 0;
    int max_depth = 0;
    double smallest_box = 0;  // width of the narrowest box settled
    double monotone_hi = 0;   // the box [0, monotone_hi] settled by monotonicity (0: none)
    double at_lo = 0, at_hi = 0;  // the box that refuted or was left undecided
    std::string detail;       // what happened there
    double seconds = 0;
};

template <class Margin, class MarginDual>
proof_result prove_positive(Margin margin, MarginDual margin_dual, bool equality_at_zero, const proof_settings& s) {
    const auto start = std::chrono::steady_clock::now();
    const mpfr_prec_t prec = s.prec;
    const interval tighten(s.tighten, prec);
    auto m = [&](const interval& x) { return s.tighten == 0 ? margin(x) : margin(x) - tighten; };
    auto md = [&](const dual& x) {
        dual r = margin_dual(x);
        if (s.tighten != 0) r.v = r.v - tighten;
        return r;
    };
    proof_result r;
    r.smallest_box = s.domain_hi;
    struct box {
        double lo, hi;
        int depth;
    };
    std::vector<box> stack{{0, s.domain_hi, 0}};
    auto stop = [&](proof_outcome o, const box& b, std::string why) {
        r.outcome = o;
        r.at_lo = b.lo;
        r.at_hi = b.hi;
        r.detail = std::move(why);
    };
    bool done = false;
    while (!stack.empty() && !done) {
        const box b = stack.back();
        stack.pop_back();
        ++r.boxes;
        r.max_depth = std::max(r.max_depth, b.depth);
        const interval x = interval(b.lo, b.hi, prec);
        const interval value = m(x);
        if (value.positive()) {
            ++r.direct;
            r.smallest_box = std::min(r.smallest_box, b.hi - b.lo);
            continue;
        }
        if (b.lo == 0 && equality_at_zero && s.tighten == 0) {
            const interval at_zero = m(interval(0.0, prec));
            const dual slope = md(dual{x, interval(1.0, prec)});
            if (at_zero.exact_zero() && slope.d.positive()) {
                ++r.monotone;
                r.monotone_hi = b.hi;
                r.smallest_box = std::min(r.smallest_box, b.hi - b.lo);
                continue;
            }
        }
        const double mid = b.lo + (b.hi - b.lo) / 2;
        const interval at_mid = m(interval(mid, prec));
        if (value.nonpositive()) {
            stop(proof_outcome::refuted, b, "margin <= 0 on the whole box: " + value.text(6));
            done = true;
        } else if (at_mid.nonpositive()) {
            stop(proof_outcome::refuted, b, "margin <= 0 at n = " + to_decimal(mid, 17) + ": " + at_mid.text(6));
            done = true;
        } else if (b.depth >= s.max_depth || r.boxes >= s.max_boxes || !(b.lo < mid && mid < b.hi)) {
            stop(proof_outcome::undecided, b, "not settled at depth " + std::to_string(b.depth) + ": margin " + value.text(6));
            done = true;
        } else {
            stack.push_back({mid, b.hi, b.depth + 1});
            stack.push_back({b.lo, mid, b.depth + 1});
        }
    }
    if (!done) r.outcome = proof_outcome::proved;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace normzoo::certify
