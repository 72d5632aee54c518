// The directional albedo at inputs typed as decimals (docs/conventions.md, "Inputs are
// decimals"): the incident angle formed from its decimal in binary128, and the bound a decimal
// parameter's rounding to double adds. Apart from albedo.hpp so that an engine's test, which
// passes doubles, does not parse the exact decimal arithmetic (bench/header_cost).
#pragma once
#include <cmath>

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

// How far an albedo can move when a decimal parameter x is rounded to the double x_d it is
// computed at: the slope measured over a relative step h = 1e-6 (both albedos with their
// bounds), doubled for its change over the step, times |x - x_d| <= x.rounding<double>() |x_d|.
// `albedo_at(x)` is the albedo at the double x; 0 when the double holds x exactly.
template <class AlbedoAt>
double albedo_input_rounding(const AlbedoAt& albedo_at, const decimal& x, const quadrature::estimate<double>& at_x) {
    using std::abs;
    const double rounding = x.rounding<double>();
    const double xd = x.to<double>();
    if (rounding == 0 || xd == 0) return 0;
    const double h = 1e-6;
    const auto moved = albedo_at(xd * (1 + h));
    const double slope = (abs(moved.value - at_x.value) + moved.abs_error + at_x.abs_error) / (h * abs(xd));
    return 2 * slope * rounding * abs(xd);
}

}  // namespace normzoo
