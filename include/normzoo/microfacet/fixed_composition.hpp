// A microfacet BRDF whose parts are named at compile time, and the shading point every composition
// reads: what a form built of parts needs (brdf/microfacet.hpp), without the run-time registry of
// all parts (composition.hpp) and what its parts cost to parse.
#pragma once
#include <type_traits>

#include "../geometry.hpp"
#include "distribution_part.hpp"
#include "fresnel.hpp"
#include "masking.hpp"

namespace normzoo::microfacet {

// The shading point of L and V: the half vector and the cosines the parts read; false where L
// or V is below the horizon (f = 0 there).
template <class T>
bool shading_point(const vec3<T>& l, const vec3<T>& v, vec3<T>& h, shading<T>& s) {
    const T nl = l.z(), nv = v.z();
    if (!(nl > 0 && nv > 0)) return false;
    h = half_vector(l, v);
    s.nl = nl, s.nv = nv, s.nm = h.z(), s.vm = v.dot(h);
    return true;
}

// A composition whose parts are fixed at compile time: f = D G F / (4 N.L N.V) at roughness alpha
// and Schlick's F0, the parts' own code with no choice at run time (two of the seed forms of
// brdf/microfacet.hpp are such compositions).
template <class D, class G, class F>
struct fixed_composition {
    static_assert(std::is_same_v<F, fresnel_one> || std::is_same_v<F, fresnel_schlick>,
                  "fixed_composition sets F0 alone: its F is one or schlick");
    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const T& alpha, const T& f0) {
        vec3<T> h;
        shading<T> s;
        if (!shading_point(l, v, h, s)) return T(0);
        ndf_params<T> np;
        np.alpha_x = np.alpha_y = alpha;
        s.alpha = alpha;
        if constexpr (G::needs_lambda) s.lambda_l = D::lambda(l, np), s.lambda_v = D::lambda(v, np);
        fresnel_params<T> fp;
        fp.f0 = f0;
        return D::d(h, np) * G::g(s) * F::eval(s.vm, fp) / (4 * s.nl * s.nv);
    }
};

}  // namespace normzoo::microfacet
