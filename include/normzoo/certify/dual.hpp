// Forward-mode derivatives over intervals: a value and its derivative in n, each a rigorous interval.
// Evaluating a margin form on dual(box, 1) encloses the margin's derivative on the whole box,
// what the monotonicity step of the proofs needs near n = 0.
#pragma once
#include "interval.hpp"

namespace normzoo::certify {

struct dual {
    interval v;  // value
    interval d;  // derivative with respect to n
};

inline dual operator+(const dual& a, const dual& b) { return {a.v + b.v, a.d + b.d}; }
inline dual operator-(const dual& a, const dual& b) { return {a.v - b.v, a.d - b.d}; }
inline dual operator-(const dual& a) { return {-a.v, -a.d}; }
inline dual operator*(const dual& a, const dual& b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }
inline dual operator/(const dual& a, const dual& b) { return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)}; }
inline dual operator+(const dual& a, long k) { return {a.v + k, a.d}; }
inline dual operator+(long k, const dual& a) { return a + k; }
inline dual operator-(const dual& a, long k) { return {a.v - k, a.d}; }
inline dual operator-(long k, const dual& a) { return {k - a.v, -a.d}; }
inline dual operator*(const dual& a, long k) { return {a.v * k, a.d * k}; }
inline dual operator*(long k, const dual& a) { return a * k; }
inline dual operator/(const dual& a, long k) { return {a.v / k, a.d / k}; }

// d/dn 2^x = 2^x ln 2 dx/dn
inline dual exp2(const dual& x) {
    const interval p = exp2(x.v);
    return {p, p * log_two(x.v.prec()) * x.d};
}

}  // namespace normzoo::certify
