// KHR_materials_iridescence (docs/materials.md, "KHR_materials_iridescence"): a thin film over
// the metal and the dielectric, its Fresnel that of Belcour and Barla 2017 as the extension
// gives it (microfacet/fresnel_thin_film.hpp), mixed into each Fresnel by `iridescence`
// (KhronosGroup/glTF, extensions/2.0/Khronos/KHR_materials_iridescence/README.md, "Iridescence
// BRDF" and its implementation notes):
//   metal       mix(conductor_fresnel(baseColor), F_film(F0 = baseColor), iridescence)
//   dielectric  rgb_mix(base, specular_brdf, a),  a = mix(specular fr, F_film(F0 = specular f0), iridescence),
//               rgb_mix(base, layer, a) = (1 - max_value(a)) base + a layer
// with f0 = min(F0(ior) specularColor, 1) and fr = Schlick(f0, 1, V.H) (KHR_materials_specular),
// the film in air (outside_ior 1), of index iridescenceIor and thickness iridescenceThickness
// (nm): the value the extension's thickness texture would give (with no texture, its
// iridescenceThicknessMaximum). The film's angle is V.H, the angle at the microfacet that the
// Fresnel it replaces reads (the extension says "the viewing angle"; the glTF Sample Renderer
// takes N.V once per pixel). A film of thickness 0 is no film: the material is then the core, as
// in the Sample Renderer (the extension's formula at d -> 0 does not reduce to the base's
// Fresnel: docs/materials.md).
#pragma once
#include <algorithm>
#include <array>
#include <vector>

#include "../microfacet/fresnel_thin_film.hpp"
#include "material.hpp"

namespace normzoo::material {

struct iridescence_layer {
    double weight = 0;  // iridescence, in [0, 1]
    microfacet::thin_film film;

    // Whether the film changes the material: a weight above 0 and a film of some thickness.
    bool active() const { return weight > 0 && film.thickness > 0; }

    // The values of V.H in (0, 1) where the weights `weights(vh)` of a material with this film
    // have kinks: where the clamps of the film's Fresnel at the F0s `f0s` change (regime), or the
    // largest channel of `largest_of(vh)` (the dielectric's layer weight, whose largest channel
    // weights the base) does; on a grid of 4096 and bisected to full precision, ascending. A
    // kink closer than 1/4096 to another of the same kind may be missed (docs/materials.md).
    template <class LargestOf>
    std::vector<double> kinks(const std::array<rgb, 2>& f0s, const LargestOf& largest_of) const {
        auto state = [&](double vh) {
            unsigned key = 0;
            for (std::size_t j = 0; j < f0s.size(); ++j) {
                unsigned r = 0;
                microfacet::thin_film_fresnel(film, f0s[j], vh, &r);
                key |= r << (10 * j);
            }
            const rgb a = largest_of(vh);
            const unsigned top = a[0] >= a[1] && a[0] >= a[2] ? 0 : a[1] >= a[2] ? 1 : 2;
            return key | top << 20;
        };
        std::vector<double> out;
        const int n = 4096;
        unsigned before = state(0.5 / n);
        for (int i = 1; i <= n; ++i) {
            double lo = (i - 0.5) / n, hi = std::min(1.0, (i + 0.5) / n);
            const unsigned after = state(hi);
            if (after == before) continue;
            for (int j = 0; j < 60; ++j) {
                const double mid = (lo + hi) / 2;
                (state(mid) == before ? lo : hi) = mid;
            }
            out.push_back(lo);
            before = after;
        }
        return out;
    }

    static rgb lerp(const rgb& a, const rgb& b, double t) {
        return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
    }
    // The metal's Fresnel at V.H = vh: `schlick` (conductor_fresnel's) mixed with the film's at F0 = baseColor.
    rgb metal(double vh, const rgb& schlick, const rgb& base_color) const {
        return lerp(schlick, microfacet::thin_film_fresnel(film, base_color, vh), weight);
    }
    // The dielectric's layer weight a at V.H = vh: its `layer` (specular fr) mixed with the
    // film's at F0 = specular f0; the base's weight is then 1 - max_value(a).
    rgb dielectric(double vh, const rgb& layer, const rgb& specular_f0) const {
        return lerp(layer, microfacet::thin_film_fresnel(film, specular_f0, vh), weight);
    }
    // What rounding moves the film's part of metal() or dielectric() at F0 = f0, per channel
    // (microfacet::thin_film_rounding): the weights' bound where the film makes them ill-conditioned.
    rgb rounding(double vh, const rgb& f0) const { return weight * microfacet::thin_film_rounding(film, f0, vh); }
};

}  // namespace normzoo::material
