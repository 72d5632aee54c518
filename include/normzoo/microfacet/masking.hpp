// The masking-shadowing parts G(L, V, m) of a microfacet BRDF (docs/microfacet.md): each a
// small value type with its id (the G of a composition id D/G/F), its formula, its literature,
// and g(s) of the cosines at the shading point (s.nl, s.nv, s.nm, s.lm = s.vm for m the half
// vector), the roughness alpha, and Smith's Lambda of the distribution for L and V (s.lambda_l,
// s.lambda_v; needs_lambda says whether a part reads them). All cosines are taken > 0 here.
// reads_half_vector: whether g reads N.m or V.m; a part that reads only N.L and N.V (and the
// Lambdas, isotropic) depends on L through its polar angle alone, which lets the albedo with F = 1
// take D's integral over L's azimuth in closed form (microfacet/azimuthal_albedo.hpp).
//   implicit                      N.L N.V                                   (G / (4 N.L N.V) = 1/4)
//   cook-torrance                 min(1, 2 N.m N.V / V.m, 2 N.m N.L / V.m)  Cook and Torrance 1982
//   kelemen                       N.L N.V / (V.m)^2                         Kelemen and Szirmay-Kalos 2001
//   smith-separable               1 / ((1 + Lambda(L)) (1 + Lambda(V)))     Smith 1967; Heitz 2014
//   smith-height-correlated       1 / (1 + Lambda(L) + Lambda(V))           Ross et al. 2005; Heitz 2014
//   schlick-ggx                   G1(L) G1(V), G1(x) = x / (x (1 - k) + k), k = alpha/2
//                                                                           Schlick 1994; Karis 2013
//   schlick-ggx-remapped          the same with k = (r + 1)^2 / 8, r = sqrt(alpha)  Karis 2013
//   schlick-beckmann              the same with k = alpha sqrt(2/pi)        Schlick 1994; Lazarov 2013
//   hammon                        4 N.L N.V / (2 lerp(2 N.L N.V, N.L + N.V, alpha))  Hammon 2017
//   smith-height-correlated-fast  4 N.L N.V / (2 (N.L (N.V (1 - a) + a) + N.V (N.L (1 - a) + a)))
//                                                                           the fast form of Filament's
//                                                                           documentation (Guy and Agopian)
//   neubelt                       N.L N.V / (N.L + N.V - N.L N.V)           Neubelt and Pettineo 2013
//   ashikhmin                     the same formula (an alias of neubelt)     Ashikhmin and Premoze 2007
//   charlie-sheen                 1 / (1 + Lambda(L) + Lambda(V)), Lambda Estevez and Kulla's fit
//                                                                           Estevez and Kulla 2017; KHR_materials_sheen
// The last three are the cloth and sheen visibilities (with D = charlie; docs/microfacet.md#sheen-visibilities).
// schlick-ggx, schlick-ggx-remapped, hammon and the fast form approximate the Smith forms of GGX,
// schlick-beckmann Smith's separable form of Beckmann; their error is what the shortcut audit
// measures (docs/microfacet.md).
#pragma once
#include <boost/math/constants/constants.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <tuple>

#include "../detail/by_id.hpp"
#include "../geometry.hpp"
#include "../parameter.hpp"

namespace normzoo::microfacet {

// The cosines of a shading point and what a G part may read beside them.
template <class T>
struct shading {
    T nl = 1, nv = 1, nm = 1, vm = 1;  // N.L, N.V, N.m, V.m = L.m
    T alpha = T(0.5);                  // the roughness along the plane of L and V (isotropic: alpha)
    T lambda_l = 0, lambda_v = 0;      // Smith's Lambda of the distribution, for L and V
};

struct g_implicit {
    static constexpr std::string_view id = "implicit";
    static constexpr const char* formula = "N.L N.V";
    static constexpr const char* literature = "the implicit G of Hoffman's course notes (G / (4 N.L N.V) = 1/4)";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = false, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) { return s.nl * s.nv; }
};

struct g_cook_torrance {
    static constexpr std::string_view id = "cook-torrance";
    static constexpr const char* formula = "min(1, 2 N.m N.V / V.m, 2 N.m N.L / V.m)";
    static constexpr const char* literature = "Cook and Torrance 1982 (V-cavities)";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = false, reads_half_vector = true;
    template <class T>
    static T g(const shading<T>& s) {
        using std::min;
        return min(T(1), min(2 * s.nm * s.nv / s.vm, 2 * s.nm * s.nl / s.vm));
    }
    // The min() switches along curves across the albedo's domain (kinks that a panel's Gauss and
    // Kronrod sums can miss together), where, with N.L = 2 (V.m)(N.m) - N.V, V.m takes one of
    //     2 N.m N.V                      (V's term is 1),
    //     2 N.m N.V / (4 (N.m)^2 - 1)    (L's term is 1; only where 4 (N.m)^2 > 1),
    //     N.V / N.m                      (the two terms are equal: N.L = N.V).
    // Writes them to vm[] in that order, +inf where there is none, and returns 3; the albedo
    // integral puts breakpoints there (docs/microfacet.md, "The albedo in the distribution's own
    // variable").
    static int kink_vm(double nv, double nm, double vm[3]) {
        const double inf = std::numeric_limits<double>::infinity(), d = 4 * nm * nm - 1;
        vm[0] = 2 * nm * nv;
        vm[1] = d > 0 ? 2 * nm * nv / d : inf;
        vm[2] = nm > 0 ? nv / nm : inf;
        return 3;
    }
};

struct g_kelemen {
    static constexpr std::string_view id = "kelemen";
    static constexpr const char* formula = "N.L N.V / (V.m)^2";
    static constexpr const char* literature = "Kelemen and Szirmay-Kalos 2001";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = false, reads_half_vector = true;
    template <class T>
    static T g(const shading<T>& s) { return s.nl * s.nv / (s.vm * s.vm); }
};

struct g_smith_separable {
    static constexpr std::string_view id = "smith-separable";
    static constexpr const char* formula = "1 / ((1 + Lambda(L)) (1 + Lambda(V)))";
    static constexpr const char* literature = "Smith 1967; Walter et al. 2007; Heitz 2014";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = true, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) { return 1 / ((1 + s.lambda_l) * (1 + s.lambda_v)); }
};

struct g_smith_height_correlated {
    static constexpr std::string_view id = "smith-height-correlated";
    static constexpr const char* formula = "1 / (1 + Lambda(L) + Lambda(V))";
    static constexpr const char* literature = "Ross, Dobbs and Brumfield 2005; Heitz 2014";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = true, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) { return 1 / (1 + s.lambda_l + s.lambda_v); }
};

namespace detail {
template <class T>
T schlick_g1(const T& x, const T& k) { return x / (x * (1 - k) + k); }
}  // namespace detail

struct g_schlick_ggx {
    static constexpr std::string_view id = "schlick-ggx";
    static constexpr const char* formula = "G1(N.L) G1(N.V), G1(x) = x / (x (1 - k) + k), k = alpha / 2";
    static constexpr const char* literature = "Schlick 1994; Karis 2013 (k = alpha / 2 for image-based lighting)";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = false, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) {
        const T k = s.alpha / 2;
        return detail::schlick_g1(s.nl, k) * detail::schlick_g1(s.nv, k);
    }
};

struct g_schlick_ggx_remapped {
    static constexpr std::string_view id = "schlick-ggx-remapped";
    static constexpr const char* formula = "G1(N.L) G1(N.V), G1(x) = x / (x (1 - k) + k), k = (r + 1)^2 / 8, r = sqrt(alpha)";
    static constexpr const char* literature = "Karis 2013 (k for analytic lights)";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = false, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) {
        using std::sqrt;
        const T r = sqrt(s.alpha), k = (r + 1) * (r + 1) / 8;
        return detail::schlick_g1(s.nl, k) * detail::schlick_g1(s.nv, k);
    }
};

struct g_schlick_beckmann {
    static constexpr std::string_view id = "schlick-beckmann";
    static constexpr const char* formula = "G1(N.L) G1(N.V), G1(x) = x / (x (1 - k) + k), k = alpha sqrt(2 / pi)";
    static constexpr const char* literature =
        "Schlick 1994 (k = m sqrt(2/pi) for Beckmann's m); Lazarov 2013 (k = 2 / sqrt(pi (n + 2)) for Blinn-Phong's n)";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = false, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) {
        using std::sqrt;
        const T k = s.alpha * sqrt(2 / boost::math::constants::pi<T>());
        return detail::schlick_g1(s.nl, k) * detail::schlick_g1(s.nv, k);
    }
};

struct g_hammon {
    static constexpr std::string_view id = "hammon";
    static constexpr const char* formula = "2 N.L N.V / lerp(2 N.L N.V, N.L + N.V, alpha)";
    static constexpr const char* literature = "Hammon 2017, \"PBR Diffuse Lighting for GGX+Smith Microsurfaces\"";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = false, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) {
        const T two = 2 * s.nl * s.nv;
        return two / (two + s.alpha * (s.nl + s.nv - two));
    }
};

struct g_smith_height_correlated_fast {
    static constexpr std::string_view id = "smith-height-correlated-fast";
    static constexpr const char* formula = "2 N.L N.V / (N.L (N.V (1 - a) + a) + N.V (N.L (1 - a) + a))";
    static constexpr const char* literature = "Filament's documentation (Guy and Agopian), after Heitz 2014";
    static constexpr auto parameters = no_parameters;  // it reads the D part's roughness only
    static constexpr bool needs_lambda = false, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) {
        const T a = s.alpha;
        return 2 * s.nl * s.nv / (s.nl * (s.nv * (1 - a) + a) + s.nv * (s.nl * (1 - a) + a));
    }
};

// The cloth visibility of Neubelt and Pettineo 2013 ("Crafting a Next-Gen Material Pipeline for The
// Order: 1886"): V = G / (4 N.L N.V) = 1 / (4 (N.L + N.V - N.L N.V)). 1 - (1 - N.L)(1 - N.V) is the
// denominator without cancellation.
struct g_neubelt {
    static constexpr std::string_view id = "neubelt";
    static constexpr const char* formula = "N.L N.V / (N.L + N.V - N.L N.V)";
    static constexpr const char* literature =
        "Neubelt and Pettineo 2013, \"Crafting a Next-Gen Material Pipeline for The Order: 1886\"";
    static constexpr auto parameters = no_parameters;
    static constexpr bool needs_lambda = false, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) { return s.nl * s.nv / (1 - (1 - s.nl) * (1 - s.nv)); }
};

// The same formula under the name engines give it (KHR_materials_sheen's "simpler visibility",
// Filament's and three.js's cloth, Babylon's sheen): Ashikhmin and Premoze 2007's denominator
// 4 (N.L + N.V - N.L N.V), which Neubelt and Pettineo took (docs/microfacet.md#sheen-visibilities).
// An alias: the one formula is g_neubelt's.
struct g_ashikhmin : g_neubelt {
    static constexpr std::string_view id = "ashikhmin";
    static constexpr const char* formula = "N.L N.V / (N.L + N.V - N.L N.V) (neubelt's)";
    static constexpr const char* literature =
        "Ashikhmin and Premoze 2007, \"Distribution-based BRDFs\"; the same formula as neubelt";
};

namespace detail {
// Estevez and Kulla 2017's fit of the Charlie distribution's Lambda, as KHR_materials_sheen
// specifies it: L(x) = a / (1 + b x^c) + d x + e, its five coefficients interpolated linearly in
// (1 - alpha)^2 between the fits at alpha = 1 and alpha = 0, and Lambda(cos t) = e^L(cos t) below
// cos t = 1/2, e^(2 L(1/2) - L(1 - cos t)) above. The specification has no terminator softening
// (the paper's Lambda^(1 + 2 (1 - cos t)^8) for shading normals): none here.
template <class T>
T charlie_fit_l(const T& x, const T& alpha) {
    using std::pow;
    const T t = (1 - alpha) * (1 - alpha);
    auto mix = [&](double at_1, double at_0) { return T(at_1) * (1 - t) + T(at_0) * t; };
    const T a = mix(21.5473, 25.3245), b = mix(3.82987, 3.32435), c = mix(0.19823, 0.16801),
            d = mix(-1.97760, -1.27393), e = mix(-4.32054, -4.85967);
    return a / (1 + b * pow(x, c)) + d * x + e;
}
template <class T>
T charlie_lambda(const T& cos_t, const T& alpha) {
    using std::exp;
    if (cos_t < T(0.5)) return exp(charlie_fit_l(cos_t, alpha));
    return exp(2 * charlie_fit_l(T(0.5), alpha) - charlie_fit_l(1 - cos_t, alpha));
}
}  // namespace detail

// KHR_materials_sheen's sheen visibility: height-correlated Smith with the fitted Lambda of the
// Charlie distribution (Estevez and Kulla 2017), G = 1 / (1 + Lambda(N.L) + Lambda(N.V)). The fit is
// not 0 at the normal (Lambda(1) ~ 1e-8 at alpha = 0.3), so G(N, N) is just below 1; it is C^1 but
// not C^2 at cos t = 1/2 and goes like (1 - cos t)^c, c ~ 0.2, at the normal.
struct g_charlie_sheen {
    static constexpr std::string_view id = "charlie-sheen";
    static constexpr const char* formula =
        "1 / (1 + Lambda(L) + Lambda(V)), Lambda(x) = e^L(x) (x < 1/2), e^(2 L(1/2) - L(1 - x)), "
        "L(x) = a / (1 + b x^c) + d x + e fitted";
    static constexpr const char* literature =
        "Estevez and Kulla 2017, \"Production Friendly Microfacet Sheen BRDF\"; KHR_materials_sheen, \"Sheen visibility\"";
    static constexpr auto parameters = no_parameters;
    static constexpr bool needs_lambda = false, reads_half_vector = false;
    template <class T>
    static T g(const shading<T>& s) {
        return 1 / (1 + detail::charlie_lambda(s.nl, s.alpha) + detail::charlie_lambda(s.nv, s.alpha));
    }
};

// The G parts, one list: a composition id's G is one of these ids.
using masking_parts = std::tuple<g_implicit, g_cook_torrance, g_kelemen, g_smith_separable, g_smith_height_correlated,
                                 g_schlick_ggx, g_schlick_ggx_remapped, g_schlick_beckmann, g_hammon,
                                 g_smith_height_correlated_fast, g_neubelt, g_ashikhmin, g_charlie_sheen>;

// Calls fn(part) with the part named `id`; false when there is none.
template <class Fn>
bool with_masking(std::string_view id, Fn&& fn) {
    return normzoo::detail::with_id<masking_parts>(id, fn);
}

}  // namespace normzoo::microfacet
