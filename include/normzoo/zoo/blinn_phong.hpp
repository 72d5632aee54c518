// Blinn-Phong: the half-vector lobe (N.H)^n as an RDF, with the cosine (modified), and as a
// microfacet normal distribution over h (NDF) or its projected "heightfield" form.
// With V = N, N.H = cos(t/2): the lobe angle is half the angle of L.
// Literature: Blinn 1977; the RDF normalizations and bounds as collected in "The Blinn-Phong
// Normalization Zoo" (Gotanda 2010 for the plain row, Giesen and Real-Time Rendering for the
// modified row); the NDF rows after Schueler (ShaderX7), Kelemen and Szirmay-Kalos 2001,
// Pharr and Humphreys (PBRT) and Hoffman 2010; the microfacet constant (n+2)/(8 pi) as in
// "Adopting a physically based shading model".
#pragma once
#include <cmath>

#include "zoo_row.hpp"

namespace normzoo::zoo {

struct blinn_phong {
    static constexpr const char* id = "blinn-phong";
    static constexpr const char* expression = "(N.H)^n";
    static constexpr const char* integrand = "cos^n(t/2) sin t";
    static constexpr const char* normalization = "(n+2) / (4 pi (2 - 2^(-n/2)))";
    static constexpr const char* literature = "Blinn 1977; Gotanda 2010";
    static constexpr auto parameters = exponent_only;
    static constexpr bool has_exponent = true;
    static constexpr double lobe_alpha = 0.5;

    // (N.H)^n from H itself: the lobe of the four rows here, of the Blinn-Phong BRDF forms and of
    // the microfacet D (microfacet::d_blinn_phong).
    template <class T>
    static T lobe(const vec3<T>& h, const T& n) { return pow_lobe(normal<T>(), h, n); }
    template <class T>
    static T rdf(const vec3<T>& l, const vec3<T>& v, const T& n) { return lobe(half_vector(l, v), n); }
    // sin t = 2 sin(t/2) cos(t/2)
    template <class T>
    static T weight(const T& c, const T& s) { return 2 * s * c; }
    template <class T>
    static T closed_form(const T& n) {
        using std::pow;
        return (n + 2) / (4 * pi<T>() * (2 - pow(T(2), -n / 2)));
    }
};

struct blinn_phong_modified {
    static constexpr const char* id = "blinn-phong-modified";
    static constexpr const char* expression = "(N.H)^n (N.L)";
    static constexpr const char* integrand = "cos^n(t/2) cos t sin t";
    static constexpr const char* normalization = "(n+2)(n+4) / (8 pi (2^(-n/2) + n))";
    static constexpr const char* literature = "Blinn 1977; Giesen; Akenine-Moller, Haines and Hoffman (RTR)";
    static constexpr auto parameters = exponent_only;
    static constexpr bool has_exponent = true;
    static constexpr double lobe_alpha = 0.5;

    template <class T>
    static T rdf(const vec3<T>& l, const vec3<T>& v, const T& n) {
        return blinn_phong::lobe(half_vector(l, v), n) * clamped_dot(normal<T>(), l);
    }
    // cos t sin t = (cos^2 - sin^2)(t/2) * 2 sin(t/2) cos(t/2)
    template <class T>
    static T weight(const T& c, const T& s) { return (c * c - s * s) * 2 * s * c; }
    template <class T>
    static T closed_form(const T& n) {
        using std::pow;
        return (n + 2) * (n + 4) / (8 * pi<T>() * (pow(T(2), -n / 2) + n));
    }
};

// D(h) = (N.h)^n over the half-vector hemisphere.
struct blinn_phong_ndf {
    static constexpr const char* id = "blinn-phong-ndf";
    static constexpr const char* expression = "D(h) = (N.H)^n, over h";
    static constexpr const char* integrand = "cos^n a sin a";
    static constexpr const char* normalization = "(n+1)/(2 pi)";
    static constexpr const char* literature = "Schueler, ShaderX7; Kelemen and Szirmay-Kalos 2001; Lafortune and Willems 1994";
    static constexpr auto parameters = exponent_only;
    static constexpr bool has_exponent = true;
    static constexpr double lobe_alpha = 1;

    template <class T>
    static T rdf(const vec3<T>& h, const vec3<T>& /*v*/, const T& n) { return blinn_phong::lobe(h, n); }
    template <class T>
    static T weight(const T& /*c*/, const T& s) { return s; }
    template <class T>
    static T closed_form(const T& n) { return (n + 1) / (2 * pi<T>()); }
};

// The projected ("heightfield") NDF: D(h) (N.h) integrates to 1. Its normalization is the
// constant of microfacet::d_blinn_phong's D.
struct blinn_phong_heightfield {
    static constexpr const char* id = "blinn-phong-heightfield";
    static constexpr const char* expression = "(N.H)^n (N.H), over h";
    static constexpr const char* integrand = "cos^n a cos a sin a";
    static constexpr const char* normalization = "(n+2)/(2 pi)";
    static constexpr const char* literature = "Pharr and Humphreys (PBRT); Hoffman 2010";
    static constexpr auto parameters = exponent_only;
    static constexpr bool has_exponent = true;
    static constexpr double lobe_alpha = 1;

    template <class T>
    static T rdf(const vec3<T>& h, const vec3<T>& /*v*/, const T& n) {
        return blinn_phong::lobe(h, n) * clamped_dot(normal<T>(), h);
    }
    template <class T>
    static T weight(const T& c, const T& s) { return c * s; }
    template <class T>
    static T closed_form(const T& n) { return (n + 2) / (2 * pi<T>()); }
};

}  // namespace normzoo::zoo
