// KHR_materials_anisotropy (docs/materials.md, "KHR_materials_anisotropy"): specular_brdf with
// anisotropic GGX (KhronosGroup/glTF, extensions/2.0/Khronos/KHR_materials_anisotropy/README.md):
//   alpha_t = mix(alpha, 1, anisotropyStrength^2) along the anisotropy direction,
//   alpha_b = alpha across it, alpha = roughness^2;
//   D = 1 / (pi alpha_t alpha_b ((h.t / alpha_t)^2 + (h.b / alpha_b)^2 + (h.n)^2)^2)   (Burley 2012)
// and Smith's G with GGX's anisotropic Lambda, Lambda(w) = (sqrt(1 + (alpha_t^2 (w.t)^2 +
// alpha_b^2 (w.b)^2) / (w.n)^2) - 1) / 2 (Heitz 2014, section 5), in the material's form: the
// extension's V_GGX_anisotropic, 0.5 / (N.L |(alpha_t T.V, alpha_b B.V, N.V)| + N.V |(alpha_t
// T.L, alpha_b B.L, N.L)|), is the height-correlated one, 1 / (4 N.L N.V (1 + Lambda_L +
// Lambda_V)) (`masking=smith-height-correlated`); the separable form takes the same Lambda. The
// direction t is at anisotropyRotation (radians) from the tangent x, toward the bitangent y; V
// lies in the x-z plane, so the rotation turns V's azimuth about the anisotropy direction. At
// strength 0 this is specular_brdf itself (alpha_t = alpha_b), evaluated as the core evaluates it.
#pragma once
#include <cmath>
#include <type_traits>

#include "../microfacet/d_ggx_aniso.hpp"
#include "lobes.hpp"

namespace normzoo::material {

struct anisotropic_specular_brdf {
    specular_brdf iso;        // at the material's alpha and masking form
    double alpha_t, alpha_b;  // along the anisotropy direction and across it
    double cos_r = 1, sin_r = 0;

    anisotropic_specular_brdf(const specular_brdf& s, double strength, double rotation)
        : iso(s), alpha_t(s.alpha + (1 - s.alpha) * strength * strength), alpha_b(s.alpha),
          cos_r(std::cos(rotation)), sin_r(std::sin(rotation)) {}

    bool anisotropic() const { return alpha_t != alpha_b; }
    // w in the frame (t, b, N) of the anisotropy direction
    vec3<double> in_frame(const vec3<double>& w) const {
        return {w.x() * cos_r + w.y() * sin_r, -w.x() * sin_r + w.y() * cos_r, w.z()};
    }
    microfacet::ndf_params<double> np() const {
        microfacet::ndf_params<double> p;
        p.alpha_x = alpha_t, p.alpha_y = alpha_b;
        return p;
    }
    double lambda(const vec3<double>& w) const {
        return anisotropic() ? microfacet::d_ggx_aniso::lambda(in_frame(w), np()) : iso.lambda(w);
    }
    double g(double lambda_l, double lambda_v) const { return iso.g(lambda_l, lambda_v); }
    double d(const vec3<double>& h) const { return anisotropic() ? microfacet::d_ggx_aniso::d(in_frame(h), np()) : iso.d(h); }
    // V D at unit L, V with N.L, N.V > 0 and h their half vector.
    double value(const vec3<double>& l, const vec3<double>& v, const vec3<double>& h) const {
        return d(h) * g(lambda(l), lambda(v)) / (4 * l.z() * v.z());
    }
};

// Whether a material's specular lobe may be anisotropic (material/albedo.hpp then integrates its
// peaked lobes in the anisotropic map, microfacet/stretched_aniso.hpp).
template <class Lobe>
constexpr bool may_be_anisotropic = std::is_same_v<Lobe, anisotropic_specular_brdf>;

}  // namespace normzoo::material
