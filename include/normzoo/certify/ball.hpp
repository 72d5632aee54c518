// Arb's balls (midpoint-radius intervals) with value semantics, for the certified tables: the
// rigorous enclosures of the zoo integrals and the proofs of the Blinn-Phong bounds.
// Only these headers need Arb (libflint-arb); the rest of normzoo does not include them.
//
// Arithmetic takes its working precision (bits) from the left operand, so the rows' templated
// weight(c, s) and the bounds' margin forms evaluate on balls exactly as they are written.
#pragma once
#include <acb.h>
#include <arb.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <cmath>

namespace normzoo::certify {

// A real ball [mid +- rad].
class ball {
public:
    explicit ball(slong prec = 128) : prec_(prec) { arb_init(x_); }
    ball(double v, slong prec) : ball(prec) { arb_set_d(x_, v); }
    ball(const ball& o) : ball(o.prec_) { arb_set(x_, o.x_); }
    ball& operator=(const ball& o) {
        arb_set(x_, o.x_);
        prec_ = o.prec_;
        return *this;
    }
    ~ball() { arb_clear(x_); }

    // The closed interval [lo, hi] (both exactly representable doubles), rounded outward.
    static ball interval(double lo, double hi, slong prec) {
        ball b(prec);
        arf_t a, c;
        arf_init(a);
        arf_init(c);
        arf_set_d(a, lo);
        arf_set_d(c, hi);
        arb_set_interval_arf(b.x_, a, c, prec);
        arf_clear(a);
        arf_clear(c);
        return b;
    }
    // A decimal string, as a ball that contains it.
    static ball parse(const std::string& text, slong prec) {
        ball b(prec);
        if (arb_set_str(b.x_, text.c_str(), prec) != 0) arb_indeterminate(b.x_);
        return b;
    }

    arb_ptr get() { return x_; }
    arb_srcptr get() const { return x_; }
    slong prec() const { return prec_; }

    bool positive() const { return arb_is_positive(x_); }        // every point > 0
    bool negative() const { return arb_is_negative(x_); }        // every point < 0
    bool exact_zero() const { return arb_is_zero(x_); }          // exactly {0}
    bool finite() const { return arb_is_finite(x_); }
    bool contains(const ball& o) const { return arb_contains(x_, o.x_); }
    bool overlaps(const ball& o) const { return arb_overlaps(x_, o.x_); }
    double radius() const { return mag_get_d(arb_radref(x_)); }
    double mid_double() const { return arf_get_d(arb_midref(x_), ARF_RND_NEAR); }
    // The radius relative to |mid| (infinite when the ball contains 0).
    double rel_radius() const {
        const double m = std::abs(mid_double());
        return m > 0 ? radius() / m : HUGE_VAL;
    }

    // The midpoint to `digits` significant digits, and a radius that covers both the ball's own
    // radius and the rounding of that printed midpoint: [printed +- radius] holds the ball.
    std::pair<std::string, double> printed(slong digits) const {
        ball m(prec_);
        arf_set(arb_midref(m.x_), arb_midref(x_));
        std::unique_ptr<char, void (*)(void*)> s(arb_get_str(m.x_, digits, ARB_STR_NO_RADIUS), flint_free);
        const ball back = parse(s.get(), prec_ + 64);
        ball gap(prec_ + 64);
        arb_sub(gap.x_, back.x_, m.x_, prec_ + 64);
        arb_abs(gap.x_, gap.x_);
        mag_t bound;
        mag_init(bound);
        arb_get_mag(bound, gap.x_);   // an upper bound of |printed - mid|
        mag_add(bound, bound, arb_radref(x_));
        const double r = mag_get_d(bound);  // rounded up
        mag_clear(bound);
        return {s.get(), r};
    }
    // Arb's own "[mid +/- rad]" text, itself a rigorous statement.
    std::string text(slong digits) const {
        std::unique_ptr<char, void (*)(void*)> s(arb_get_str(x_, digits, 0), flint_free);
        return s.get();
    }

private:
    slong prec_;
    arb_t x_;
};

inline ball operator+(const ball& a, const ball& b) { ball r(a.prec()); arb_add(r.get(), a.get(), b.get(), a.prec()); return r; }
inline ball operator-(const ball& a, const ball& b) { ball r(a.prec()); arb_sub(r.get(), a.get(), b.get(), a.prec()); return r; }
inline ball operator*(const ball& a, const ball& b) { ball r(a.prec()); arb_mul(r.get(), a.get(), b.get(), a.prec()); return r; }
inline ball operator/(const ball& a, const ball& b) { ball r(a.prec()); arb_div(r.get(), a.get(), b.get(), a.prec()); return r; }
inline ball operator-(const ball& a) { ball r(a.prec()); arb_neg(r.get(), a.get()); return r; }
inline ball operator+(const ball& a, int k) { ball r(a.prec()); arb_add_si(r.get(), a.get(), k, a.prec()); return r; }
inline ball operator+(int k, const ball& a) { return a + k; }
inline ball operator-(const ball& a, int k) { return a + (-k); }
inline ball operator-(int k, const ball& a) { return -a + k; }
inline ball operator*(const ball& a, int k) { ball r(a.prec()); arb_mul_si(r.get(), a.get(), k, a.prec()); return r; }
inline ball operator*(int k, const ball& a) { return a * k; }
inline ball operator/(const ball& a, int k) { ball r(a.prec()); arb_div_si(r.get(), a.get(), k, a.prec()); return r; }

// 2^x
inline ball exp2(const ball& x) {
    ball r(x.prec()), two(2.0, x.prec());
    arb_pow(r.get(), two.get(), x.get(), x.prec());
    return r;
}
inline ball pi_ball(slong prec) { ball r(prec); arb_const_pi(r.get(), prec); return r; }

// A complex ball, for integrands on Arb's complex path.
class cball {
public:
    explicit cball(slong prec) : prec_(prec) { acb_init(z_); }
    cball(acb_srcptr z, slong prec) : cball(prec) { acb_set(z_, z); }
    cball(const cball& o) : cball(o.prec_) { acb_set(z_, o.z_); }
    cball& operator=(const cball& o) {
        acb_set(z_, o.z_);
        prec_ = o.prec_;
        return *this;
    }
    ~cball() { acb_clear(z_); }
    acb_ptr get() { return z_; }
    acb_srcptr get() const { return z_; }
    slong prec() const { return prec_; }

private:
    slong prec_;
    acb_t z_;
};

inline cball operator+(const cball& a, const cball& b) { cball r(a.prec()); acb_add(r.get(), a.get(), b.get(), a.prec()); return r; }
inline cball operator-(const cball& a, const cball& b) { cball r(a.prec()); acb_sub(r.get(), a.get(), b.get(), a.prec()); return r; }
inline cball operator*(const cball& a, const cball& b) { cball r(a.prec()); acb_mul(r.get(), a.get(), b.get(), a.prec()); return r; }
inline cball operator*(const cball& a, int k) { cball r(a.prec()); acb_mul_si(r.get(), a.get(), k, a.prec()); return r; }
inline cball operator*(int k, const cball& a) { return a * k; }

// Frees the thread's Arb caches (constants, tables): called by each worker before it ends, so
// that a thread's caches do not outlive it (LeakSanitizer would report them).
inline void release_thread_caches() { flint_cleanup(); }

}  // namespace normzoo::certify
