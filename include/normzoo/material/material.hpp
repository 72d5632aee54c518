// A material: the one BRDF concept (brdf/brdf.hpp) extended to lobes and the operators that
// layer them (docs/materials.md). A material is a small value type, as a form is:
//   id, literature            strings for tables and docs
//   parameters                its parameters declared (parameter.hpp; a colour has three
//                             components, a choice names its values)
//   lobe_ids                  its lobes, named ("diffuse", "specular", "metal"), in a fixed order
//   lobe_maps                 for each lobe, the map its albedo is integrated in (lobe_map):
//                             a microfacet lobe's own D, or the flat map of a smooth lobe
//   weights(c)                each lobe's RGB weight at the cosines c of a direction pair: the
//                             product of the layering operators above it (below)
//   lobe(i, c)                lobe i's scalar BRDF at c (D Vis of a microfacet lobe, 1/pi)
//   f(L, V)                   the whole, per channel: the sum over lobes of weight x lobe
//   in, set(i, j, x),         its inputs; number parameter i's component j, choice parameter i's
//   choose(i, c)              choice c (declaration order), as the command sets them
//   input_error(in)           why inputs the declared ranges let through are refused, or nullptr
// with albedo(m, mu, compensation, settings), compensation_error, claims_preservation and
// reciprocity_difference beside it, and one line in registry.hpp (the command's list of materials).
// So that the operators that read only V.H, N.L and N.V (the glTF core and its extensions: mix,
// fresnel_mix, conductor_fresnel, albedo scaling by a lobe's E, a coat's Fresnel on N.V) each
// stay one small type, and a new lobe (sheen with Charlie's D, a coat with its own roughness)
// adds one entry to lobe_ids and a map, without reshaping the integral (material/albedo.hpp).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "../geometry.hpp"
#include "../microfacet/fresnel.hpp"

namespace normzoo::material {

// A colour or a per-channel weight: linear RGB.
using rgb = std::array<double, 3>;

inline rgb grey(double x) { return {x, x, x}; }
inline rgb operator*(const rgb& a, const rgb& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }
inline rgb operator*(double s, const rgb& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline rgb operator+(const rgb& a, const rgb& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
// The glTF specification's max_value(color): a colour to the scalar that weights the base below
// a coloured layer (KHR_materials_specular), so that no channel's base gains from another's.
inline double max_value(const rgb& c) { return std::max({c[0], c[1], c[2]}); }

// The cosines of a direction pair (L, V) and their half vector H that every lobe and operator
// of the glTF family reads: N.L, N.V, N.H, V.H (= L.H).
struct cosines {
    double nl, nv, nh, vh;
};

// Schlick's Fresnel factor (1 - |V.H|)^5 (Schlick 1994), what the glTF operators interpolate by.
inline double schlick_weight(double vh) { return microfacet::detail::pow5(1 - std::abs(vh)); }

// mix(base, layer, weight) = (1 - weight) base + weight layer (glTF 2.0, Appendix B: the metal
// and the dielectric mixed by `metallic`).
struct mix {
    double weight;
    double base() const { return 1 - weight; }
    double layer() const { return weight; }
};

// fresnel_mix(f0_color, ior, weight, base, layer) (glTF 2.0, Appendix B, with the two arguments
// KHR_materials_specular adds): f0 = min(((1 - ior) / (1 + ior))^2 f0_color, 1),
// fr = f0 + (1 - f0) (1 - |V.H|)^5; the layer weighted by weight fr (per channel), the base by
// 1 - weight max_value(fr). ior = 1.5, f0_color = 1, weight = 1 is the core's dielectric
// (F0 = 0.04). The extension's dielectric_f0 = weight f0 and dielectric_f90 = weight.
struct fresnel_mix {
    rgb f0_color = grey(1);
    double ior = 1.5, weight = 1;

    // ((1 - ior) / (1 + ior))^2; ior = 0 gives 1, as the extension's conversion from
    // specular-glossiness asks.
    double f0_of_ior() const { return microfacet::f0_of_eta(ior); }
    rgb f0() const {
        const double r = f0_of_ior();
        return {std::min(r * f0_color[0], 1.0), std::min(r * f0_color[1], 1.0), std::min(r * f0_color[2], 1.0)};
    }
    rgb fr(double vh, const rgb& f0v) const {
        const double s = schlick_weight(vh);
        return {f0v[0] + (1 - f0v[0]) * s, f0v[1] + (1 - f0v[1]) * s, f0v[2] + (1 - f0v[2]) * s};
    }
    rgb layer(double vh, const rgb& f0v) const { return weight * fr(vh, f0v); }
    double base(double vh, const rgb& f0v) const { return 1 - weight * max_value(fr(vh, f0v)); }
};

// conductor_fresnel(f0, bsdf) = bsdf (f0 + (1 - f0) (1 - |V.H|)^5) (glTF 2.0, Appendix B: the
// metal, f0 = baseColor).
struct conductor_fresnel {
    rgb f0;
    rgb weight(double vh) const {
        const double s = schlick_weight(vh);
        return {f0[0] + (1 - f0[0]) * s, f0[1] + (1 - f0[1]) * s, f0[2] + (1 - f0[2]) * s};
    }
};

// Where a lobe's albedo is integrated (material/albedo.hpp): in the half vector, over GGX's
// polar map at roughness alpha, the map in which a GGX lobe's mass is flat. A microfacet lobe
// takes its own D (peaked: alpha its roughness); a smooth lobe (Lambert) takes GGX at alpha = 1,
// where D N.h = cos t / pi is a cosine density of h and the integrand is smooth.
struct lobe_map {
    double alpha;
    bool peaked;  // the lobe is GGX's D at alpha times a visibility (a microfacet lobe)
    bool by_nodes = true;  // albedo_by_nodes integrates it (not a sheen's Charlie lobe, nor a second alpha)
};

// The directions reciprocity is checked at (docs/materials.md, "Verdicts"): 8, polar angles 5 to
// 85 degrees, four azimuths.
inline std::vector<vec3<double>> reciprocity_directions() {
    const double deg = pi<double>() / 180;
    std::vector<vec3<double>> dirs;
    for (int i = 0; i < 8; ++i) dirs.push_back(direction<double>((5 + 80 * i / 7.0) * deg, (i % 4) * 97.0 * deg));
    return dirs;
}

// The largest relative difference of a channel, |f(a, b) - f(b, a)| / the larger of the two, over
// the pairs of n directions; f(a, b) is the material's f (rgb) at L = direction a, V = direction b.
template <class F>
double largest_reciprocity_difference(std::size_t n, const F& f) {
    double worst = 0;
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b) {
            const auto x = f(a, b), y = f(b, a);
            for (std::size_t ch = 0; ch < 3; ++ch) {
                const double scale = std::max(std::abs(x[ch]), std::abs(y[ch]));
                if (scale > 0) worst = std::max(worst, std::abs(x[ch] - y[ch]) / scale);
            }
        }
    return worst;
}

}  // namespace normzoo::material
