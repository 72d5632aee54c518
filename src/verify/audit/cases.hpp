// The error audit's cases: the families, the settings, and the random draws (docs/error-audit.md,
// "What is drawn").
//
// Families (one summary per family and number type):
//   zoo-1d      every zoo row by the 1D lobe quadrature, in binary128 and in double
//   zoo-2d      every zoo row by the 2D vector quadrature, in long double
//   irradiance  sphere and disk lights by the cap quadrature (binary128), tilts above and
//               across the horizon, r0/r log-uniform down to 1e-300
//   albedo      every BRDF form's directional albedo at normal incidence (double)
// Exponents are log-uniform over [1e-6, 1e7], with one draw in seven an exact small one
// (0, 0.5, 1, ..., 64).
//
// Reproducible: std::mt19937_64 (its output sequence is fixed by the C++ standard), one stream
// per family seeded with seed + family index, uniforms in [0, 1) from the top 53 bits of each
// output (std::uniform_real_distribution is left to each standard library).
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <normzoo/registry.hpp>

#include "../library_names.hpp"

namespace verify {

enum class audit_family {
    zoo_1d_quad,
    zoo_1d_double,
    zoo_2d,
    irradiance_sphere,
    irradiance_disk,
    irradiance_closed_form,
    albedo_normal
};

inline constexpr audit_family audit_families[] = {
    audit_family::zoo_1d_quad,     audit_family::zoo_1d_double,          audit_family::zoo_2d,
    audit_family::irradiance_sphere, audit_family::irradiance_disk, audit_family::irradiance_closed_form,
    audit_family::albedo_normal};

inline const char* audit_family_name(audit_family f) {
    switch (f) {
        case audit_family::zoo_1d_quad:
        case audit_family::zoo_1d_double: return "zoo-1d";
        case audit_family::zoo_2d: return "zoo-2d";
        case audit_family::irradiance_sphere: return "irradiance-sphere";
        case audit_family::irradiance_disk: return "irradiance-disk";
        case audit_family::irradiance_closed_form: return "irradiance-closed-form";
        case audit_family::albedo_normal: return "albedo-normal";
    }
    return "";
}

inline const char* audit_number_type(audit_family f) {
    switch (f) {
        case audit_family::zoo_1d_double:
        case audit_family::albedo_normal: return "double";
        case audit_family::zoo_2d: return "long double";
        default: return "binary128";
    }
}

struct audit_settings {
    std::uint64_t seed = 20240607;
    std::size_t cases = 10000;        // at least this many in all, shared among the families below
    double pessimism_limit = 1e6;     // e / max(t, u) above this is a defect
    double estimate_scale = 1;        // tests only: 0.1 makes every estimate dishonest by 10x
    double albedo_max_n = 1e7;
};

// The share of the cases each family gets (they add up to 1).
inline double audit_share(audit_family f) {
    switch (f) {
        case audit_family::zoo_1d_quad: return 0.28;
        case audit_family::zoo_1d_double: return 0.16;
        case audit_family::zoo_2d: return 0.16;
        case audit_family::irradiance_sphere:
        case audit_family::irradiance_disk: return 0.11;
        case audit_family::irradiance_closed_form: return 0.06;
        case audit_family::albedo_normal: return 0.12;
    }
    return 0;
}

// One case to run: a member of a family (zoo row, light, BRDF form) and its parameters.
struct audit_case {
    audit_family family = audit_family::zoo_1d_quad;
    std::string member;
    double n = 0;         // exponent (zoo, albedo); 0 for a member without one
    double ratio = 0;     // r0 / r (lights)
    double tilt_deg = 0;  // tilt of the light's centre from N
};

namespace detail {

// Uniform in [0, 1) from the top 53 bits: the same numbers on every platform.
inline double audit_uniform(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1p-53; }

inline double audit_log_uniform(std::mt19937_64& g, double lo, double hi) {
    return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * audit_uniform(g));
}

// An exponent: one draw in seven an exact small one (0, 0.5, ..., 64), else log-uniform.
inline double audit_exponent(std::mt19937_64& g, double max_n) {
    if (audit_uniform(g) < 1.0 / 7) return std::floor(audit_uniform(g) * 129) / 2;
    return audit_log_uniform(g, 1e-6, max_n);
}

inline audit_case audit_new_case(audit_family f, std::string member, double n) {
    audit_case c;
    c.family = f, c.member = std::move(member), c.n = n;
    return c;
}

// The family's cases, drawn from its own stream.
inline std::vector<audit_case> audit_draw(audit_family f, const audit_settings& s) {
    std::mt19937_64 g(s.seed + static_cast<std::uint64_t>(f));
    std::vector<audit_case> out;
    const double share = audit_share(f) * static_cast<double>(s.cases);
    auto per = [&](std::size_t members) { return static_cast<std::size_t>(std::ceil(share / static_cast<double>(members))); };
    switch (f) {
        case audit_family::zoo_1d_quad:
        case audit_family::zoo_1d_double:
        case audit_family::zoo_2d: {
            // a row without an exponent has one answer: one case
            std::size_t with_exponent = 0;
            for_each_zoo_row([&](auto row) { with_exponent += decltype(row)::has_exponent; });
            for_each_zoo_row([&](auto row) {
                using Row = decltype(row);
                const std::size_t count = Row::has_exponent ? per(with_exponent) : 1;
                for (std::size_t i = 0; i < count; ++i) out.push_back(audit_new_case(f, Row::id, Row::has_exponent ? audit_exponent(g, 1e7) : 0.0));
            });
            break;
        }
        case audit_family::irradiance_sphere:
        case audit_family::irradiance_disk:
        case audit_family::irradiance_closed_form: {
            const std::size_t count = per(1);
            for (std::size_t i = 0; i < count; ++i) {
                // the closed form's cases alternate between the two lights
                const bool sphere = f == audit_family::irradiance_closed_form ? i % 2 == 0 : f == audit_family::irradiance_sphere;
                const double top = sphere ? 0.999 : 10;
                audit_case c = audit_new_case(f, sphere ? "sphere" : "disk", 0);
                // half the cases cross the horizon: only where the cap is wider than a double can
                // resolve about 90 degrees (r0/r >= 1e-12)
                const bool crossing = audit_uniform(g) < 0.5;
                c.ratio = audit_log_uniform(g, crossing ? 1e-12 : 1e-300, top);
                const double b_deg = (sphere ? std::asin(c.ratio) : std::atan(c.ratio)) * 180 / boost::math::constants::pi<double>();
                const double u = audit_uniform(g);
                // across: the band 90 +- b, kept a millionth of b from its ends; above: up to 90 - b
                c.tilt_deg = crossing ? 90 + b_deg * (2 * u - 1) * 0.999999 : (90 - b_deg) * u;
                out.push_back(c);
            }
            break;
        }
        case audit_family::albedo_normal: {
            std::size_t with_exponent = 0;
            for_each_zoo_brdf([&](auto form) { with_exponent += decltype(form)::has_exponent; });
            for_each_zoo_brdf([&](auto form) {
                using Form = decltype(form);
                const std::size_t count = Form::has_exponent ? per(with_exponent) : 1;
                for (std::size_t i = 0; i < count; ++i)
                    out.push_back(audit_new_case(f, Form::id, Form::has_exponent ? audit_exponent(g, s.albedo_max_n) : 0.0));
            });
            break;
        }
    }
    return out;
}

}  // namespace detail

// Every family's cases, in a fixed order.
inline std::vector<audit_case> audit_cases(const audit_settings& s) {
    std::vector<audit_case> all;
    for (audit_family f : audit_families) {
        auto part = detail::audit_draw(f, s);
        all.insert(all.end(), part.begin(), part.end());
    }
    return all;
}

}  // namespace verify
