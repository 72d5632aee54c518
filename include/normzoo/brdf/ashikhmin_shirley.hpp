// Ashikhmin and Shirley 2000, "An anisotropic Phong BRDF model": the anisotropic specular lobe
// and the diffuse term made to pair with it.
//   specular  sqrt((n_u+1)(n_v+1)) / (8 pi) (N.H)^(n_u cos^2 p_h + n_v sin^2 p_h) / ((H.L) max(N.L, N.V))
//             F_schlick(R_s, H.L); here R_s = 1 (F = 1, the white furnace). The anisotropic form
//             takes n_u = n, n_v = 4n (u in the plane of incidence).
//   diffuse   28 R_d / (23 pi) (1 - R_s) (1 - (1 - N.L/2)^5) (1 - (1 - N.V/2)^5), R_d = 1, R_s = 0.
// Closed forms: the diffuse albedo is 1 - (1 - cos t/2)^5 at every incidence (28/(23 pi) is the
// reciprocal of 2 pi integral_0^1 (1 - (1 - c/2)^5) c dc = 23 pi / 28). At L = N the specular
// lobe is (n+1)/(8 pi) c^(n-1) in c = N.H (L.H = c, max(N.L, N.V) = 1), whose albedo is
// brdf.hpp's half-vector moment; anisotropic, the mean of that moment over the azimuth of H at
// exponent n_u cos^2 + n_v sin^2 (periodic trapezoid, 256 nodes).
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cmath>

#include "brdf.hpp"

namespace normzoo::brdf {

template <int AspectRatio>
struct ashikhmin_shirley_form {
    static constexpr bool anisotropic = AspectRatio != 1;
    static constexpr std::array<parameter, 2> parameters{
        parameter{"n", "the exponent n_u (n_v = n_u times the aspect ratio)", 0, 1e9, anisotropic_phong_exponents},
        parameter{"specular", "R_s, Schlick's F0 (1: F = 1, the white furnace)", 0, 1, {}, 1}};
    static constexpr const char* literature = "Ashikhmin and Shirley 2000, \"An anisotropic Phong BRDF model\"";
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = true;
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::half;
    static constexpr int inverse_lh_power = 1;
    static constexpr bool fresnel = true;
    // max(N.L, N.V) has a kink where N.V = N.L: the albedo integral puts a breakpoint there.
    static constexpr bool kink_where_cosines_equal = true;

    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        using std::exp;
        using std::log1p;
        using std::sqrt;
        const T nl = l.z(), nv = v.z();
        if (!(nl > 0 && nv > 0)) return T(0);
        const T nu = p.n, nvv = p.n * AspectRatio;
        const vec3<T> h = half_vector(l, v);
        // (N.H)^e with N.H = sqrt(1 - s^2), s^2 = h_x^2 + h_y^2: exp(e/2 log1p(-s^2)), e s^2 = n_u h_x^2 + n_v h_y^2
        const T s2 = h.x() * h.x() + h.y() * h.y();
        const T lobe = s2 > 0 ? exp((nu * h.x() * h.x() + nvv * h.y() * h.y()) / s2 / 2 * log1p(-s2)) : T(1);
        const T lh = l.dot(h);
        return sqrt((nu + 1) * (nvv + 1)) / (8 * pi<T>()) * lobe / (lh * (nl > nv ? nl : nv)) *
               fresnel_schlick(p.specular, lh);
    }
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        using std::cos;
        using std::sqrt;
        const T nu = p.n, nvv = p.n * AspectRatio;
        const T k = sqrt((nu + 1) * (nvv + 1)) / (8 * pi<T>());
        if (AspectRatio == 1) return k * detail::half_vector_albedo_moment(nu - 1);
        const int m = 256;
        T sum = 0;
        for (int i = 0; i < m; ++i) {
            const T c = cos(boost::math::constants::two_pi<T>() * i / m);
            sum += detail::half_vector_albedo_moment(nu * c * c + nvv * (1 - c * c) - 1);
        }
        return k * sum / m;
    }
};

struct ashikhmin_shirley : ashikhmin_shirley_form<1> {
    static constexpr const char* id = "ashikhmin-shirley";
    static constexpr const char* formula = "(n+1)/(8 pi) (N.H)^n / ((H.L) max(N.L, N.V)) F_schlick(R_s, H.L)";
    static constexpr check_point monte_carlo_case{100, 30};
};

struct ashikhmin_shirley_aniso : ashikhmin_shirley_form<4> {
    static constexpr const char* id = "ashikhmin-shirley-aniso";
    static constexpr const char* formula =
        "sqrt((n_u+1)(n_v+1))/(8 pi) (N.H)^(n_u cos^2 p_h + n_v sin^2 p_h) / ((H.L) max(N.L, N.V)) F, n_u = n, n_v = 4n";
    static constexpr check_point monte_carlo_case{10, 60};
};

struct ashikhmin_shirley_diffuse {
    static constexpr const char* id = "ashikhmin-shirley-diffuse";
    static constexpr const char* formula = "28/(23 pi) (1 - (1 - N.L/2)^5) (1 - (1 - N.V/2)^5)";
    static constexpr const char* literature = "Ashikhmin and Shirley 2000, \"An anisotropic Phong BRDF model\"";
    static constexpr std::array<parameter, 0> parameters{};  // R_d = 1, R_s = 0: the white furnace
    static constexpr check_point monte_carlo_case{0, 45};
    static constexpr bool has_exponent = false;
    static constexpr bool has_specular = false;
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::normal;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;

    // 1 - (1 - x)^5 with x = c/2, expanded: 1 - (1 - x)^5 cancels to nothing near grazing (c -> 0)
    template <class T>
    static T edge(const T& c) {
        const T x = c / 2;
        return x * (5 + x * (-10 + x * (10 + x * (-5 + x))));
    }
    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& /*p*/) {
        const T nl = l.z(), nv = v.z();
        if (!(nl > 0 && nv > 0)) return T(0);
        return 28 / (23 * pi<T>()) * edge(nl) * edge(nv);
    }
    // At every incidence: 1 - (1 - cos t / 2)^5.
    template <class T>
    static T albedo_at(const T& cos_t) { return edge(cos_t); }
    template <class T>
    static T albedo_at_normal(const params<T>& /*p*/) { return edge(T(1)); }
};

}  // namespace normzoo::brdf
