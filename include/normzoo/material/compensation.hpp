// Multiple-scattering compensation on a material, and the verdicts on its albedo (docs/materials.md,
// "Compensations"). A compensation is a suffix of the material's name: gltf/kulla-conty,
// gltf/turquin, gltf/fdez-aguera (microfacet/multiple_scattering.hpp, the compositions' code). It applies to each
// microfacet lobe on its own, with that lobe's Fresnel, and the compensated lobes are then mixed
// by the material's operators: the metal channel by channel at F0 = baseColor, the dielectric's
// specular at its F0 = min(F0(ior) specularColor, 1), F90 = 1, times its weight `specular`. That
// is the mixture of two compensated BRDFs, which is what the material is; compensating the mixed
// F0 instead (what Bevy and three.js computed) is another BRDF (the table material-blend). The
// diffuse lobe is left as the specification weights it.
#pragma once
#include <array>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "../microfacet/multiple_scattering.hpp"
#include "albedo.hpp"
#include "coat_albedo.hpp"
#include "gltf.hpp"
#include "sheen_albedo.hpp"

namespace normzoo::material {

enum class compensation_kind { none, kulla_conty, turquin, fdez_aguera };

inline constexpr std::string_view compensation_ids = "kulla-conty, turquin, fdez-aguera";

// The compensation named by a material's suffix ("kulla-conty", "turquin"); throws
// std::invalid_argument naming it and the known ones.
inline compensation_kind parse_compensation(std::string_view id) {
    if (id == "kulla-conty") return compensation_kind::kulla_conty;
    if (id == "turquin") return compensation_kind::turquin;
    if (id == "fdez-aguera") return compensation_kind::fdez_aguera;
    throw std::invalid_argument("unknown compensation '" + std::string(id) + "' (known: " + std::string(compensation_ids) + ")");
}

namespace detail {

// The composition of glTF's specular_brdf with Schlick's F and the compensation: ggx/G/schlick/C.
inline microfacet::composition gltf_specular_composition(const gltf& m, compensation_kind k) {
    const std::string g = m.in.masking == smith_form::separable ? "smith-separable" : "smith-height-correlated";
    const std::string c = k == compensation_kind::kulla_conty ? "/kulla-conty"
                          : k == compensation_kind::turquin   ? "/turquin"
                          : k == compensation_kind::fdez_aguera ? "/fdez-aguera"
                                                                : "";
    return microfacet::composition::parse("ggx/" + g + "/schlick" + c);
}

// Kulla and Conty's terms of F = 1 (E_avg and the lost energy, of the parts and alpha alone),
// kept per thread for the last eight (parts, alpha, tolerance, panels) computed, the oldest
// dropped first: a sweep over mu at one alpha computes them once, its other points read them.
// They hold for F = 1: a caller with a Fresnel term sets `of`, `f0` and `f_avg` on its copy.
// `built` says whether this call computed them (their evaluations are then its to count).
inline microfacet::kulla_conty_terms kulla_conty_kept(const microfacet::composition& c, double alpha,
                                                      const albedo_settings& s, bool* built = nullptr) {
    thread_local std::vector<microfacet::kulla_conty_terms> kept;
    const microfacet::composition one = microfacet::detail::with_f_one(c);
    if (built) *built = false;
    for (const auto& t : kept)
        if (t.hold_at(one, alpha, 1, s)) return t;
    if (kept.size() == 8) kept.erase(kept.begin());
    kept.push_back(microfacet::kulla_conty_at(one, alpha, 1, s));
    if (built) *built = true;
    return kept.back();
}

}  // namespace detail

// Why the glTF material refuses compensation k, or nullptr: a compensation under a sheen (its
// scaling of a compensated lobe would need that lobe's integrand over N.L, sheen_albedo.hpp), or
// with a film, anisotropy or transmission (gltf::compensation_error: a compensation is the core's).
inline const char* compensation_error(const gltf& m, compensation_kind k) {
    if (k == compensation_kind::none) return nullptr;
    if (m.sheen_on()) return "a compensation with a sheen (sheenColor not 0) is not modelled";
    return gltf::compensation_error(m.in);
}

// The albedo of the glTF material with its microfacet lobes compensated (`k` not none): the
// specular and metal lobes each the compositions' compensated albedo (compensated_albedo) per
// channel at its F0, times its weight; the diffuse as in albedo_of. Kulla and Conty's terms of
// alpha (E_avg and the lost energy) are shared by the six channels and kept per thread for the
// next points at this alpha (detail::kulla_conty_kept).
inline material_albedo<gltf::lobe_count> compensated_albedo_of(const gltf& m, double mu, compensation_kind k,
                                                               const albedo_settings& settings = {}) {
    namespace mf = microfacet;
    if (k == compensation_kind::none) return m.by_nodes() ? coated_albedo_by_nodes(m, mu, settings) : gltf_albedo(m, mu, settings);
    // a sheen's scaling of a compensated lobe would need that lobe's integrand over N.L; a film,
    // anisotropy or transmission leave the core
    if (const char* why = compensation_error(m, k)) throw std::invalid_argument(why);
    material_albedo<gltf::lobe_count> r = albedo_of(m, mu, settings);  // the diffuse and the coat; the others replaced
    const mf::composition c = detail::gltf_specular_composition(m, k);
    // compensated_albedo asks each of its albedos for 1/8 of this: at 0.8 of the tolerance that is
    // 1e-11 for 1e-10, where GGX with Schlick's F still takes the 1D closed-azimuth integral
    // (microfacet/azimuthal_albedo.hpp), 5x to 10x faster than the 2D one below it; the channels'
    // weights (metallic, (1 - metallic) specular) sum to at most 1
    albedo_settings s = settings;
    s.tolerance = settings.tolerance * 0.8;
    const rgb f0_dielectric = m.weight_terms();
    // under a coat, both weighted by 1 - clearcoat fr(N.V) (1 exactly without one); the coat's
    // own lobe stays single scattering (its Fresnel is the layering's, at N.V)
    const double under = m.coat().base(mu);
    const double w_specular = under * ((1 - m.in.metallic) * m.in.specular), w_metal = under * m.in.metallic;
    // Schlick's F is affine in F0, F0 + (1 - F0) (1 - V.H)^5: the single-scattering albedo at each
    // channel's F0 is F0 E(F = 1) + (1 - F0) E(F = s), two quadratures at this mu for the six
    // channels (each to what compensated_albedo asks of its own: s.tolerance / 8)
    mf::composition single = c;
    single.compensation = mf::composition::compensation_kind::none;
    albedo_settings part = s;
    part.tolerance = s.tolerance / 8;
    const auto e1 = mf::directional_albedo(single, mu, m.alpha(), 1, part), e5 = mf::directional_albedo(single, mu, m.alpha(), 0, part);
    r.evaluations += e1.evaluations + e5.evaluations;
    auto e_ss_at = [&](double f0) {
        const double v = f0 * e1.value + (1 - f0) * e5.value;
        return quadrature::estimate<double>{
            v, f0 * e1.abs_error + (1 - f0) * e5.abs_error + 4 * std::numeric_limits<double>::epsilon() * (e1.value + e5.value), 0};
    };
    std::optional<mf::kulla_conty_terms> kept;
    auto lobe_at = [&](double f0) {
        if (k == compensation_kind::kulla_conty) {
            if (!kept) {
                // E_avg and the loss are of F = 1 and alpha: shared by the six channels, and by
                // the points of a sweep at this alpha (kept per thread)
                bool built = false;
                kept = detail::kulla_conty_kept(c, m.alpha(), s, &built);
                if (built) r.evaluations += kept->lost.evaluations + kept->e_avg.evaluations;
            }
            mf::kulla_conty_terms t = *kept;
            t.of = c;
            t.f0 = f0;
            t.f_avg = mf::fresnel_average(c, f0);
            return mf::compensated_albedo_from(c, m.alpha(), f0, e_ss_at(f0), e1, s, &t);
        }
        return mf::compensated_albedo_from(c, m.alpha(), f0, e_ss_at(f0), e1, s, nullptr);
    };
    const std::size_t specular = 1, metal = 2;
    for (std::size_t ch = 0; ch < 3; ++ch) {
        for (const auto& [lobe, weight, f0] : {std::tuple{specular, w_specular, f0_dielectric[ch]},
                                               std::tuple{metal, w_metal, m.in.baseColor[ch]}}) {
            if (weight == 0) {
                r.lobes[lobe].value[ch] = r.lobes[lobe].abs_error[ch] = 0;
                continue;
            }
            const auto e = lobe_at(f0);
            r.evaluations += e.evaluations;
            r.lobes[lobe].value[ch] = weight * e.value;
            // the weight's product errs by an ulp; the weight itself by two (1 - metallic, a
            // product), and under a coat by a few ulps of 1 more, absolute (1 - clearcoat fr(mu)
            // cancels toward 0 at grazing V): 8 eps of the weight without it
            const double eps = std::numeric_limits<double>::epsilon();
            const double unweighted = under == 1 ? 0 : weight / under;
            r.lobes[lobe].abs_error[ch] = weight * e.abs_error + 4 * eps * weight * e.value + 8 * eps * unweighted * e.value;
        }
    }
    r.whole = {};
    for (const auto& l : r.lobes) {
        r.whole.value = r.whole.value + l.value;
        r.whole.abs_error = r.whole.abs_error + l.abs_error;
    }
    for (std::size_t ch = 0; ch < 3; ++ch) r.whole.abs_error[ch] += 4 * std::numeric_limits<double>::epsilon() * r.whole.value[ch];
    return r;
}

// The glTF material's albedo with V at cos t = mu (registry.hpp's call shape): single scattering by
// gltf_albedo (albedo_of without a sheen), or with its microfacet lobes compensated.
inline material_albedo<gltf::lobe_count> albedo(const gltf& m, double mu, compensation_kind k,
                                                const albedo_settings& settings = {}) {
    return compensated_albedo_of(m, mu, k, settings);  // with k none: gltf_albedo, or node by node (gltf::by_nodes)
}

// Whether the model claims its albedo is 1 at this configuration: a white metal (metallic 1,
// baseColor 1) with a compensation (each compensation gives a white furnace 1 by design), no
// sheen or coat over it.
inline bool claims_preservation(const gltf& m, compensation_kind k) {
    // (a sheen or a coat, single scattering, claims nothing)
    return k != compensation_kind::none && m.in.metallic == 1 && m.in.baseColor == grey(1) && !m.sheen_on() && !m.coat_on();
}

// The verdicts on an albedo (docs/conventions.md): conserving, its largest channel at most 1
// within its bound; preserving, 1 within the bound, where the model claims it.
inline bool conserving(const rgb_estimate& e) { return !(e.largest() - e.largest_error() > 1); }
inline bool preserving(const rgb_estimate& e) {
    for (std::size_t k = 0; k < 3; ++k)
        if (std::abs(e.value[k] - 1) > e.abs_error[k]) return false;
    return true;
}

// Reciprocity, f(L, V) = f(V, L), on the pairs of 8 directions (polar angles 5 to 85 degrees,
// four azimuths): the largest relative difference of a channel, |f(L, V) - f(V, L)| / max of the
// two. The single-scattering material is reciprocal (V.H = L.H); Kulla and Conty's lobe is
// symmetric in L and V, so it leaves that as it is; Turquin's factor 1 + F0 (1/E(N.V) - 1) and
// Fdez-Aguera's 1 / (1 - F_avg (1 - E(N.V))) (F_avg = F0 + (1 - F0)/21) read V alone, and are
// measured here with E at each direction (F = 1, to 1e-12).
inline double reciprocity_difference(const gltf& m, compensation_kind k) {
    namespace mf = microfacet;
    const std::vector<vec3<double>> dirs = reciprocity_directions();
    std::vector<double> e(dirs.size(), 1.0);  // E(N.X) of F = 1 where Turquin's factor reads it
    const bool by_view = k == compensation_kind::turquin || k == compensation_kind::fdez_aguera;
    if (by_view) {
        const mf::composition one = mf::detail::with_f_one(detail::gltf_specular_composition(m, k));
        albedo_settings s;
        s.tolerance = 1e-12;
        for (std::size_t i = 0; i < dirs.size(); ++i) e[i] = mf::directional_albedo(one, dirs[i].z(), m.alpha(), 1, s).value;
    }
    auto f = [&](std::size_t li, std::size_t vi) {
        auto lobes = m.f_lobes(dirs[li], dirs[vi]);
        if (by_view)
            for (std::size_t ch = 0; ch < 3; ++ch) {
                const double f0s[2] = {m.weight_terms()[ch], m.in.baseColor[ch]};
                for (std::size_t j = 0; j < 2; ++j) {
                    const double f_avg = f0s[j] + (1 - f0s[j]) / 21;
                    lobes[1 + j][ch] *= k == compensation_kind::turquin ? 1 + f0s[j] * (1 / e[vi] - 1)
                                                                        : 1 / (1 - f_avg * (1 - e[vi]));
                }
            }
        rgb sum{};
        for (const auto& x : lobes) sum = sum + x;
        return sum;
    };
    return largest_reciprocity_difference(dirs.size(), f);
}

}  // namespace normzoo::material
