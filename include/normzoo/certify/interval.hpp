// Endpoint intervals [lo, hi] (MPFI, MPFR endpoints rounded outward) for the proofs of the
// Blinn-Phong bounds. Endpoints rather than Arb's midpoint-radius balls because 2^(-n/2) over
// a wide box, e.g. n in [4e6, 8e6], spans a million binary orders of magnitude: a ball of it
// must contain 0 and loses the sign, an interval keeps [2^-4e6, 2^-2e6] > 0 exactly.
// MPFR's exponent range (about 2^-1e9) holds 2^(-n/2) for every n up to 1e7.
#pragma once
#include <mpfi.h>
#include <mpfr.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace normzoo::certify {

class interval {
public:
    explicit interval(mpfr_prec_t prec = 128) { mpfi_init2(x_, prec); }
    interval(double v, mpfr_prec_t prec) : interval(prec) { mpfi_set_d(x_, v); }
    // [lo, hi], both exact doubles.
    interval(double lo, double hi, mpfr_prec_t prec) : interval(prec) { mpfi_interv_d(x_, lo, hi); }
    interval(const interval& o) : interval(mpfi_get_prec(o.x_)) { mpfi_set(x_, o.x_); }
    interval& operator=(const interval& o) {
        if (this != &o) {
            mpfi_set_prec(x_, mpfi_get_prec(o.x_));
            mpfi_set(x_, o.x_);
        }
        return *this;
    }
    ~interval() { mpfi_clear(x_); }

    // A decimal string, as an interval that holds it.
    static interval parse(const std::string& text, mpfr_prec_t prec) {
        interval r(prec);
        if (mpfi_set_str(r.x_, text.c_str(), 10) != 0) mpfi_interv_d(r.x_, -HUGE_VAL, HUGE_VAL);
        return r;
    }

    mpfi_ptr get() { return x_; }
    mpfi_srcptr get() const { return x_; }
    mpfr_prec_t prec() const { return mpfi_get_prec(x_); }

    bool positive() const { return !mpfi_nan_p(x_) && mpfi_is_strictly_pos(x_) > 0; }       // every point > 0
    bool nonpositive() const { return !mpfi_nan_p(x_) && mpfi_is_nonpos(x_) > 0; }          // every point <= 0
    // They share a point.
    bool overlaps(const interval& o) const {
        return !mpfi_nan_p(x_) && !mpfi_nan_p(o.x_) && mpfr_lessequal_p(&x_->left, &o.x_->right) &&
               mpfr_lessequal_p(&o.x_->left, &x_->right);
    }
    bool exact_zero() const { return !mpfi_nan_p(x_) && mpfi_is_zero(x_) > 0; }             // exactly {0}

    // "[lo, hi]" with `digits` significant digits, each end rounded outward.
    std::string text(int digits) const {
        return "[" + end(&x_->left, digits, MPFR_RNDD) + ", " + end(&x_->right, digits, MPFR_RNDU) + "]";
    }

private:
    static std::string end(mpfr_srcptr v, int digits, mpfr_rnd_t rnd) {
        char* s = nullptr;
        if (mpfr_asprintf(&s, "%.*R*e", digits - 1, rnd, v) < 0 || !s) return "?";
        std::unique_ptr<char, void (*)(char*)> hold(s, [](char* p) { mpfr_free_str(p); });
        return s;
    }
    mpfi_t x_;
};

#define NORMZOO_INTERVAL_OP(op, fn)                                                                  \
    inline interval operator op(const interval& a, const interval& b) {                             \
        interval r(a.prec() > b.prec() ? a.prec() : b.prec());                                      \
        fn(r.get(), a.get(), b.get());                                                              \
        return r;                                                                                   \
    }
NORMZOO_INTERVAL_OP(+, mpfi_add)
NORMZOO_INTERVAL_OP(-, mpfi_sub)
NORMZOO_INTERVAL_OP(*, mpfi_mul)
NORMZOO_INTERVAL_OP(/, mpfi_div)
#undef NORMZOO_INTERVAL_OP

inline interval operator-(const interval& a) { interval r(a.prec()); mpfi_neg(r.get(), a.get()); return r; }
inline interval operator+(const interval& a, long k) { interval r(a.prec()); mpfi_add_si(r.get(), a.get(), k); return r; }
inline interval operator+(long k, const interval& a) { return a + k; }
inline interval operator-(const interval& a, long k) { interval r(a.prec()); mpfi_sub_si(r.get(), a.get(), k); return r; }
inline interval operator-(long k, const interval& a) { interval r(a.prec()); mpfi_si_sub(r.get(), k, a.get()); return r; }
inline interval operator*(const interval& a, long k) { interval r(a.prec()); mpfi_mul_si(r.get(), a.get(), k); return r; }
inline interval operator*(long k, const interval& a) { return a * k; }
inline interval operator/(const interval& a, long k) { interval r(a.prec()); mpfi_div_si(r.get(), a.get(), k); return r; }

// 2^x, monotone: MPFI evaluates it at the endpoints, rounded outward.
inline interval exp2(const interval& x) { interval r(x.prec()); mpfi_exp2(r.get(), x.get()); return r; }
inline interval log_two(mpfr_prec_t prec) { interval r(prec); mpfi_const_log2(r.get()); return r; }

}  // namespace normzoo::certify
