// The lobes of the glTF 2.0 material (its specification, Appendix B), each a small value type with
// its formula and literature: a material weights them by its operators (material.hpp).
//   diffuse_brdf            1/pi (the colour is the material's weight)         Lambert 1760
//   specular_brdf(alpha)    V D, V = G / (4 |N.L| |N.V|),                      Trowbridge and Reitz 1975;
//                           D = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2)   Walter et al. 2007
//     G separable           G1(L) G1(V), G1(X) = 2 |N.X| / (|N.X| + sqrt(alpha^2 + (1 - alpha^2) (N.X)^2))
//                                                                              Smith 1967 (glTF 2.0.1's text)
//     G height-correlated   V = 0.5 / (N.L sqrt((N.V)^2 (1 - alpha^2) + alpha^2)
//                                      + N.V sqrt((N.L)^2 (1 - alpha^2) + alpha^2))
//                                                                              Heitz 2014 (the Sample Viewer's,
//                                                                              and Appendix B's since its 2026 revision)
// Both G are Smith's with GGX's Lambda, 1 / (1 + Lambda), written with Lambda
// (microfacet/d_ggx.hpp): G1 = 1 / (1 + Lambda), height-correlated 1 / (1 + Lambda_L + Lambda_V).
#pragma once
#include <cmath>
#include <string_view>

#include "../geometry.hpp"
#include "../microfacet/d_ggx.hpp"
#include "material.hpp"

namespace normzoo::material {

// The masking-shadowing of specular_brdf: the separable form of glTF 2.0.1 as published (the
// default), or the height-correlated form most implementations take (the glTF Sample Viewer's),
// which Appendix B gives since KhronosGroup/glTF pull request 2541 (2026) (docs/materials.md).
enum class smith_form { separable, height_correlated };

inline constexpr std::string_view smith_form_ids = "smith-separable,smith-height-correlated";

struct diffuse_brdf {
    static constexpr std::string_view id = "diffuse_brdf";
    static constexpr const char* formula = "1 / pi (times its colour, a weight)";
    static constexpr const char* literature = "Lambert 1760; glTF 2.0, Appendix B";
    static double value() { return 1 / pi<double>(); }
};

struct specular_brdf {
    static constexpr std::string_view id = "specular_brdf";
    static constexpr const char* formula = "V D, V = G / (4 |N.L| |N.V|), D = GGX(alpha)";
    static constexpr const char* literature =
        "glTF 2.0, Appendix B; Trowbridge and Reitz 1975; Walter et al. 2007; Smith 1967; Heitz 2014";
    double alpha;
    smith_form form = smith_form::separable;

    // Smith's Lambda of GGX at alpha for a direction w (microfacet/d_ggx.hpp).
    double lambda(const vec3<double>& w) const { return microfacet::detail::ggx_lambda(w, alpha); }
    // G from the two Lambdas: the specification's separable form or the height-correlated one.
    double g(double lambda_l, double lambda_v) const {
        return form == smith_form::separable ? 1 / ((1 + lambda_l) * (1 + lambda_v)) : 1 / (1 + lambda_l + lambda_v);
    }
    double d(const vec3<double>& h) const {
        microfacet::ndf_params<double> np;
        np.alpha_x = np.alpha_y = alpha;
        return microfacet::d_ggx::d(h, np);
    }
    // V D at unit L, V with N.L, N.V > 0 and h their half vector.
    double value(const vec3<double>& l, const vec3<double>& v, const vec3<double>& h) const {
        return d(h) * g(lambda(l), lambda(v)) / (4 * l.z() * v.z());
    }
};

}  // namespace normzoo::material
