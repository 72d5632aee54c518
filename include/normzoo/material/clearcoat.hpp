// KHR_materials_clearcoat (docs/materials.md#khr_materials_clearcoat): a coat over the material,
//   coated = fresnel_coat(ior = 1.5, weight = clearcoat, base = material,
//                         layer = specular_brdf(alpha = clearcoatRoughness^2))
//          = (1 - clearcoat fr) material + clearcoat fr specular_brdf,
//   fr = f0 + (1 - f0) (1 - |N.V|)^5, f0 = ((1 - ior)/(1 + ior))^2 = 0.04,
// the Fresnel read at N.V, not V.H: the extension's "Implementation" section, so that the
// layering is energy conserving with a simple layering function (a weight constant over L).
// The coat's normal is the material's here (no clearcoatNormalTexture).
#pragma once
#include "../microfacet/fresnel.hpp"
#include "material.hpp"

namespace normzoo::material {

struct fresnel_coat {
    static constexpr const char* literature = "KHR_materials_clearcoat, \"Implementation\" (fresnel_coat); Schlick 1994";
    double weight;     // clearcoat
    double ior = 1.5;  // fixed by the extension, independent of KHR_materials_ior's
    double f0() const { return microfacet::f0_of_eta(ior); }
    // fr at N.V: Schlick's factor of |N.V|, as the extension writes it
    double fr(double nv) const {
        const double f = f0();
        return f + (1 - f) * schlick_weight(nv);
    }
    double layer(double nv) const { return weight * fr(nv); }
    double base(double nv) const { return 1 - weight * fr(nv); }
};

}  // namespace normzoo::material
