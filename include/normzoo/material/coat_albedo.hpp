// The glTF material's albedo with V fixed where its lobes are integrated node by node (a film or
// anisotropy: gltf::by_nodes), under KHR_materials_clearcoat (docs/materials.md,
// "KHR_materials_clearcoat"). The coat's weights read N.V alone, so with V held
//     E = (1 - clearcoat fr(mu)) E_bare + clearcoat fr(mu) E_coat(mu),
// E_bare the uncoated material's albedo (every lobe, the transmission's too: bare_albedo_by_nodes)
// and E_coat the coat's specular_brdf at its own alpha with F = 1, one 1D integral of its
// composition (microfacet/albedo.hpp): the base's GGX map, in which the node-by-node route
// integrates, is not the coat's.
#pragma once
#include <cmath>
#include <cstddef>
#include <limits>

#include "../microfacet/albedo.hpp"
#include "about_v.hpp"
#include "albedo.hpp"
#include "gltf.hpp"
#include "sheen_nodes.hpp"

namespace normzoo::material {

// The uncoated material's lobes: under a film by the half vector about V (about_v.hpp: its
// weights read V.H and N.V alone, and the film's Fresnel is evaluated once a node of V.H), under a
// sheen scaled by it (sheen_nodes.hpp); an anisotropic lobe in its own map (albedo_by_nodes). The
// route about V takes an anisotropic lobe too, but a narrow one (alpha_b 1e-8) still errs there
// by up to 5e-10 beyond its bound (docs/materials.md), so the command refuses a film or a sheen
// with anisotropy (gltf::input_error).
inline material_albedo<gltf::lobe_count> bare_albedo_by_nodes(const gltf& m, double mu, const albedo_settings& settings) {
    if (m.specular_lobe().anisotropic()) return albedo_by_nodes(m, mu, settings);
    return m.sheen_on() ? sheen_albedo_by_nodes(m, mu, settings) : albedo_about_v(m, mu, settings);
}

// Each lobe and the whole per channel, to about settings.tolerance: the bare material's lobes to
// half of it, the coat's albedo to a quarter. Without a coat, the bare material's as it is.
inline material_albedo<gltf::lobe_count> coated_albedo_by_nodes(const gltf& m, double mu, const albedo_settings& settings = {}) {
    if (!m.coat_on()) return bare_albedo_by_nodes(m, mu, settings);
    const double eps = std::numeric_limits<double>::epsilon();
    gltf bare = m;
    bare.in.clearcoat = 0;
    albedo_settings s = settings;
    s.tolerance = settings.tolerance / 2;
    material_albedo<gltf::lobe_count> r = bare_albedo_by_nodes(bare, mu, s);
    const fresnel_coat coat = m.coat();
    // layer = clearcoat fr(mu) errs by a few ulps of itself; under = 1 - layer by a few ulps of 1,
    // absolute (it cancels toward 0 at grazing V with a full coat)
    const double under = coat.base(mu), layer = coat.layer(mu);
    for (auto& lobe : r.lobes)
        for (std::size_t ch = 0; ch < 3; ++ch) {
            const double bare_value = lobe.value[ch];
            lobe.value[ch] = under * bare_value;
            lobe.abs_error[ch] = under * lobe.abs_error[ch] + 8 * eps * std::abs(bare_value) + eps * std::abs(lobe.value[ch]);
        }
    const std::size_t coat_lobe = 4;
    const auto [c, alpha, scale] = m.lobe_composition(coat_lobe);
    s.tolerance = settings.tolerance / 4;
    const auto e = microfacet::directional_albedo(c, mu, alpha, 1, s);  // F = 1: the layer's Fresnel is fr(mu)
    r.evaluations += e.evaluations;
    for (std::size_t ch = 0; ch < 3; ++ch) {
        r.lobes[coat_lobe].value[ch] = scale * layer * e.value;
        r.lobes[coat_lobe].abs_error[ch] = scale * layer * e.abs_error + 8 * eps * r.lobes[coat_lobe].value[ch];
    }
    detail::sum_lobes(r);
    return r;
}

}  // namespace normzoo::material
