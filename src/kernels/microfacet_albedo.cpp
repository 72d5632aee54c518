// The microfacet albedo's three routes and the transmitting interface's (microfacet/albedo.hpp's directional_albedo), compiled
// once for the command and its tests (include/normzoo/detail/compiled_kernels.hpp declares them).
#include <normzoo/detail/compiled_kernels.hpp>

#define NORMZOO_DETAIL_DEFINE_FORM(Form) template NORMZOO_DETAIL_FORM_ALBEDO(Form)
#define NORMZOO_DETAIL_DEFINE_STRETCHED(D) template NORMZOO_DETAIL_STRETCHED_ALBEDO(D)
#define NORMZOO_DETAIL_DEFINE_AZIMUTHAL(D) template NORMZOO_DETAIL_AZIMUTHAL_ALBEDO(D)

namespace normzoo {
NORMZOO_DETAIL_DEFINE_FORM(microfacet::composition)
}  // namespace normzoo

namespace normzoo::microfacet {
template NORMZOO_DETAIL_ROUGH_DIELECTRIC_ALBEDO
}  // namespace normzoo::microfacet

namespace normzoo::microfacet::detail {
NORMZOO_POLAR_MAP_DISTRIBUTIONS(NORMZOO_DETAIL_DEFINE_STRETCHED)
NORMZOO_AZIMUTHAL_DISTRIBUTIONS(NORMZOO_DETAIL_DEFINE_AZIMUTHAL)
}  // namespace normzoo::microfacet::detail
