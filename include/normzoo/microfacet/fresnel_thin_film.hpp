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
// internal reflection into the film (n_f < n_o) gives 1. Usable by any material with a thin film.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>

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
inline std::array<double, 3> thin_film_sensitivity(double opd, const std::array<double, 3>& shift) {
    using fit = thin_film_sensitivity_fit;
    const double p = 2 * pi<double>() * opd * 1e-9;
    double xyz[3] = {0, 0, 0};
    for (int i = 0; i < 4; ++i) {
        const int k = fit::component[i];
        xyz[k] += fit::val[i] * std::sqrt(2 * pi<double>() * fit::var[i]) * std::cos(fit::pos[i] * p + shift[k]) *
                  std::exp(-fit::var[i] * p * p);
    }
    std::array<double, 3> rgb{};
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) rgb[r] += xyz_to_rec709[r][k] * xyz[k] / fit::norm;
    return rgb;
}

// A thin film: the outside medium's index, the film's, its thickness in nm.
struct thin_film {
    double outside_ior = 1, film_ior = 1.3, thickness = 400;
};

// The terms of the film's series at cos t1 (what thin_film_fresnel sums; the tests integrate
// the same series over wavelength): R12, T121, per channel R23 and the phase phi, and OPD (nm).
struct thin_film_terms {
    double r12 = 1, t121 = 0, opd = 0;
    std::array<double, 3> r23{}, phi{};
    bool total_reflection = true;
};

inline thin_film_terms thin_film_terms_at(const thin_film& film, const std::array<double, 3>& base_f0, double cos_t1) {
    const double n_o = film.outside_ior, n_f = film.film_ior;
    thin_film_terms t;
    const double sin2_t2 = (n_o / n_f) * (n_o / n_f) * (1 - cos_t1 * cos_t1);
    const double cos2_t2 = 1 - sin2_t2;
    if (cos2_t2 < 0) return t;
    t.total_reflection = false;
    const double cos_t2 = std::sqrt(cos2_t2);
    const double r0 = ((n_f - n_o) / (n_f + n_o)) * ((n_f - n_o) / (n_f + n_o));
    t.r12 = r0 + (1 - r0) * detail::pow5(1 - cos_t1);
    t.t121 = 1 - t.r12;
    t.opd = 2 * n_f * film.thickness * cos_t2;
    const double phi12 = n_f < n_o ? pi<double>() : 0.0;
    for (int k = 0; k < 3; ++k) {
        const double s = std::sqrt(base_f0[k] + 0.0001);  // the extension's guard against F0 = 1
        const double n_b = (1 + s) / (1 - s);
        const double r1 = ((n_b - n_f) / (n_b + n_f)) * ((n_b - n_f) / (n_b + n_f));
        t.r23[k] = r1 + (1 - r1) * detail::pow5(1 - cos_t2);
        t.phi[k] = (pi<double>() - phi12) + (n_b < n_f ? pi<double>() : 0.0);
    }
    return t;
}

// KHR_materials_iridescence's iridescent_fresnel(outside_ior, film_ior, base_f0, thickness) at
// cos t1, per channel. `regime`, where given, gets which of its clamps hold (3 bits a channel:
// R12 R23 below 1e-5, above 0.9999, I below 0; bit 9 total reflection): where it changes, F has
// a kink (material/albedo.hpp takes those as breakpoints).
inline std::array<double, 3> thin_film_fresnel(const thin_film& film, const std::array<double, 3>& base_f0, double cos_t1,
                                               unsigned* regime = nullptr) {
    const thin_film_terms t = thin_film_terms_at(film, base_f0, cos_t1);
    if (regime) *regime = t.total_reflection ? 1u << 9 : 0u;
    if (t.total_reflection) return {1, 1, 1};
    std::array<double, 3> i{}, c{};
    for (int k = 0; k < 3; ++k) {
        const double product = t.r12 * t.r23[k];
        if (regime) *regime |= (product < 1e-5 ? 1u : 0u) << (3 * k) | (product > 0.9999 ? 2u : 0u) << (3 * k);
        const double r123 = std::clamp(product, 1e-5, 0.9999);
        const double rs = t.t121 * t.t121 * t.r23[k] / (1 - r123);
        i[k] = t.r12 + rs;
        c[k] = rs - t.t121;
    }
    for (int m = 1; m <= 2; ++m) {
        const std::array<double, 3> s = thin_film_sensitivity(m * t.opd, {m * t.phi[0], m * t.phi[1], m * t.phi[2]});
        for (int k = 0; k < 3; ++k) {
            c[k] *= std::sqrt(std::clamp(t.r12 * t.r23[k], 1e-5, 0.9999));
            i[k] += c[k] * 2 * s[k];
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (regime && i[k] < 0) *regime |= 4u << (3 * k);
        i[k] = std::max(i[k], 0.0);
    }
    return i;
}

}  // namespace normzoo::microfacet
