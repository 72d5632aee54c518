// EON, the energy-preserving Oren-Nayar diffuse BRDF (Portsmouth, Kutz and Hill 2025, "EON: A
// practical energy-preserving rough diffuse BRDF", JCGT 14(1); OpenPBR 1.1's base diffuse), with its
// roughness r (the paper's r, OpenPBR's base_diffuse_roughness) and its albedo rho (p.specular):
//   f = f_FON + f_ms,
//   f_FON = (rho / pi) A (1 + r s / t),  A = 1 / (1 + c1 r),  c1 = 1/2 - 2/(3 pi),
//           s = L.V - N.L N.V,  s / t = s / max(N.L, N.V) where s > 0, s elsewhere (Fujii's form)
//   f_ms  = (rho_ms / pi) (1 - E(N.L)) (1 - E(N.V)) / (1 - E_avg),
//           rho_ms = rho^2 E_avg / (1 - rho (1 - E_avg)),  E_avg = A (1 + c2 r),  c2 = 2/3 - 28/(15 pi)
// with E(mu) FON's directional albedo at rho = 1 in closed form:
//   E(mu) = A + (r A / pi) G(mu),
//   G = S (acos mu - S mu) + (2/3) ((S / mu) (1 - S^3) - S),  S = sqrt(1 - mu^2).
// Written without cancellation (docs/models.md#eon): (S / mu)(1 - S^3) = S mu (1 + S + S^2) / (1 + S);
// 1 - E = r A (c1 - G / pi); 1 - E_avg = (c1 - c2) r A; so (1 - E_o)(1 - E_i) / (1 - E_avg) =
// r A (c1 - G_o / pi)(c1 - G_i / pi) / (c1 - c2), which is 0 at r = 0, the limit the paper's
// listing reaches through max(1e-7, ...) guards (those guards add rho_ms 1e-7 to the albedo for
// r below ~5e-7; normzoo takes the formula, not the guards).
// Its albedo is rho E(mu) + rho_ms (1 - E(mu)) (the lobe f_ms's is rho_ms (1 - E(mu)), as E_avg is
// E's cosine-weighted average): 1 at rho = 1 for every r, the white furnace.
#pragma once
#include <cmath>

#include "brdf.hpp"

namespace normzoo::brdf {

inline constexpr parameter eon_roughness{"r", "the EON roughness (the paper's r, OpenPBR's base_diffuse_roughness)", 0, 1,
                                         disney_roughnesses};
inline constexpr parameter eon_albedo{"specular", "rho, the diffuse albedo (1: the white furnace)", 0, 1, {}, 1};

struct eon {
    static constexpr const char* id = "eon";
    static constexpr const char* formula =
        "(rho/pi) A (1 + r s/t) + (rho_ms/pi) (1 - E(N.L)) (1 - E(N.V)) / (1 - E_avg), A = 1/(1 + (1/2 - 2/(3 pi)) r)";
    static constexpr const char* literature =
        "Portsmouth, Kutz and Hill 2025, \"EON: A practical energy-preserving rough diffuse BRDF\"; Fujii 2013 (FON)";
    static constexpr std::array<parameter, 2> parameters{eon_roughness, eon_albedo};
    static constexpr bool has_exponent = false;
    static constexpr bool has_specular = true;  // rho
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::normal;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;
    // s / max(N.L, N.V) switches its denominator where N.L = N.V (s > 0 there): a kink.
    static constexpr bool kink_where_cosines_equal = true;
    static constexpr check_point monte_carlo_case{1, 60};

    template <class T>
    static T c1() { return T(1) / 2 - 2 / (3 * pi<T>()); }
    template <class T>
    static T c2() { return T(2) / 3 - 28 / (15 * pi<T>()); }
    // G(mu) of E(mu) = A + (r A / pi) G(mu), without cancellation at either end.
    template <class T>
    static T g_of(const T& mu) {
        using std::acos; using std::sqrt;
        const T s = sqrt((1 - mu) * (1 + mu));
        return s * (acos(mu) - s * mu) + 2 * (s * mu * (1 + s + s * s) / (1 + s) - s) / 3;
    }
    // FON's albedo at rho = 1, E(mu), and 1 - E(mu) = r A (c1 - G / pi).
    template <class T>
    static T fon_albedo(const T& mu, const T& r) {
        const T a = 1 / (1 + c1<T>() * r);
        return a + r * a * g_of(mu) / pi<T>();
    }
    template <class T>
    static T rho_ms(const T& rho, const T& r) {
        const T a = 1 / (1 + c1<T>() * r), avg = a * (1 + c2<T>() * r), lost = (c1<T>() - c2<T>()) * r * a;
        return rho * rho * avg / (1 - rho * lost);
    }

    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        const T nl = l.z(), nv = v.z();
        if (!(nl > 0 && nv > 0)) return T(0);
        const T r = p.roughness, rho = p.specular, a = 1 / (1 + c1<T>() * r);
        const T s = l.x() * v.x() + l.y() * v.y();  // L.V - N.L N.V, from the tangential parts
        const T s_over_t = s > 0 ? s / (nl > nv ? nl : nv) : s;
        const T single = rho / pi<T>() * a * (1 + r * s_over_t);
        const T lost_l = c1<T>() - g_of(nl) / pi<T>(), lost_v = c1<T>() - g_of(nv) / pi<T>();
        const T multiple = rho_ms(rho, r) / pi<T>() * r * a * lost_l * lost_v / (c1<T>() - c2<T>());
        return single + multiple;
    }
    // rho A + rho_ms (1 - A): G(1) = 0.
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        const T a = 1 / (1 + c1<T>() * p.roughness);
        return p.specular * a + rho_ms(p.specular, p.roughness) * (1 - a);
    }
    // At every incidence: rho E(mu) + rho_ms (1 - E(mu)).
    template <class T>
    static T albedo_of(const T& mu, const params<T>& p) {
        const T e = fon_albedo(mu, p.roughness);
        return p.specular * e + rho_ms(p.specular, p.roughness) * (1 - e);
    }
};

}  // namespace normzoo::brdf
