// The directional albedo of every BRDF form of the registry, compiled once for the command and
// its tests (include/normzoo/detail/compiled_kernels.hpp declares them).
#include <normzoo/detail/compiled_kernels.hpp>

#define NORMZOO_DETAIL_DEFINE_FORM(Form) template NORMZOO_DETAIL_FORM_ALBEDO(Form)

namespace normzoo {
NORMZOO_BRDF_FORMS(NORMZOO_DETAIL_DEFINE_FORM)
}  // namespace normzoo
