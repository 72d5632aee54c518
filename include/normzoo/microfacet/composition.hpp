// A microfacet BRDF composed from parts (docs/microfacet.md):
//     f(L, V) = D(h) G(L, V, h) F(V.h) / (4 N.L N.V),   h = (L + V) / |L + V|,
// named by the id "D/G/F" of its parts (distribution.hpp, masking.hpp, fresnel.hpp), for example
// ggx/smith-height-correlated/one. It is a BRDF form of brdf/brdf.hpp whose parts are chosen at
// run time: one type, so the albedo integral is compiled once for every composition.
//   params.roughness  alpha (Walter et al. 2007); an anisotropic D takes alpha_y = aspect x alpha
//   params.specular   F0 of the Schlick parts; a dielectric's F0 gives its index,
//                     eta = (1 + sqrt F0) / (1 - sqrt F0)
//   params.n          the Phong-Beckmann exponent 2/alpha^2 - 2: where the albedo integral
//                     places its nodes (node_exponent)
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "../brdf/brdf.hpp"
#include "distribution.hpp"
#include "fixed_composition.hpp"
#include "fresnel.hpp"
#include "masking.hpp"

namespace normzoo::microfacet {

namespace detail {

using normzoo::detail::ids_of;
using normzoo::detail::index_of;
// fn(part) for the part at `index` of the list Parts, its result as R.
template <class Parts, class R, class Fn>
R visit_part(std::size_t index, const Fn& fn) {
    return normzoo::detail::visit_index<Parts, R>(index, fn);
}

// The ids of the parts of Parts that read the parameter `name`, comma-separated.
template <class Parts>
std::string readers_of(std::string_view name) {
    std::string s;
    normzoo::detail::for_each_of<Parts>([&](auto part) {
        if (declares(decltype(part)::parameters, name)) s += (s.empty() ? "" : ", ") + std::string(decltype(part)::id);
    });
    return s;
}

}  // namespace detail

struct composition {
    // The traits the albedo integral reads (brdf/brdf.hpp), the same for every composition: the
    // lobe is about h, n places the nodes, and the tails of GGX-like distributions are not cut
    // (heavy_tail). The rounding model of a node takes the worst any G or F has: 1/(L.h)^2
    // (Kelemen's) and a Fresnel term.
    static constexpr brdf::lobe_kind lobe = brdf::lobe_kind::half;
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = true;
    static constexpr bool fresnel = true;
    static constexpr int inverse_lh_power = 2;
    static constexpr bool heavy_tail = true;
    static constexpr bool reciprocal = true;

    std::string id;          // "D/G/F", as given
    std::size_t d_part = 0, g_part = 0, f_part = 0;  // the parts' places in their lists
    // The parts' parameters beyond alpha and F0 (docs/microfacet.md#part-parameters); each part
    // names those it reads (its `parameters`, composition::reads).
    double aspect = 1;       // alpha_y / alpha_x of an anisotropic D
    double gamma = 2;        // GTR's exponent
    double f90 = 1;          // schlick-f90's F90
    double eta = 0;          // the exact parts' index; 0: from F0, as a dielectric's (1 + sqrt F0)/(1 - sqrt F0)
    double k = 0;            // a conductor's extinction coefficient

    // The multiple-scattering compensation named by a fourth part (microfacet/multiple_scattering.hpp):
    // none, Kulla and Conty 2017's lobe, Turquin 2019's scaling or Fdez-Aguera 2019's series. f() is
    // the single-scattering BRDF either way; the compensation enters the albedo (compensated_albedo).
    enum class compensation_kind { none, kulla_conty, turquin, fdez_aguera };
    compensation_kind compensation = compensation_kind::none;
    // A fourth part "transmission": the albedo is the interface's, reflection plus Walter et al.
    // 2007's rough BTDF (rough_dielectric.hpp), of ggx/smith-separable/dielectric alone; f() stays
    // the reflection.
    bool transmission = false;

    // Parses "D/G/F" or "D/G/F/kulla-conty", "D/G/F/turquin", "D/G/F/fdez-aguera", or
    // "ggx/smith-separable/dielectric/transmission"; throws std::invalid_argument
    // naming the part that is not known (and the ones that are), or a Smith G over a D whose
    // Lambda has no closed form.
    static composition parse(std::string_view text) {
        composition c;
        c.id = std::string(text);
        std::string_view parts[4];
        std::size_t count = 0, start = 0;
        while (count < 4) {
            const std::size_t slash = text.find('/', start);
            parts[count++] = text.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
            if (slash == std::string_view::npos) break;
            start = slash + 1;
            if (count == 4) count = 5;  // a fifth part
        }
        if (count < 3 || count > 4)
            throw std::invalid_argument("'" + c.id + "' is not a composition D/G/F (three part ids separated by '/', "
                                        "optionally a fourth: kulla-conty, turquin, fdez-aguera or transmission)");
        if (count == 4) {
            if (parts[3] == "kulla-conty") c.compensation = compensation_kind::kulla_conty;
            else if (parts[3] == "turquin") c.compensation = compensation_kind::turquin;
            else if (parts[3] == "fdez-aguera") c.compensation = compensation_kind::fdez_aguera;
            else if (parts[3] == "transmission") c.transmission = true;
            else
                throw std::invalid_argument("unknown fourth part '" + std::string(parts[3]) + "' in '" + c.id +
                                            "' (known: kulla-conty, turquin, fdez-aguera, transmission)");
        }
        auto find = [&](auto list, std::string_view id, const char* what) {
            const std::size_t i = detail::index_of<decltype(list)>(id);
            if (i == std::tuple_size_v<decltype(list)>)
                throw std::invalid_argument("unknown " + std::string(what) + " part '" + std::string(id) + "' in '" +
                                            c.id + "' (known: " + detail::ids_of<decltype(list)>() + ")");
            return i;
        };
        c.d_part = find(distribution_parts{}, parts[0], "D");
        c.g_part = find(masking_parts{}, parts[1], "G");
        c.f_part = find(fresnel_parts{}, parts[2], "F");
        const bool exact_lambda = detail::visit_part<distribution_parts, bool>(
            c.d_part, [](auto part) { return decltype(part)::has_exact_lambda; });
        const bool needs_lambda = detail::visit_part<masking_parts, bool>(
            c.g_part, [](auto part) { return decltype(part)::needs_lambda; });
        if (needs_lambda && !exact_lambda)
            throw std::invalid_argument("'" + c.id + "': " + std::string(parts[1]) + " needs Smith's Lambda of " +
                                        std::string(parts[0]) + ", which has no closed form");
        if (c.transmission && (parts[0] != "ggx" || parts[1] != "smith-separable" || parts[2] != "dielectric"))
            throw std::invalid_argument("'" + c.id + "': the transmitting interface is ggx/smith-separable/dielectric/transmission "
                                        "(Walter et al. 2007's BTDF with Smith's separable G), not " +
                                        std::string(parts[0]) + "/" + std::string(parts[1]) + "/" + std::string(parts[2]));
        return c;
    }

    // Whether o is the same single-scattering BRDF: the same parts with the same parameters
    // (the id as typed and the compensation aside; a transmitting interface is another: its albedo is).
    bool same_brdf(const composition& o) const {
        return d_part == o.d_part && g_part == o.g_part && f_part == o.f_part && aspect == o.aspect && gamma == o.gamma &&
               f90 == o.f90 && eta == o.eta && k == o.k && transmission == o.transmission;
    }

    // Whether the D or F part reads the parameter `name` (aspect, gamma, f0, f90, eta, k).
    bool reads(std::string_view name) const {
        auto in = [&](auto part) { return declares(decltype(part)::parameters, name); };
        return detail::visit_part<distribution_parts, bool>(d_part, in) || detail::visit_part<fresnel_parts, bool>(f_part, in);
    }

    // The parameters it reads beyond alpha, declared by its D and F parts (part_parameters.hpp),
    // each once, D's first: a composition declares its parameters as a form does, at run time.
    std::vector<parameter> parameters() const {
        std::vector<parameter> list;
        auto add = [&](auto part) {
            for (const parameter& p : decltype(part)::parameters)
                if (!declares(list, p.name)) list.push_back(p);
            return true;
        };
        detail::visit_part<distribution_parts, bool>(d_part, add);
        detail::visit_part<fresnel_parts, bool>(f_part, add);
        return list;
    }

    // The ids of the D and F parts that read the parameter `name`, for messages.
    static std::string readers_of(std::string_view name) {
        const std::string d = detail::readers_of<distribution_parts>(name), f = detail::readers_of<fresnel_parts>(name);
        return d + (d.empty() || f.empty() ? "" : ", ") + f;
    }

    // The part ids, list by list, for help texts.
    static std::string known_parts() {
        return "D: " + detail::ids_of<distribution_parts>() + "; G: " + detail::ids_of<masking_parts>() + "; F: " +
               detail::ids_of<fresnel_parts>() + "; optional fourth part: kulla-conty, turquin, fdez-aguera";
    }

    template <class T>
    static T node_exponent(const T& alpha) {
        const T n = 2 / (alpha * alpha) - 2;
        return n > 0 ? n : T(0);
    }

    template <class T>
    ndf_params<T> ndf(const T& alpha) const {
        ndf_params<T> np;
        np.alpha_x = alpha, np.alpha_y = alpha * T(aspect), np.gamma = T(gamma);
        return np;
    }

    // Whether the D part is anisotropic (brdf::anisotropic), whatever the aspect.
    bool anisotropic_lobe() const {
        return !detail::visit_part<distribution_parts, bool>(d_part, [](auto part) { return decltype(part)::isotropic; });
    }

    // Where f has kinks that are not at the albedo integral's breakpoints (a G that is a min():
    // Cook-Torrance's), the values of V.h along them (masking.hpp, g_cook_torrance::kink_vm);
    // nullptr for a smooth G.
    using kink_vm_fn = int (*)(double nv, double nm, double vm[3]);
    kink_vm_fn kink_vm() const {
        return g_part == detail::index_of<masking_parts>("cook-torrance") ? &g_cook_torrance::kink_vm : nullptr;
    }
    // The V.h of total internal reflection's critical angle, sqrt(1 - eta^2), where F has a kink
    // (1 beyond it, an infinite slope below: docs/microfacet.md, "Total internal reflection"): a
    // dielectric's at eta < 1, and a conductor's, where k rounds the kink but for small k hardly
    // (a breakpoint does no harm where it is smooth); 0 where F has none. An index from F0 is >= 1.
    double critical_vh() const {
        const bool exact = f_part == detail::index_of<fresnel_parts>("dielectric") || f_part == detail::index_of<fresnel_parts>("conductor");
        if (!exact || !(eta > 0 && eta < 1)) return 0;
        // below eta ~ 1e-8 it rounds to 1: F is 1 at every V.h a double holds but 1, no kink inside
        const double c = std::sqrt((1 - eta) * (1 + eta));
        return c < 1 ? c : 0;
    }
    // Whether f has kinks the albedo integrals take as breakpoints: G's or F's.
    bool kinked() const { return kink_vm() != nullptr || critical_vh() > 0; }
    // Whether the D part has the polar map that microfacet/albedo.hpp integrates in.
    bool has_polar_map() const {
        return detail::visit_part<distribution_parts, bool>(d_part, [](auto part) { return decltype(part)::has_polar_map; });
    }

    // What G F reads of V alone (Smith's Lambda of V, the Fresnel parameters): the albedo
    // integral evaluates G F at thousands of L for one V, so this is computed once.
    // The parts are reached through plain function pointers, chosen here once: a visit over the
    // lists at every node cost a fifth of the albedo's time.
    template <class T>
    struct view_terms {
        ndf_params<T> np;
        fresnel_params<T> fp;
        T alpha = 0, lambda_v = 0;
        bool needs_lambda = false;
        T (*lambda)(const vec3<T>&, const ndf_params<T>&) = nullptr;  // D's, where G reads it
        T (*g)(const shading<T>&) = nullptr;
        T (*fresnel)(const T&, const fresnel_params<T>&) = nullptr;
    };

    template <class T>
    view_terms<T> at_view(const vec3<T>& v, const brdf::params<T>& p) const {
        view_terms<T> t;
        t.np = ndf(p.roughness);
        t.alpha = p.roughness;
        t.needs_lambda = detail::visit_part<masking_parts, bool>(g_part, [](auto part) { return decltype(part)::needs_lambda; });
        using lambda_function = decltype(t.lambda);
        t.lambda = detail::visit_part<distribution_parts, lambda_function>(d_part, [](auto part) -> lambda_function {
            using D = decltype(part);
            if constexpr (D::has_exact_lambda) return &D::template lambda<T>;
            return nullptr;
        });
        if (t.needs_lambda) t.lambda_v = t.lambda(v, t.np);
        using g_function = decltype(t.g);
        t.g = detail::visit_part<masking_parts, g_function>(g_part, [](auto part) -> g_function { return &decltype(part)::template g<T>; });
        using fresnel_function = decltype(t.fresnel);
        t.fresnel = detail::visit_part<fresnel_parts, fresnel_function>(
            f_part, [](auto part) -> fresnel_function { return &decltype(part)::template eval<T>; });
        t.fp = fresnel_at(p.specular);
        return t;
    }

    // The Fresnel parameters at F0 = specular: the index eta, or a dielectric's from F0; F90 and k.
    template <class T>
    fresnel_params<T> fresnel_at(const T& specular) const {
        using std::sqrt;
        fresnel_params<T> fp;
        fp.f0 = specular, fp.f90 = T(f90), fp.k = T(k);
        if (eta > 0) {
            fp.eta = T(eta);
        } else {
            const T r = sqrt(specular);
            fp.eta = (1 + r) / (1 - r);
        }
        return fp;
    }

    // G at a shading point whose cosines s.nl, s.nv, s.nm, s.vm are set, for the direction L and
    // the terms of V (Smith's Lambdas are filled where G reads them).
    template <class T>
    T masking(shading<T>& s, const vec3<T>& l, const view_terms<T>& vt) const {
        s.alpha = vt.alpha;
        if (vt.needs_lambda) {
            s.lambda_v = vt.lambda_v;
            s.lambda_l = vt.lambda(l, vt.np);
        }
        return vt.g(s);
    }

    // G F at one shading point: the parts visited directly (setting up view_terms, whose function
    // pointers pay off over an integral, cost more than the visits for one evaluation).
    template <class T>
    T masking_fresnel(shading<T>& s, const vec3<T>& l, const vec3<T>& v, const brdf::params<T>& p) const {
        s.alpha = p.roughness;
        if (detail::visit_part<masking_parts, bool>(g_part, [](auto part) { return decltype(part)::needs_lambda; })) {
            const ndf_params<T> np = ndf(p.roughness);
            detail::visit_part<distribution_parts, bool>(d_part, [&](auto part) {
                using D = decltype(part);
                if constexpr (D::has_exact_lambda) s.lambda_l = D::lambda(l, np), s.lambda_v = D::lambda(v, np);
                return true;
            });
        }
        const fresnel_params<T> fp = fresnel_at(p.specular);
        const T gv = detail::visit_part<masking_parts, T>(g_part, [&](auto part) { return decltype(part)::g(s); });
        const T fv = detail::visit_part<fresnel_parts, T>(f_part, [&](auto part) { return decltype(part)::eval(s.vm, fp); });
        return gv * fv;
    }

    template <class T>
    T f(const vec3<T>& l, const vec3<T>& v, const brdf::params<T>& p) const {
        vec3<T> h;
        shading<T> s;
        if (!shading_point(l, v, h, s)) return T(0);
        const ndf_params<T> np = ndf(p.roughness);
        const T dv = detail::visit_part<distribution_parts, T>(d_part, [&](auto part) { return decltype(part)::d(h, np); });
        return dv * masking_fresnel(s, l, v, p) / (4 * s.nl * s.nv);
    }
};

}  // namespace normzoo::microfacet
