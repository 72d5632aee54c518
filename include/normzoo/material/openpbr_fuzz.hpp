// OpenPBR Surface 1.1's fuzz lobe (docs/materials.md, "OpenPBR Surface 1.1"; the specification's
// section Fuzz): the model it recommends, Zeltner, Burley and Chiang 2022 ("Practical
// Multiple-Scattering Sheen Using Linearly Transformed Cosines"),
//   N.L f_fuzz(L, V) = fuzz_color E_fuzz(N.V, alpha) D(L | N.V, alpha),   alpha = fuzz_roughness,
// D a linearly transformed cosine (Heitz et al. 2016): in V's frame (x along V's tangential part),
// w_o = M^-1 L = (a L.x + b L.z, a L.y, L.z) and D(L) = (w_o.z / pi) a^2 / |w_o|^4 (the cosine
// lobe w_o.z / pi times the Jacobian |M^-1| / |M^-1 L|^3, |M^-1| = a^2). M^-1 keeps z, so D is a
// density over the upper hemisphere whose integral is 1 by construction: the lobe's albedo is
// fuzz_color E_fuzz. a, b and E_fuzz are fits over (N.V, alpha): MaterialX's closed forms
// (libraries/pbrlib/genglsl/lib/mx_microfacet_sheen.glsl, mx_zeltner_sheen_dir_albedo,
// mx_zeltner_sheen_ltc_aInv, mx_zeltner_sheen_ltc_bInv: "a Gaussian fit to the directional albedo
// table" and rational fits of the matrix, adapted from the authors' tizian/ltc-sheen), restated
// here. E_fuzz is therefore the fit's value, a model definition, not the integral of a physical
// lobe: what normzoo checks exactly is D's normalization (ltc_normalization: 1 to its bound) and
// what the layering does with E_fuzz. The fits hold on alpha in [0.01, 1] (MaterialX clamps to it).
#pragma once
#include <cmath>
#include <limits>
#include <vector>

#include "../geometry.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/estimate.hpp"

namespace normzoo::material::openpbr_fuzz {

inline constexpr double min_alpha = 0.01;

// E_fuzz(x = N.V, y = alpha): a Gaussian in x with mean m(y), width s(y) and offset o(y).
inline double e_fuzz(double x, double y) {
    const double s = y * (0.0206607 + 1.58491 * y) / (0.0379424 + y * (1.32227 + y));
    const double m = y * (-0.193854 + y * (-1.14885 + y * (1.7932 - 0.95943 * y * y))) / (0.046391 + y);
    const double o = y * (0.000654023 + (-0.0207818 + 0.119681 * y) * y) / (1.26264 + y * (-1.92021 + y));
    const double z = (x - m) / s;
    return std::exp(-0.5 * z * z) / (s * std::sqrt(2 * pi<double>())) + o;
}
// The inverse matrix's entries a = aInv (x and y) and b = bInv (x from z).
inline double ltc_a(double x, double y) { return (2.58126 * x + 0.813703 * y) * y / (1 + 0.310327 * x * x + 2.60994 * x * y); }
inline double ltc_b(double x, double y) {
    return std::sqrt(1 - x) * (y - 1) * y * y * y / (0.0000254053 + 1.71228 * x - 1.71506 * x * y + 1.34174 * y * y);
}

// D at a direction w in V's frame (w.z = N.L > 0), given a and b: (w_o.z / pi) (a / |w_o|^2)^2.
inline double ltc_density(double wx, double wy, double wz, double a, double b) {
    if (!(wz > 0)) return 0;
    const double ox = a * wx + b * wz, oy = a * wy, len2 = ox * ox + oy * oy + wz * wz;
    const double q = a / len2;
    return wz / pi<double>() * q * q;
}

// L in V's frame: x along V's tangential part (any, at normal incidence), z the normal.
inline vec3<double> to_view_frame(const vec3<double>& l, const vec3<double>& v) {
    const double t = std::hypot(v.x(), v.y());
    const double cx = t > 0 ? v.x() / t : 1, cy = t > 0 ? v.y() / t : 0;
    return {l.x() * cx + l.y() * cy, -l.x() * cy + l.y() * cx, l.z()};
}

// The integral of D over the hemisphere, 2 int_0^1 d(N.L) int_0^pi dphi D (D is even in phi), by
// nested adaptive Gauss-Kronrod: D's mass sits within ~a of the horizon where a is small, so the
// outer panels start at breakpoints a 2^k. It is 1 by construction; its bound is the integrals'.
inline quadrature::estimate<double> ltc_normalization(double mu, double alpha, double tolerance = 1e-11) {
    const double a = ltc_a(mu, alpha), b = ltc_b(mu, alpha), eps = std::numeric_limits<double>::epsilon();
    const double p = pi<double>();
    const quadrature::adaptive_kronrod<double, 15> inner_rule(200), outer_rule(800);
    auto over_phi = [&](double u) {
        const double s = std::sqrt((1 - u) * (1 + u));
        auto d = [&](double phi) {
            const double v = 2 * ltc_density(s * std::cos(phi), s * std::sin(phi), u, a, b);
            return quadrature::estimate<double>{v, 32 * eps * v, 1};
        };
        return inner_rule.integrate(d, {0.0, p / 4, p / 2, p}, 0.0, 1e-13);
    };
    std::vector<double> breaks = {0.0};
    const double scale = a / std::sqrt(1 + b * b);
    for (double x = scale / 16; x < 1; x *= 2) breaks.push_back(x);
    breaks.push_back(1.0);
    return outer_rule.integrate(over_phi, breaks, tolerance, 0.0);
}

}  // namespace normzoo::material::openpbr_fuzz
