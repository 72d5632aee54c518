// Lambert: a constant BRDF; its RDF is the cosine N.L.
// Literature: J. H. Lambert, Photometria (1760); the zoo's normalization 1/pi.
#pragma once
#include "zoo_row.hpp"

namespace normzoo::zoo {

struct lambert {
    static constexpr const char* id = "lambert";
    static constexpr const char* expression = "1 (N.L)";
    static constexpr const char* integrand = "cos t sin t";
    static constexpr const char* normalization = "1/pi";
    static constexpr const char* literature = "Lambert, Photometria (1760)";
    static constexpr auto parameters = no_parameters;
    static constexpr bool has_exponent = false;
    static constexpr double lobe_alpha = 1;

    template <class T>
    static T rdf(const vec3<T>& l, const vec3<T>& /*v*/, const T& /*n*/) { return clamped_dot(normal<T>(), l); }
    template <class T>
    static T weight(const T& c, const T& s) { return c * s; }
    template <class T>
    static T closed_form(const T& /*n*/) { return 1 / pi<T>(); }
};

}  // namespace normzoo::zoo
