// The Fresnel reflectance of a thin dielectric film over a base, integrated over the visible
// spectrum in closed form (docs/materials.md, "KHR_materials_iridescence"): Belcour and Barla
// 2017, "A Practical Extension to Microfacet Theory for the Modeling of Varying Iridescence",
// section 4 (the Airy reflectance as a Fourier series in the phase, each term integrated against
// the colour-matching functions fitted by Gaussians in wavenumber), in the approximation the glTF
// extension KHR_materials_iridescence gives (KhronosGroup/glTF,
// extensions/2.0/Khronos/KHR_materials_iridescence/README.md, "Iridescence Fresnel"):
//   R12 = Schlick(((n_f - n_o) / (n_f + n_o))^2, cos t1),   T121 = 1 - R12,
//   n_b = (1 + sqrt(F0 + 1e-4)) / (1 - sqrt(F0 + 1e-4))     the base's index from its F0, per channel
//   R23 = Schlick(((n_b - n_f) / (n_b + n_f))^2, cos t2),   cos^2 t2 = 1 - (n_o / n_f)^2 (1 - cos^2 t1)
//   OPD = 2 n_f d cos t2;  phases 0 or pi by the order of the indices, phi = phi21 + phi23
//   R123 = clamp(R12 R23, 1e-5, 0.9999),  Rs = T121^2 R23 / (1 - R123)
//   I = R12 + Rs + sum over m = 1, 2 of (Rs - T121) R123^(m/2) 2 S(m OPD, m phi),  F = max(I, 0)
// S the sensitivities' Fourier transform (sensitivity below), XYZ to linear Rec. 709. Total
// internal reflection into the film (n_f < n_o) gives 1. Usable by any material with a thin film;
// the base's index from F0 either as the extension writes it (above) or as MaterialX's Airy
// Fresnel takes it, n_b from sqrt(clamp(F0, 0.01, 0.99)) (film_base). The formula is ill-conditioned
// where F0 nears 1 under the extension's guard (1 - sqrt(F0 + 1e-4) cancels) and where R12 R23
// nears its clamp 0.9999 (1/(1 - R123)): thin_film_rounding estimates what double's rounding
// moves, from the same formula in extended precision.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "../geometry.hpp"
#include "fresnel.hpp"

namespace normzoo::microfacet {

// XYZ to linear Rec. 709 (sRGB primaries, D65), rows, as the extension gives it.
inline constexpr double xyz_to_rec709[3][3] = {
    {3.2404542, -1.5371385, -0.4985314}, {-0.9692660, 1.8760108, 0.0415560}, {0.0556434, -0.2040259, 1.0572252}};

// The colour-matching functions as Gaussians in wavenumber nu (1/m): component k is
// val_k / sqrt(2) exp(-(nu - pos_k)^2 / (4 var_k)), X with a second lobe (the last entry); the
// sum is divided by norm. Their Fourier transforms at phase p = 2 pi OPD (OPD in m) are
// val sqrt(2 pi var) cos(pos p + shift) exp(-var p^2) (the extension's constants).
struct thin_film_sensitivity_fit {
    static constexpr double val[4] = {5.4856e-13, 4.4201e-13, 5.2481e-13, 9.7470e-14};
    static constexpr double pos[4] = {1.6810e+06, 1.7953e+06, 2.2084e+06, 2.2399e+06};
    static constexpr double var[4] = {4.3278e+09, 9.3046e+09, 6.6121e+09, 4.5282e+09};
    static constexpr double norm = 1.0685e-7;
    static constexpr int component[4] = {0, 1, 2, 0};  // X, Y, Z, X
};

// The sensitivities' transform at optical path difference opd (nm), phase shifts per XYZ
// component (the extension applies its RGB phases to X, Y, Z in order), in linear Rec. 709.
template <class T = double>
std::array<T, 3> thin_film_sensitivity(T opd, const std::array<T, 3>& shift) {
    using fit = thin_film_sensitivity_fit;
    using std::cos;
    using std::exp;
    using std::sqrt;
    const T p = 2 * pi<T>() * opd * T(1e-9);
    T xyz[3] = {0, 0, 0};
    for (int i = 0; i < 4; ++i) {
        const int k = fit::component[i];
        const T var = fit::var[i], pos = fit::pos[i];
        xyz[k] += T(fit::val[i]) * sqrt(2 * pi<T>() * var) * cos(pos * p + shift[k]) * exp(-var * p * p);
    }
    std::array<T, 3> rgb{};
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) rgb[r] += T(xyz_to_rec709[r][k]) * xyz[k] / T(fit::norm);
    return rgb;
}

// How the base's index follows from its F0: KHR_materials_iridescence's n_b = (1 + s)/(1 - s),
// s = sqrt(F0 + 1e-4) (a guard against F0 = 1 that puts F0 >= 0.9999 at a negative index, where
// R23 > 1), or MaterialX's mx_f0_to_ior, s = sqrt(clamp(F0, 0.01, 0.99))
// (AcademySoftwareFoundation/MaterialX, libraries/pbrlib/genglsl/lib/mx_microfacet_specular.glsl).
enum class film_base { f0_guard, f0_clamped };

// A thin film: the outside medium's index, the film's, its thickness in nm, and how the base's
// index follows from its F0.
struct thin_film {
    double outside_ior = 1, film_ior = 1.3, thickness = 400;
    film_base base = film_base::f0_guard;
};

// The terms of the film's series at cos t1 (what thin_film_fresnel sums; the tests integrate
// the same series over wavelength): R12, T121, per channel R23 and the phase phi, and OPD (nm).
template <class T = double>
struct basic_thin_film_terms {
    T r12 = 1, t121 = 0, opd = 0;
    std::array<T, 3> r23{}, phi{};
    bool total_reflection = true;
};
using thin_film_terms = basic_thin_film_terms<double>;

template <class T = double>
basic_thin_film_terms<T> thin_film_terms_at(const thin_film& film, const std::array<double, 3>& base_f0, T cos_t1) {
    using std::sqrt;
    const T n_o = film.outside_ior, n_f = film.film_ior;
    basic_thin_film_terms<T> t;
    const T sin2_t2 = (n_o / n_f) * (n_o / n_f) * (1 - cos_t1 * cos_t1);
    const T cos2_t2 = 1 - sin2_t2;
    if (cos2_t2 < 0) return t;
    t.total_reflection = false;
    const T cos_t2 = sqrt(cos2_t2);
    const T r0 = ((n_f - n_o) / (n_f + n_o)) * ((n_f - n_o) / (n_f + n_o));
    t.r12 = r0 + (1 - r0) * detail::pow5(1 - cos_t1);
    t.t121 = 1 - t.r12;
    t.opd = 2 * n_f * T(film.thickness) * cos_t2;
    const T phi12 = n_f < n_o ? pi<T>() : T(0);
    for (int k = 0; k < 3; ++k) {
        const T f0 = base_f0[k];
        const T s = film.base == film_base::f0_guard ? sqrt(f0 + T(0.0001)) : sqrt(std::clamp(f0, T(0.01), T(0.99)));
        const T n_b = (1 + s) / (1 - s);
        const T r1 = ((n_b - n_f) / (n_b + n_f)) * ((n_b - n_f) / (n_b + n_f));
        t.r23[k] = r1 + (1 - r1) * detail::pow5(1 - cos_t2);
        t.phi[k] = (pi<T>() - phi12) + (n_b < n_f ? pi<T>() : T(0));
    }
    return t;
}

// KHR_materials_iridescence's iridescent_fresnel(outside_ior, film_ior, base_f0, thickness) at
// cos t1, per channel. `regime`, where given, gets which of its clamps hold (3 bits a channel:
// R12 R23 below 1e-5, above 0.9999, I below 0; bit 9 total reflection): where it changes, F has
// a kink (material/albedo.hpp takes those as breakpoints).
template <class T = double>
std::array<T, 3> thin_film_fresnel(const thin_film& film, const std::array<double, 3>& base_f0, T cos_t1,
                                   unsigned* regime = nullptr) {
    using std::sqrt;
    const basic_thin_film_terms<T> t = thin_film_terms_at(film, base_f0, cos_t1);
    if (regime) *regime = t.total_reflection ? 1u << 9 : 0u;
    if (t.total_reflection) return {1, 1, 1};
    const T lo = T(1e-5), hi = T(0.9999);
    std::array<T, 3> i{}, c{};
    for (int k = 0; k < 3; ++k) {
        const T product = t.r12 * t.r23[k];
        if (regime) *regime |= (product < lo ? 1u : 0u) << (3 * k) | (product > hi ? 2u : 0u) << (3 * k);
        const T r123 = std::clamp(product, lo, hi);
        const T rs = t.t121 * t.t121 * t.r23[k] / (1 - r123);
        i[k] = t.r12 + rs;
        c[k] = rs - t.t121;
    }
    for (int m = 1; m <= 2; ++m) {
        const std::array<T, 3> s = thin_film_sensitivity<T>(m * t.opd, {m * t.phi[0], m * t.phi[1], m * t.phi[2]});
        for (int k = 0; k < 3; ++k) {
            c[k] *= sqrt(std::clamp(t.r12 * t.r23[k], lo, hi));
            i[k] += c[k] * 2 * s[k];
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (regime && i[k] < 0) *regime |= 4u << (3 * k);
        i[k] = std::max(i[k], T(0));
    }
    return i;
}

// What rounding to double can move thin_film_fresnel at cos t1, per channel: 4 times its
// difference from the same formula in x87 extended precision (64-bit significand, whose own
// rounding is 2^-11 of double's at the same conditioning), plus 64 eps of the value. Where the
// formula is well conditioned this is a few eps; it grows where the film makes it ill-conditioned
// (above).
inline std::array<double, 3> thin_film_rounding(const thin_film& film, const std::array<double, 3>& base_f0, double cos_t1) {
    const std::array<double, 3> d = thin_film_fresnel<double>(film, base_f0, cos_t1);
    const std::array<long double, 3> x = thin_film_fresnel<long double>(film, base_f0, cos_t1);
    std::array<double, 3> out{};
    for (int k = 0; k < 3; ++k)
        out[k] = 4 * double(std::abs(x[k] - (long double)d[k])) + 64 * std::numeric_limits<double>::epsilon() * std::max(1.0, d[k]);
    return out;
}

}  // namespace normzoo::microfacet
