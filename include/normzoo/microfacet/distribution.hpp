// The normal distribution parts D(m) of a microfacet BRDF, one list (docs/microfacet.md): each part
// is a header of its own (what it has: distribution_part.hpp), and adding one is its header and
// its entry here.
//   blinn-phong     (n+2)/(2 pi) (N.m)^n, n = 2/alpha^2 - 2            Blinn 1977; Walter et al. 2007
//   beckmann        e^(-tan^2 t / a^2) / (pi a^2 cos^4 t)               Beckmann and Spizzichino 1963
//   ggx             a^2 / (pi cos^4 t (a^2 + tan^2 t)^2)                Trowbridge and Reitz 1975; Walter et al. 2007
//   gtr             c / (a^2 cos^2 t + sin^2 t)^gamma                    Burley 2012, appendix B
//   ggx-aniso       1 / (pi ax ay cos^4 t (1 + tan^2 t (cos^2 p / ax^2 + sin^2 p / ay^2))^2)
//   beckmann-aniso  e^(-tan^2 t (cos^2 p / ax^2 + sin^2 p / ay^2)) / (pi ax ay cos^4 t)
//   charlie         (2 + 1/a) sin^(1/a) t / (2 pi)                      Estevez and Kulla 2017 (sheen)
#pragma once
#include <string_view>
#include <tuple>

#include "../detail/by_id.hpp"
#include "d_beckmann.hpp"
#include "d_beckmann_aniso.hpp"
#include "d_charlie.hpp"
#include "d_blinn_phong.hpp"
#include "d_ggx.hpp"
#include "d_ggx_aniso.hpp"
#include "d_gtr.hpp"

namespace normzoo::microfacet {

// The D parts, one list: a composition id's D is one of these ids.
using distribution_parts = std::tuple<d_blinn_phong, d_beckmann, d_ggx, d_gtr, d_ggx_aniso, d_beckmann_aniso,
                                      d_charlie>;

// Calls fn(part) with the part named `id`; false when there is none.
template <class Fn>
bool with_distribution(std::string_view id, Fn&& fn) {
    return normzoo::detail::with_id<distribution_parts>(id, fn);
}

}  // namespace normzoo::microfacet
