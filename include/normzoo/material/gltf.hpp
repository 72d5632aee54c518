// The glTF 2.0 metallic-roughness material (docs/materials.md), as its specification's Appendix B
// defines it, with KHR_materials_ior, _specular, _sheen and _clearcoat:
//   material        = mix(dielectric_brdf, metal_brdf, metallic)
//   metal_brdf      = conductor_fresnel(f0 = baseColor, bsdf = specular_brdf(alpha = roughness^2))
//   dielectric_brdf = fresnel_mix(f0_color = specularColor, ior, weight = specular,
//                                 base = diffuse_brdf(color = baseColor),
//                                 layer = specular_brdf(alpha = roughness^2))
//   sheen_material  = sheenColor sheen_brdf(alpha = sheenRoughness^2) + s material     (sheen.hpp)
//   coated          = fresnel_coat(weight = clearcoat, base = sheen_material,
//                                  layer = specular_brdf(alpha = clearcoatRoughness^2)) (clearcoat.hpp)
// so that, with fr = min(((1 - ior)/(1 + ior))^2 specularColor, 1) + (1 - that) (1 - |V.H|)^5
// (KHR_materials_specular's dielectric_f0 = specular x that min, dielectric_f90 = specular),
//   f_core = (1 - metallic) [(1 - specular max_value(fr)) baseColor / pi + specular fr V D]
//          + metallic (baseColor + (1 - baseColor) (1 - |V.H|)^5) V D,
//   f = (1 - clearcoat fc(N.V)) [s f_core + sheenColor sheen_brdf] + clearcoat fc(N.V) specular_brdf(coat),
// s = min(1 - max_value(sheenColor) E(N.V), 1 - max_value(sheenColor) E(N.L)) (E the sheen lobe's
// albedo), fc = 0.04 + 0.96 (1 - N.V)^5. Its six lobes: diffuse, specular (the dielectric's),
// metal, sheen, clearcoat, transmission. Core glTF is ior = 1.5 (F0 = 0.04), specular = 1,
// specularColor = 1, sheenColor = 0 and clearcoat = 0 (the extensions off, their lobes 0). With
// KHR_materials_iridescence (iridescence.hpp: a thin film mixed into the metal's and the
// dielectric's Fresnel), KHR_materials_anisotropy (anisotropy.hpp: specular_brdf with anisotropic
// GGX) and KHR_materials_transmission (transmission.hpp: the dielectric's base a mix of the diffuse
// and specular_btdf, the lobe "transmission" below the surface); each at its default leaves the
// core as it is. A coat over those three weights the base by 1 - clearcoat fr(N.V), the
// transmission with the rest (coat_albedo.hpp); a sheen over a film scales its lobes as over the
// core (sheen_nodes.hpp); a film or a sheen on an anisotropic lobe, and a sheen with transmission,
// are refused (input_error).
#pragma once
#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "../geometry.hpp"
#include "../microfacet/composition.hpp"
#include "../parameter.hpp"
#include "anisotropy.hpp"
#include "clearcoat.hpp"
#include "iridescence.hpp"
#include "lobes.hpp"
#include "material.hpp"
#include "sheen.hpp"
#include "sheen_curve.hpp"
#include "transmission.hpp"

namespace normzoo::material {

// The inputs by the specification's names (colours linear RGB), at its defaults.
struct gltf_inputs {
    rgb baseColor = grey(1);
    double metallic = 1, roughness = 1;
    double ior = 1.5;                        // KHR_materials_ior
    double specular = 1;                     // KHR_materials_specular
    rgb specularColor = grey(1);             // KHR_materials_specular
    smith_form masking = smith_form::separable;
    rgb sheenColor = grey(0);                // KHR_materials_sheen (0: off)
    double sheenRoughness = 0;               // KHR_materials_sheen
    double clearcoat = 0;                    // KHR_materials_clearcoat (0: off)
    double clearcoatRoughness = 0;           // KHR_materials_clearcoat
    double iridescence = 0, iridescenceIor = 1.3;  // KHR_materials_iridescence
    double iridescenceThickness = 400;            // nm: the thickness texture's value (no texture: the maximum, 400)
    double anisotropyStrength = 0, anisotropyRotation = 0;  // KHR_materials_anisotropy (radians)
    double transmission = 0;                                // KHR_materials_transmission
};

// The smallest sheenRoughness taken where the sheen is on: Charlie's D at alpha = 0 has no value
// ((2 + 1/alpha) sin^(1/alpha) t, its mass all at the horizon) and E's integral
// (sheen.hpp) is validated from alpha = 0.0025; the glTF Sample Viewer clamps instead.
inline constexpr double min_sheen_roughness = 0.05;
// The smallest clearcoatRoughness taken where the coat is on: alpha = 1e-8, as for roughness (a
// mirror coat, alpha = 0, is a delta: not integrated).
inline constexpr double min_clearcoat_roughness = 1e-4;

struct gltf {
    static constexpr std::string_view id = "gltf";
    static constexpr const char* literature =
        "glTF 2.0 Specification, Appendix B (BRDF implementation); KHR_materials_ior; KHR_materials_specular; "
        "KHR_materials_sheen; KHR_materials_clearcoat; KHR_materials_iridescence (Belcour and Barla 2017); "
        "KHR_materials_anisotropy; KHR_materials_transmission";
    static constexpr std::size_t lobe_count = 6;
    static constexpr std::array<std::string_view, lobe_count> lobe_ids = {"diffuse", "specular", "metal", "sheen",
                                                                          "clearcoat", "transmission"};
    // The core's lobes, the first ones (the material-furnace table's columns).
    static constexpr std::size_t core_lobe_count = 3;
    // roughness from 1e-4 (alpha = 1e-8, the smallest the microfacet integrals were validated at:
    // microfacet/albedo.hpp); ior 0 or from 1 (KHR_materials_ior: 0 gives F0 = 1), checked by
    // input_error; specularColor unbounded above in the extension, its product with F0 clamped.
    // iridescenceThickness up to 10 um, where the film's oscillating terms are below e^-100 of
    // its mean; iridescenceIor from 1 (the schema's minimum) to 1000, as ior.
    static constexpr std::array<parameter, 17> parameters = {{
        {"baseColor", "the base colour, linear RGB (R,G,B, or one number for grey), each in [0, 1]", 0, 1, {}, 1,
         false, 3},
        {"metallic", "the mix of the metal over the dielectric, in [0, 1]", 0, 1, {}, 1},
        {"roughness", "the perceptual roughness, alpha = roughness^2, in [1e-4, 1]", 1e-4, 1, {}, 1},
        {"ior", "the dielectric's index of refraction (KHR_materials_ior), 0 or in [1, 1000]", 0, 1000, {}, 1.5},
        {"specular", "the dielectric's specular weight (KHR_materials_specular), in [0, 1]", 0, 1, {}, 1},
        {"specularColor", "the dielectric's F0 colour (KHR_materials_specular), linear RGB, each in [0, 1000]", 0,
         1000, {}, 1, false, 3},
        {"masking", "specular_brdf's Smith masking-shadowing: the specification's separable form, or the "
                    "height-correlated form of the glTF Sample Viewer",
         0, 0, {}, 0, false, 1, smith_form_ids},
        {"sheenColor", "the sheen's colour (KHR_materials_sheen; 0: no sheen), linear RGB, each in [0, 1]", 0, 1, {}, 0,
         false, 3},
        {"sheenRoughness", "the sheen's roughness, alpha = sheenRoughness^2 (KHR_materials_sheen), in [0, 1]; at least "
                           "0.05 where sheenColor is not 0",
         0, 1, {}, 0},
        {"clearcoat", "the coat's weight (KHR_materials_clearcoat; 0: no coat), in [0, 1]", 0, 1, {}, 0},
        {"clearcoatRoughness", "the coat's roughness, alpha = clearcoatRoughness^2 (KHR_materials_clearcoat), in [0, 1]; "
                               "at least 1e-4 where clearcoat is not 0",
         0, 1, {}, 0},
        {"iridescence", "the thin film's weight (KHR_materials_iridescence), in [0, 1]", 0, 1, {}, 0},
        {"iridescenceIor", "the thin film's index of refraction (KHR_materials_iridescence), in [1, 1000]", 1, 1000, {},
         1.3},
        {"iridescenceThickness", "the thin film's thickness in nm, the value its thickness texture gives "
                                 "(KHR_materials_iridescence; no texture: iridescenceThicknessMaximum, 400), in [0, 10000]",
         0, 10000, {}, 400},
        {"anisotropyStrength", "the anisotropy's strength (KHR_materials_anisotropy): alpha along its direction "
                               "mix(alpha, 1, strength^2), in [0, 1]",
         0, 1, {}, 0},
        {"anisotropyRotation", "the anisotropy direction's angle from the tangent in radians (KHR_materials_anisotropy; "
                               "V lies in the tangent-normal plane), in [-10, 10]",
         -10, 10, {}, 0},
        {"transmission", "the thin-walled transmission's weight in the dielectric's base (KHR_materials_transmission), "
                         "in [0, 1]",
         0, 1, {}, 0},
    }};

    gltf_inputs in;

    // Why an input the declared ranges let through is refused, or nullptr: an ior in (0, 1); a
    // sheen or a coat too smooth to integrate (min_sheen_roughness, min_clearcoat_roughness); a
    // film or a sheen on an anisotropic lobe (the route about V they need errs beyond its bound for
    // a narrow anisotropic lobe); a sheen with transmission (its scaling reads E(N.L), which has
    // no value for L below the surface: docs/materials.md).
    static const char* input_error(const gltf_inputs& x) {
        if (x.ior > 0 && x.ior < 1) return "ior is 0 or at least 1 (KHR_materials_ior)";
        if (max_value(x.sheenColor) > 0 && x.sheenRoughness < min_sheen_roughness)
            return "sheenRoughness is at least 0.05 where sheenColor is not 0 (Charlie's D has no value at alpha = 0)";
        if (x.clearcoat > 0 && x.clearcoatRoughness < min_clearcoat_roughness)
            return "clearcoatRoughness is at least 1e-4 where clearcoat is not 0 (a mirror coat is a delta)";
        if (x.anisotropyStrength > 0 && (film_on(x) || max_value(x.sheenColor) > 0))
            return "anisotropyStrength with iridescence or sheenColor: a film or a sheen on an anisotropic lobe is not "
                   "integrated";
        if (max_value(x.sheenColor) > 0 && x.transmission > 0)
            return "sheenColor with transmission: the sheen's albedo scaling reads E(N.L), which has no value for L below "
                   "the surface";
        return nullptr;
    }
    static bool film_on(const gltf_inputs& x) { return x.iridescence > 0 && x.iridescenceThickness > 0; }
    // Why a compensation does not apply to these inputs, or nullptr: it is the core's, or the core's
    // under a coat.
    static const char* compensation_error(const gltf_inputs& x) {
        if (film_on(x) || x.anisotropyStrength > 0 || x.transmission > 0)
            return "a compensation applies to the glTF core only (iridescence, anisotropyStrength and transmission 0)";
        return nullptr;
    }

    // Number parameter i's component j (declaration order), choice parameter i's choice c.
    void set(std::size_t i, std::size_t j, double x) {
        double* slots[] = {&in.baseColor[j],        &in.metallic,           &in.roughness,     &in.ior,
                           &in.specular,            &in.specularColor[j],   nullptr /* masking */,
                           &in.sheenColor[j],       &in.sheenRoughness,     &in.clearcoat,     &in.clearcoatRoughness,
                           &in.iridescence,         &in.iridescenceIor,     &in.iridescenceThickness,
                           &in.anisotropyStrength,  &in.anisotropyRotation, &in.transmission};
        if (i < sizeof slots / sizeof slots[0] && slots[i]) *slots[i] = x;
    }
    void choose(std::size_t, std::size_t c) { in.masking = c == 0 ? smith_form::separable : smith_form::height_correlated; }

    double alpha() const { return in.roughness * in.roughness; }
    anisotropic_specular_brdf specular_lobe() const {
        return {specular_brdf{alpha(), in.masking}, in.anisotropyStrength, in.anisotropyRotation};
    }
    iridescence_layer iridescence() const { return {in.iridescence, {1, in.iridescenceIor, in.iridescenceThickness}}; }
    // Whether the albedo takes a route of nodes (coat_albedo.hpp): a film's weights are not affine
    // in Schlick's factor (the half vector about V), and an anisotropic lobe is no composition's
    // (its own map).
    bool by_nodes() const { return iridescence().active() || specular_lobe().anisotropic(); }
    // The values of V.H where the weights have kinks (a film's: iridescence_layer::kinks), for
    // the node-by-node integral's breakpoints; none without a film.
    std::vector<double> weight_kinks() const {
        const iridescence_layer film = iridescence();
        if (!film.active()) return {};
        const rgb f0 = weight_terms();
        return film.kinks({in.specular * f0, in.baseColor},
                          [&](double vh) { return film.dielectric(vh, dielectric().layer(vh, f0), in.specular * f0); });
    }
    // Whether an extension changes the core (a compensation applies to the core only).
    bool extended() const { return compensation_error(in) != nullptr; }
    bool sheen_on() const { return max_value(in.sheenColor) > 0; }
    bool coat_on() const { return in.clearcoat > 0; }
    sheen_brdf sheen_lobe() const { return {in.sheenRoughness * in.sheenRoughness}; }
    albedo_scaling sheen_scaling() const { return {max_value(in.sheenColor)}; }
    specular_brdf coat_lobe() const { return {in.clearcoatRoughness * in.clearcoatRoughness, in.masking}; }
    fresnel_coat coat() const { return {in.clearcoat}; }
    mix metal_mix() const { return {in.metallic}; }
    fresnel_mix dielectric() const { return {in.specularColor, in.ior, in.specular}; }
    conductor_fresnel metal() const { return {in.baseColor}; }

    // Where each lobe's albedo is integrated: the diffuse in the flat map, the microfacet lobes
    // (specular, metal, transmission) in their GGX's own (material.hpp, lobe_map); the sheen
    // (Charlie's D, and the scaling it puts on the others) and the coat (its own alpha) not node by
    // node, where on.
    std::array<lobe_map, lobe_count> maps() const {
        return {{{1, false}, {alpha(), true}, {alpha(), true}, {alpha(), true, !sheen_on()}, {alpha(), true, !coat_on()},
                 {alpha(), true}}};
    }
    // Whether albedo_of (material/albedo.hpp) integrates lobe i: the core's three, the coat
    // (weights affine in Schlick's factor) and the transmission; the sheen lobe and its scaling are
    // gltf_albedo's (material/sheen_albedo.hpp).
    bool in_albedo_of(std::size_t i) const { return i < 3 || (i == 4 && coat_on()) || i == transmission_lobe; }

    // What the weights read of the inputs alone (the dielectric's F0 per channel): computed once
    // by an integral's caller, not at each node.
    rgb weight_terms() const { return dielectric().f0(); }

    // The weights of the lobes at the cosines c, from the operators above; f0 = weight_terms().
    // The transmission lobe's c are those of L's mirror (transmission.hpp): V.H_T. The sheen's
    // albedo scaling of the core's lobes, a factor of N.L through E(N.L), is not among them:
    // f_lobes applies it, gltf_albedo integrates it.
    std::array<rgb, lobe_count> weights(const cosines& c, const rgb& f0) const {
        const mix m = metal_mix();
        const fresnel_mix d = dielectric();
        const fresnel_coat k = coat();
        const double under = k.base(c.nv);  // 1 exactly without a coat
        const iridescence_layer film = iridescence();
        rgb layer = d.layer(c.vh, f0), metal_f = metal().weight(c.vh);
        double base = d.base(c.vh, f0);
        if (film.active()) {
            layer = film.dielectric(c.vh, layer, in.specular * f0);
            base = 1 - max_value(layer);
            metal_f = film.metal(c.vh, metal_f, in.baseColor);
        }
        const double t = in.transmission;
        return {{under * (m.base() * base * (1 - t) * in.baseColor), under * (m.base() * layer), under * (m.layer() * metal_f),
                 under * in.sheenColor, grey(k.layer(c.nv)), under * (m.base() * base * t * in.baseColor)}};
    }

    // What rounding can move each weight beyond a few ulps, per channel: a film's Fresnel where it
    // is ill-conditioned (iridescence_layer::rounding; 1 - max_value moves by at most the largest
    // channel's), 0 without a film. material/albedo.hpp adds it to the nodes' bounds.
    std::array<rgb, lobe_count> weight_rounding(const cosines& c, const rgb& f0) const {
        const iridescence_layer film = iridescence();
        if (!film.active()) return {};
        const mix m = metal_mix();
        const double under = coat().base(c.nv), t = in.transmission;
        const rgb layer = film.rounding(c.vh, in.specular * f0), metal_f = film.rounding(c.vh, in.baseColor);
        const double base = max_value(layer);
        return {{under * (m.base() * base * (1 - t) * in.baseColor), under * (m.base() * layer), under * (m.layer() * metal_f),
                 grey(0), grey(0), under * (m.base() * base * t * in.baseColor)}};
    }

    // Without a film every weight is affine in (1 - |V.H|)^5 (material/albedo.hpp, albedo_of):
    // Schlick's factor enters each operator linearly, and max_value of fr is fr at the largest F0
    // (fr grows with F0); the coat's weights read N.V alone, constant where V is held. With a film
    // (by_nodes()) the albedo is integrated node by node.
    static constexpr bool weights_affine_in_schlick = true;
    // The weights read V.H and N.V alone (the sheen's scaling, which reads N.L, is f_lobes'): a film's
    // albedo integrates its Fresnel once a node of V.H (material/about_v.hpp).
    static constexpr bool weights_of_vh_alone = true;

    // Lobe i as a composition at its alpha, times a factor: specular_brdf is ggx/G/schlick's
    // single scattering (its F the weight's); diffuse_brdf = 1/pi is 4 x ggx/implicit at alpha = 1,
    // D = 1/pi, G / (4 N.L N.V) = 1/4.
    struct lobe_as_composition {
        microfacet::composition c;
        double alpha, scale;
    };
    // The coat is specular_brdf at its own alpha; the sheen is charlie/charlie-sheen/one.
    lobe_as_composition lobe_composition(std::size_t i) const {
        if (i == 0) return {microfacet::composition::parse("ggx/implicit/schlick"), 1, 4};
        if (i == 3) return {microfacet::composition::parse("charlie/charlie-sheen/one"), sheen_lobe().alpha, 1};
        return {microfacet::composition::parse(in.masking == smith_form::separable ? "ggx/smith-separable/schlick"
                                                                                  : "ggx/smith-height-correlated/schlick"),
                i == 4 ? coat_lobe().alpha : alpha(), 1};
    }

    // Each lobe's scalar BRDF at unit L, V above the horizon: 1/pi, V D, V D, the sheen's V D, the
    // coat's (0 where off), and V D at L's mirror for the transmission.
    std::array<double, lobe_count> lobes(const vec3<double>& l, const vec3<double>& v, const vec3<double>& h) const {
        const double s = specular_lobe().value(l, v, h);
        return {{diffuse_brdf::value(), s, s, sheen_on() ? sheen_lobe().value(l, v, h) : 0.0,
                 coat_on() ? coat_lobe().value(l, v, h) : 0.0, s}};
    }

    // Each lobe's contribution to f(L, V) (weight x lobe), per channel: the reflected lobes for
    // L above the horizon, the transmission for L below it (at L's mirror); 0 for V below.
    std::array<rgb, lobe_count> f_lobes(const vec3<double>& l_in, const vec3<double>& v) const {
        std::array<rgb, lobe_count> out{};
        const bool below = l_in.z() < 0;
        const vec3<double> l = below ? through_surface(l_in) : l_in;
        if (!(l.z() > 0 && v.z() > 0) || (below && in.transmission == 0)) return out;
        const vec3<double> h = half_vector(l, v);
        const cosines c{l.z(), v.z(), h.z(), v.dot(h)};
        const auto w = weights(c, weight_terms());
        const auto b = lobes(l, v, h);
        for (std::size_t i = 0; i < lobe_count; ++i)
            if ((i == transmission_lobe) == below) out[i] = b[i] * w[i];
        if (sheen_on() && !below) {  // the albedo scaling of the core's lobes, E from the sheen's curve
            const auto e = sheen_curve_for(sheen_lobe().alpha, sheen_curve_tolerance);
            const double s = sheen_scaling().factor((*e)(c.nv).value, (*e)(c.nl).value);
            // (E to 1e-11 times max(1, E): f is exact to about that where the sheen is on)
            for (std::size_t i = 0; i < 3; ++i) out[i] = s * out[i];
        }
        return out;
    }
    static constexpr std::size_t transmission_lobe = 5;
    // the tolerance of the sheen's E (sheen_curve.hpp) in f and, at the default tolerance, in the albedo
    static constexpr double sheen_curve_tolerance = 1e-11;

    rgb f(const vec3<double>& l, const vec3<double>& v) const {
        rgb sum{};
        for (const rgb& x : f_lobes(l, v)) sum = sum + x;
        return sum;
    }
};

}  // namespace normzoo::material
