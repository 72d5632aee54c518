// Phong and its cosine-weighted ("modified") form.
// R is the mirror of L (docs/conventions.md); with V = N, R.V = N.L = cos t. (The zoo writes the
// same lobe as R.L with R the mirror of V; both dot products are equal.)
// Literature: Phong 1975; the normalizations in Lewis 1994 ("Making Shaders More Physically
// Plausible"), Lafortune and Willems 1994 (modified Phong), Giesen ("Phong Normalization
// Factor derivation"), collected in "The Blinn-Phong Normalization Zoo".
#pragma once
#include "zoo_row.hpp"

namespace normzoo::zoo {

struct phong {
    static constexpr const char* id = "phong";
    static constexpr const char* expression = "(R.V)^n";
    static constexpr const char* integrand = "cos^n t sin t";
    static constexpr const char* normalization = "(n+1)/(2 pi)";
    static constexpr const char* literature = "Phong 1975; Lewis 1994; Lafortune and Willems 1994";
    static constexpr auto parameters = exponent_only;
    static constexpr bool has_exponent = true;
    static constexpr double lobe_alpha = 1;

    // (R.V)^n, R the mirror of L: the lobe of both rows here and of brdf::phong, brdf::phong_modified.
    template <class T>
    static T lobe(const vec3<T>& l, const vec3<T>& v, const T& n) { return pow_lobe(reflect(l), v, n); }
    template <class T>
    static T rdf(const vec3<T>& l, const vec3<T>& v, const T& n) { return lobe(l, v, n); }
    template <class T>
    static T weight(const T& /*c*/, const T& s) { return s; }
    template <class T>
    static T closed_form(const T& n) { return (n + 1) / (2 * pi<T>()); }
};

struct phong_modified {
    static constexpr const char* id = "phong-modified";
    static constexpr const char* expression = "(R.V)^n (N.L)";
    static constexpr const char* integrand = "cos^n t cos t sin t";
    static constexpr const char* normalization = "(n+2)/(2 pi)";
    static constexpr const char* literature = "Lewis 1994; Lafortune and Willems 1994; Giesen";
    static constexpr auto parameters = exponent_only;
    static constexpr bool has_exponent = true;
    static constexpr double lobe_alpha = 1;

    template <class T>
    static T rdf(const vec3<T>& l, const vec3<T>& v, const T& n) {
        return phong::lobe(l, v, n) * clamped_dot(normal<T>(), l);
    }
    template <class T>
    static T weight(const T& c, const T& s) { return c * s; }
    template <class T>
    static T closed_form(const T& n) { return (n + 2) / (2 * pi<T>()); }
};

}  // namespace normzoo::zoo
