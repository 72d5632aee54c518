// The directional albedo at inputs typed as decimals (docs/conventions.md, "Inputs are
// decimals"): the incident angle formed from its decimal in binary128, and the bound a decimal
// parameter's rounding to double adds. Apart from albedo.hpp so that an engine's test, which
// passes doubles, does not parse the exact decimal arithmetic (bench/header_cost).
#pragma once
#include <cmath>
#include <limits>

#include "albedo.hpp"
#include "decimal.hpp"

namespace normzoo {

// At an incident angle typed in degrees (docs/conventions.md, "Inputs are decimals"): the
// direction is formed from the decimal in binary128, so cos t is that of the angle typed.
template <class Model>
quadrature::estimate<double> albedo(const decimal& theta_deg, double n, double specular = 1,
                                    const albedo_settings& s = {}, double roughness = 0) {
    return albedo<Model>(degrees_of<quad>(theta_deg), n, specular, s, roughness);
}

// Where albedo_input_rounding measures the slope at x_d: a relative step of 1e-6, up unless that
// passes `upper` (mu <= 1), else down. A sweep can compute what the albedo shares there once (the
// Kulla-Conty terms of microfacet/multiple_scattering.hpp).
inline double input_rounding_step(double xd, double upper = std::numeric_limits<double>::infinity()) {
    const double h = 1e-6 * std::abs(xd);
    return xd + h <= upper ? xd + h : xd - h;
}

// How far an albedo can move when an input x is computed at the double x_d, |x - x_d| <= delta:
// the slope measured over a relative step h = 1e-6 (both albedos with their bounds), doubled for
// its change over the step, times delta. `albedo_at(x)` is the albedo at the double x; 0 when
// delta is 0.
template <class AlbedoAt>
double albedo_input_rounding(const AlbedoAt& albedo_at, double xd, double delta, const quadrature::estimate<double>& at_x,
                             double upper = std::numeric_limits<double>::infinity()) {
    using std::abs;
    if (!(delta > 0) || xd == 0) return 0;
    const double moved_x = input_rounding_step(xd, upper);
    const auto moved = albedo_at(moved_x);
    const double slope = (abs(moved.value - at_x.value) + moved.abs_error + at_x.abs_error) / abs(moved_x - xd);
    return 2 * slope * delta;
}

// The same for a decimal parameter x rounded to the double nearest it: |x - x_d| <=
// x.rounding<double>() |x_d|; 0 when the double holds x exactly.
template <class AlbedoAt>
double albedo_input_rounding(const AlbedoAt& albedo_at, const decimal& x, const quadrature::estimate<double>& at_x) {
    using std::abs;
    const double xd = x.to<double>();
    return albedo_input_rounding(albedo_at, xd, x.rounding<double>() * abs(xd), at_x);
}

}  // namespace normzoo
