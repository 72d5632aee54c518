// The polar map of Blinn-Phong's normalized lobe (n+2)/(2 pi) (N.m)^n (N.m) d(omega_m): the
// polar angle t of m below which the lobe holds the mass sin^2 psi. With 1 - cos^(n+2) t =
// sin^2 psi, cos t = cos(psi)^(2/(n+2)). Apart from distribution.hpp so that the albedo of the
// Blinn-Phong forms (brdf/, albedo.hpp) can integrate in it without the other distributions.
#pragma once
#include <cmath>

namespace normzoo::microfacet {

// cos t and sin t at psi: ln cos psi from sin^2 psi below 45 degrees (1 - cos psi would lose
// digits there), and t's 1 - cos t likewise.
template <class T>
void blinn_phong_polar(const T& psi, const T& n, T& c, T& s) {
    using std::cos; using std::exp; using std::expm1; using std::log; using std::log1p; using std::sin; using std::sqrt;
    const T e = 2 / (n + 2), sp = sin(psi);
    const T lc = psi < T(0.785) ? log1p(-sp * sp) / 2 : log(cos(psi));
    c = exp(e * lc), s = sqrt(-expm1(2 * e * lc));
}

// psi at the polar angle t: the inverse of blinn_phong_polar.
template <class T>
T blinn_phong_theta_to_psi(const T& t, const T& n) {
    using std::asin; using std::cos; using std::expm1; using std::log; using std::log1p; using std::sin; using std::sqrt;
    const T st = sin(t), lc = t < T(0.785) ? log1p(-st * st) / 2 : log(cos(t));
    return asin(sqrt(-expm1((n + 2) * lc)));
}

// The same map as a lobe type of the albedo integral in the lobe's mass (stretched.hpp), whose
// parameter is the exponent n itself.
struct blinn_phong_lobe {
    static void polar(double psi, double n, double& c, double& s) { blinn_phong_polar(psi, n, c, s); }
    static double theta_to_psi(double t, double n) { return blinn_phong_theta_to_psi(t, n); }
};

}  // namespace normzoo::microfacet
