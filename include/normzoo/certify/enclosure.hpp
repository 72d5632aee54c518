// Rigorous enclosures of the zoo integrals with Arb's acb_calc_integrate (Petras-style
// Gauss-Legendre on complex ellipses with rigorous error bounds, adaptive bisection):
//   I(n) = 2 pi * integral over t in [0, pi/2] of cos^n(alpha t) * weight(cos alpha t, sin alpha t)
// the reduced integrand of the zoo table, with the row's own templated weight() evaluated on
// complex balls. The result is a ball that provably contains I(n); 1/I(n) then contains the
// normalization.
//
// Holomorphy: the weights are polynomials in cos and sin (entire). cos^n is entire for an
// integer n; for any other n it is exp(n log cos) on the principal branch, which is analytic
// except where cos(alpha t) is real and <= 0. For alpha = 1 that happens at t = pi/2, the
// upper end. Arb's contract: when asked for an analytic evaluation (order 1), the integrand
// must return a non-finite ball if the input ball touches a point where it is not analytic;
// Arb then bisects towards that point and bounds the last small pieces directly (their part
// is below the tolerance). acb_pow_analytic does exactly that check on the branch cut.
#pragma once
#include <acb_calc.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "../decimal.hpp"
#include "../zoo/zoo_row.hpp"
#include "ball.hpp"

namespace normzoo::certify {

struct enclosure {
    ball integral;       // contains I(n)
    ball normalization;  // contains 1 / I(n)
    int status;          // ARB_CALC_SUCCESS, or not: then the ball is still rigorous, only wider
    double seconds;
};

struct enclosure_settings {
    slong prec = 168;        // working precision, bits (~50 digits)
    slong goal_bits = 140;   // relative accuracy asked of Arb: 2^-140 ~ 7e-43
    slong eval_limit = 0;    // 0: Arb's default budget
};

namespace detail {

template <class Row>
struct integrand_params {
    arb_struct n;      // the exponent: the decimal, in a ball when it has no binary expansion
    bool integer_n;    // cos^n is then entire
};

template <class Row>
int reduced_integrand(acb_ptr out, const acb_t t, void* param, slong order, slong prec) {
    const auto* p = static_cast<const integrand_params<Row>*>(param);
    if (order > 1) flint_abort();  // Arb asks at most for order 1 (holomorphy) here
    cball theta(t, prec);
    acb_mul_arb(theta.get(), theta.get(), ball(Row::lobe_alpha, prec).get(), prec);
    cball c(prec), s(prec);
    acb_sin_cos(s.get(), c.get(), theta.get(), prec);
    cball power(prec);
    if (!Row::has_exponent || arb_is_zero(&p->n)) {
        acb_one(power.get());
    } else {
        cball n(prec);
        acb_set_arb(n.get(), &p->n);
        // order 1: Arb needs holomorphy; an integer power is entire, else mind the cut.
        acb_pow_analytic(power.get(), c.get(), n.get(), order != 0 && !p->integer_n, prec);
        if (order == 0 && !acb_is_finite(power.get())) {
            // A direct bound on a piece that reaches t = pi/2, where cos takes 0 (and, in the
            // ball, values past it): on the path the integrand is the principal power, and
            // |c^n| = |c|^n for real n > 0, so the disk of radius max|c|^n holds it.
            arb_t m;
            arf_t top;
            arb_init(m);
            arf_init(top);
            acb_abs(m, c.get(), prec);
            arb_get_ubound_arf(top, m, prec);
            arb_set_arf(m, top);
            arb_pow(m, m, &p->n, prec);
            arf_clear(top);
            acb_zero(power.get());
            arb_add_error(acb_realref(power.get()), m);
            arb_add_error(acb_imagref(power.get()), m);
            arb_clear(m);
        }
    }
    const cball w = Row::weight(c, s);
    acb_mul(out, power.get(), w.get(), prec);
    return 0;
}

}  // namespace detail

// The reduced integral of Row at exponent n (ignored without an exponent), times 2 pi; a double
// n is taken as the number it holds.
// `magnitude` is a rough size of I(n) (any positive value within a few orders): it scales
// the absolute tolerance for the pieces near a branch point and does not affect rigour.
template <class Row>
enclosure enclose_zoo_integral(const decimal& n, double magnitude, const enclosure_settings& s = {}) {
    const auto start = std::chrono::steady_clock::now();
    const slong prec = s.prec;
    detail::integrand_params<Row> p;
    arb_init(&p.n);
    // The decimal exactly: a ball around it when it has no binary expansion.
    if (arb_set_str(&p.n, Row::has_exponent ? n.canonical().c_str() : "0", prec) != 0)
        throw std::invalid_argument("the exponent " + n.text() + " is not a number Arb reads");
    p.integer_n = arb_is_int(&p.n);
    acb_t a, b, result;
    acb_init(a);
    acb_init(b);
    acb_init(result);
    acb_zero(a);
    arb_const_pi(acb_realref(b), prec);
    arb_mul_2exp_si(acb_realref(b), acb_realref(b), -1);
    mag_t tol;
    mag_init(tol);
    mag_set_d(tol, magnitude);
    mag_mul_2exp_si(tol, tol, -s.goal_bits - 8);
    acb_calc_integrate_opt_t opt;
    acb_calc_integrate_opt_init(opt);
    if (s.eval_limit > 0) opt->eval_limit = s.eval_limit;
    const int status = acb_calc_integrate(result, detail::reduced_integrand<Row>, &p, a, b, s.goal_bits, tol, opt, prec);

    enclosure e{ball(prec), ball(prec), status, 0};
    // The integrand is real on the path: the real part holds I / (2 pi); the imaginary part's
    // ball holds 0 and is dropped.
    arb_set(e.integral.get(), acb_realref(result));
    e.integral = e.integral * pi_ball(prec) * 2;
    arb_inv(e.normalization.get(), e.integral.get(), prec);
    mag_clear(tol);
    acb_clear(a);
    acb_clear(b);
    acb_clear(result);
    arb_clear(&p.n);
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return e;
}

}  // namespace normzoo::certify
