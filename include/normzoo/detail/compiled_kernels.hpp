// The heaviest kernels, compiled once instead of in every translation unit that uses them: the
// directional albedo of every BRDF form of the registry, the microfacet albedo's three routes and
// the transmitting interface's (microfacet/rough_dielectric.hpp)
// (docs/architecture.md, "The build"). With NORMZOO_COMPILED_KERNELS defined, registry.hpp and
// microfacet/albedo.hpp end with these explicit instantiation declarations, and a program links
// their definitions (the verify command and its tests: src/kernels/, the CMake target
// normzoo_kernels, which defines the macro for what links it). Without the macro, as in an
// engine's own test, the library stays header-only and nothing here is seen.
#pragma once
#include "../albedo.hpp"
#include "../microfacet/albedo.hpp"
#include "../microfacet/azimuthal_albedo.hpp"
#include "../registry.hpp"

// The signatures, once for the declarations here and the definitions in src/kernels/.
#define NORMZOO_DETAIL_FORM_ALBEDO(Form)                                                                 \
    quadrature::estimate<double> albedo<Form>(const degrees_angle<quad>&, double, double, const albedo_settings&, \
                                              double, const Form&);
#define NORMZOO_DETAIL_STRETCHED_ALBEDO(D)                                                               \
    quadrature::estimate<double> stretched_albedo<D, 15>(const composition&, double, double, double,      \
                                                         const albedo_settings&);
#define NORMZOO_DETAIL_AZIMUTHAL_ALBEDO(D)                                                               \
    quadrature::estimate<double> azimuthal_albedo<D>(const composition&, double, double, double, const albedo_settings&);
#define NORMZOO_DETAIL_ROUGH_DIELECTRIC_ALBEDO \
    rough_dielectric_albedo rough_dielectric_albedo_of<15>(double, double, double, double, std::size_t);

// The distributions each route takes (directional_albedo: has_polar_map, has_azimuthal_integral).
#define NORMZOO_POLAR_MAP_DISTRIBUTIONS(X) X(d_blinn_phong) X(d_beckmann) X(d_ggx) X(d_charlie)
#define NORMZOO_AZIMUTHAL_DISTRIBUTIONS(X) X(d_beckmann) X(d_ggx)

#define NORMZOO_DETAIL_EXTERN(signature) extern template signature
#define NORMZOO_DETAIL_EXTERN_FORM(Form) NORMZOO_DETAIL_EXTERN(NORMZOO_DETAIL_FORM_ALBEDO(Form))
#define NORMZOO_DETAIL_EXTERN_STRETCHED(D) NORMZOO_DETAIL_EXTERN(NORMZOO_DETAIL_STRETCHED_ALBEDO(D))
#define NORMZOO_DETAIL_EXTERN_AZIMUTHAL(D) NORMZOO_DETAIL_EXTERN(NORMZOO_DETAIL_AZIMUTHAL_ALBEDO(D))

namespace normzoo {
NORMZOO_BRDF_FORMS(NORMZOO_DETAIL_EXTERN_FORM)
NORMZOO_DETAIL_EXTERN_FORM(microfacet::composition)
}  // namespace normzoo

namespace normzoo::microfacet {
NORMZOO_DETAIL_EXTERN(NORMZOO_DETAIL_ROUGH_DIELECTRIC_ALBEDO)
}  // namespace normzoo::microfacet

namespace normzoo::microfacet::detail {
NORMZOO_POLAR_MAP_DISTRIBUTIONS(NORMZOO_DETAIL_EXTERN_STRETCHED)
NORMZOO_AZIMUTHAL_DISTRIBUTIONS(NORMZOO_DETAIL_EXTERN_AZIMUTHAL)
}  // namespace normzoo::microfacet::detail
