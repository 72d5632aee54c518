// The shortcuts engines take instead of the split-sum pair (A, B) of split_sum.hpp (E = F0 A +
// F90 B), each written as engines write it (its constants, its order of operations, its number
// type), so that an engine's test can hold its own copy against the exact pair
// (docs/microfacet.md, "The shortcuts, measured"):
//   env_brdf_approx     a fit in the perceptual roughness r and mu    Karis 2014, after Lazarov 2013
//   lazarov_2013        a fit in gloss g and mu (Black Ops II)         Lazarov 2013
//   monte_carlo_baker   N samples of GGX at Hammersley points, float   Karis 2013; Filament's V
// Each names the composition whose exact pair it stands for (made_for: split_sum.hpp computes it)
// and the roughness alpha its input maps to; results/microfacet-shortcuts.md has their errors.
// The visibility shortcuts are G parts (masking.hpp: schlick-ggx, hammon, ...) and Schlick's
// Fresnel an F part (fresnel.hpp).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string_view>

namespace normzoo::microfacet {

// The pair a shortcut gives, in the type it computes in: E = F0 a + F90 b.
template <class T>
struct split_sum_pair {
    T a, b;
};

// Unreal's mobile environment BRDF: the pair as a fit in r, exactly as its shader writes it
// (four-wide constants, one exp2). The pair is the fit alone, before any saturate.
struct env_brdf_approx {
    static constexpr std::string_view id = "EnvBRDFApprox (Karis 2014)";
    static constexpr const char* formula =
        "v = r c0 + c1, c0 = (-1, -0.0275, -0.572, 0.022), c1 = (1, 0.0425, 1.04, -0.04); "
        "a004 = min(v0^2, 2^(-9.28 mu)) v0 + v1; (A, B) = (-1.04 a004 + v2, 1.04 a004 + v3)";
    static constexpr const char* literature =
        "Karis 2014, \"Physically Based Shading on Mobile\" (Unreal Engine blog), after Lazarov 2013";
    static constexpr const char* domain = "perceptual roughness r in [0, 1] (alpha = r^2), mu = N.V in [0, 1]";
    // Fitted to Unreal's G: Schlick-GGX with k = alpha/2 (Karis 2013).
    static constexpr std::string_view made_for = "ggx/schlick-ggx/schlick";
    static double alpha(double r) { return r * r; }
    static split_sum_pair<double> eval(double r, double mu) {
        const double c0[4] = {-1, -0.0275, -0.572, 0.022}, c1[4] = {1, 0.0425, 1.04, -0.04};
        double v[4];
        for (int i = 0; i < 4; ++i) v[i] = r * c0[i] + c1[i];
        const double a004 = std::min(v[0] * v[0], std::exp2(-9.28 * mu)) * v[0] + v[1];
        return {-1.04 * a004 + v[2], 1.04 * a004 + v[3]};
    }
};

// Black Ops II's environment BRDF (normalized Blinn-Phong of power 8192^g, Schlick's Smith
// visibility with k = 2 / sqrt(pi (n + 2)), Schlick's Fresnel) as a fit in gloss g. The shader
// returns saturate(a0 + F0 (a1 - a0)), which is F0 A + B with A = a1 - a0, B = a0: the pair here
// is the fit before its saturate. Its a1 does not depend on mu, so it holds only for glossy
// surfaces away from grazing (docs/microfacet.md, "The shortcuts, measured").
struct lazarov_2013 {
    static constexpr std::string_view id = "Lazarov 2013 (Black Ops II)";
    static constexpr const char* formula =
        "a0 = g/0.96 min(0.475 g, 2^(-9.28 mu)) + (0.0275 - 0.25 0.04)/0.96 g + (0.015 - 0.75 0.04)/0.96, "
        "a1 = 0.25 g + 0.75; (A, B) = (a1 - a0, a0)";
    static constexpr const char* literature =
        "Lazarov 2013, \"Getting More Physical in Call of Duty: Black Ops II\" (SIGGRAPH 2013 course "
        "Physically Based Shading in Theory and Practice)";
    static constexpr const char* domain = "gloss g in [0, 1] (Blinn-Phong power 8192^g), mu = N.V in [0, 1]";
    // Schlick-Beckmann's k = alpha sqrt(2/pi) is Lazarov's 2 / sqrt(pi (n + 2)) at n = 2/alpha^2 - 2.
    static constexpr std::string_view made_for = "blinn-phong/schlick-beckmann/schlick";
    // The roughness of gloss g: the power 8192^g is n = 2/alpha^2 - 2.
    static double alpha(double gloss) { return std::sqrt(2 / (std::pow(8192.0, gloss) + 2)); }
    static split_sum_pair<double> eval(double gloss, double mu) {
        const double tx = gloss / 0.96, ty = 0.475 * gloss;
        const double tz = (0.0275 - 0.25 * 0.04) / 0.96 * gloss + (0.015 - 0.75 * 0.04) / 0.96, tw = 0.25 * gloss + 0.75;
        const double a0 = tx * std::min(ty, std::exp2(-9.28 * mu)) + tz, a1 = tw;
        return {a1 - a0, a0};
    }
};

namespace detail {

// The base-2 radical inverse of i in 32 bits, i's bits reversed (the Hammersley() of Karis 2013).
inline std::uint32_t reverse_bits(std::uint32_t bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return bits;
}

// Height-correlated Smith visibility V = G / (4 N.L N.V) of GGX, a2 = alpha^2, as Filament's
// documentation writes it (after Heitz 2014).
inline float v_smith_ggx_correlated(float nv, float nl, float a2) {
    return 0.5f / (nv * std::sqrt(nl * nl * (1 - a2) + a2) + nl * std::sqrt(nv * nv * (1 - a2) + a2));
}

}  // namespace detail

// The pair as engines bake it: IntegrateBRDF's loop, N half vectors h from GGX's distribution at
// the Hammersley points (i/N, radical inverse of i), each weighted by G_vis = 4 V N.L (V.h) / (N.h)
// and split by Schlick's Fc = (1 - V.h)^5, in float. Its error is the quadrature's, falling
// about as N^-0.55 at grazing mu (docs/microfacet.md).
struct monte_carlo_baker {
    static constexpr std::string_view id = "Monte Carlo baker, GGX sampling at Hammersley points, float";
    static constexpr const char* formula =
        "(A, B) = 1/N sum over i of ((1 - Fc) G_vis, Fc G_vis), h_i GGX-sampled at (i/N, radical inverse of i)";
    static constexpr const char* literature =
        "Karis 2013, \"Real Shading in Unreal Engine 4\" (IntegrateBRDF); Walter et al. 2007 (GGX sampling); "
        "Filament's documentation, Guy and Agopian (height-correlated V, after Heitz 2014)";
    static constexpr const char* domain = "perceptual roughness r in (0, 1] (alpha = r^2), mu = N.V in (0, 1], N >= 1";
    static constexpr std::string_view made_for = "ggx/smith-height-correlated/schlick";
    static float alpha(float r) { return r * r; }
    static split_sum_pair<float> eval(float r, float mu, unsigned samples) {
        const float alpha = r * r, a2 = alpha * alpha;
        const float vx = std::sqrt(1.0f - mu * mu), vz = mu;
        float a = 0, b = 0;
        for (unsigned i = 0; i < samples; ++i) {
            const float u1 = float(i) / float(samples), u2 = float(detail::reverse_bits(i)) * 2.3283064365386963e-10f;
            // GGX importance sampling of h (Walter et al. 2007; Karis 2013)
            const float phi = 6.2831853f * u1;
            const float cos_t = std::sqrt((1 - u2) / (1 + (a2 - 1) * u2)), sin_t = std::sqrt(1 - cos_t * cos_t);
            const float hx = sin_t * std::cos(phi), hz = cos_t;
            const float vh = vx * hx + vz * hz;
            const float lz = 2 * vh * hz - vz;
            const float nl = std::min(std::max(lz, 0.0f), 1.0f), nh = std::min(std::max(hz, 0.0f), 1.0f);
            const float vhc = std::min(std::max(vh, 0.0f), 1.0f);
            if (nl > 0) {
                const float g_vis = detail::v_smith_ggx_correlated(mu, nl, a2) * 4 * nl * vhc / nh;
                const float x = 1 - vhc, fc = x * x * x * x * x;
                a += (1 - fc) * g_vis;
                b += fc * g_vis;
            }
        }
        return {a / float(samples), b / float(samples)};
    }
};

}  // namespace normzoo::microfacet
