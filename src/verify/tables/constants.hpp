// The constants (docs/conventions.md, "The zoo rows") that shaders use beside the zoo rows ("Adopting a physically
// based shading model"):
//   microfacet-blinn   (n+2)/(8 pi): the heightfield NDF normalization over 4, checked by quadrature
//   approx             (n+8)/(8 pi) for blinn-phong-modified: its relative error against the exact
//                      factor, = the energy it gains at normal incidence (the exact factor gives 1)
//   gloss              n = 2^(10 g + 1), g in [0, 1] stored in 8 bits
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include <normzoo/detail/parallel.hpp>
#include <normzoo/zoo/blinn_phong.hpp>
#include <normzoo/real.hpp>
#include <normzoo/wide.hpp>

#include "../record.hpp"
#include "bounds.hpp"
#include "zoo.hpp"

namespace verify {

// (n+8)/(8 pi) / exact - 1 without cancellation: (3n - (n+8)(1 - 2^(-n/2))) / ((n+2)(n+4)).
template <class T = wide>
T approx_relative_error(const T& n) {
    const T one_minus_p = half_power(n).second;
    return (3 * n - (n + 8) * one_minus_p) / ((n + 2) * (n + 4));
}

// Largest relative error of (n+8)/(8 pi) over n in [0, n_max]: a log-spaced scan in double (the
// rewritten form has no cancellation, so double is accurate to ~1e-15 there), then golden-section
// refinement in log n, in 50 digits, around the best grid point.
inline std::pair<double, double> approx_worst_error(double n_max = 1e7) {
    auto scan = [](double ln) { return approx_relative_error<double>(std::exp(ln)); };
    auto err = [](double ln) { return static_cast<double>(approx_relative_error(wide(std::exp(ln)))); };
    const double lo = std::log(1e-6), hi = std::log(n_max);
    const int steps = 4000;
    int best = 0;
    double best_val = -1;
    for (int k = 0; k <= steps; ++k) {
        const double v = scan(lo + (hi - lo) * k / steps);
        if (v > best_val) best_val = v, best = k;
    }
    double a = lo + (hi - lo) * (best > 0 ? best - 1 : 0) / steps;
    double b = lo + (hi - lo) * (best < steps ? best + 1 : steps) / steps;
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 200 && b - a > 1e-9; ++it) {
        const double c = b - g * (b - a), d = a + g * (b - a);
        if (err(c) > err(d)) b = d;
        else a = c;
    }
    const double at = std::exp((a + b) / 2);
    return {err(std::log(at)), at};
}

inline std::vector<record> zoo_constants_table(const std::vector<decimal>& exponents, unsigned jobs) {
    std::vector<record> micro(exponents.size());
    detail::parallel_for(exponents.size(), jobs, [&](std::size_t i) {
        using std::abs;
        const decimal& n = exponents[i];
        const auto hf = zoo_norm_1d<zoo::blinn_phong_heightfield>(n);
        const quad from_ndf = hf.norm / 4;
        const quad closed = static_cast<quad>((n.to<wide>() + 2) / (8 * pi<wide>()));
        const quad rel = abs(from_ndf - closed) / closed;
        micro[i] = record{"zoo-constants", {}};
        micro[i]
            .set("constant", std::string("microfacet-blinn (n+2)/(8 pi)"))
            .set("n", n.to<double>())
            .set("n_input", n.text())
            .set("value", to_decimal(closed, 34))
            .set("reference", to_decimal(from_ndf, 34))
            .set("reference_is", std::string("heightfield NDF normalization by quadrature, / 4"))
            .set("rel_error", static_cast<double>(rel))
            .set("error_estimate", static_cast<double>(hf.rel_error))
            .set("pass", rel <= hf.rel_error + 8 * eps<quad>());
    });
    std::vector<record> out = micro;
    for (const auto& n_in : exponents) {
        const wide n = n_in.to<wide>();
        const wide exact = zoo::blinn_phong_modified::closed_form(n);
        const wide approx = (n + 8) / (8 * pi<wide>());
        const wide rel = approx_relative_error(n);
        const wide naive = approx / exact - 1;
        record r{"zoo-constants", {}};
        r.set("constant", std::string("approx (n+8)/(8 pi) for blinn-phong-modified"))
            .set("n", n_in.to<double>())
            .set("n_input", n_in.text())
            .set("value", to_decimal(approx, 34))
            .set("reference", to_decimal(exact, 34))
            .set("reference_is", std::string("exact (n+2)(n+4)/(8 pi (2^(-n/2)+n))"))
            .set("rel_error", static_cast<double>(rel))
            .set("energy_at_normal_incidence", static_cast<double>(1 + rel))
            // It is the upper bound, so it can only gain energy (equal at n = 0).
            .set("pass", (n == 0 ? rel == 0 : rel > 0) && abs(naive - rel) < wide(1e-45));
        out.push_back(r);
    }
    const auto [worst, at] = approx_worst_error();
    record w{"zoo-constants", {}};
    w.set("constant", std::string("approx (n+8)/(8 pi): largest relative error over n in [0, 1e7]"))
        .set("n", at)
        .set("n_input", decimal::exactly(at).text())
        .set("rel_error", worst)
        .set("energy_at_normal_incidence", 1 + worst);
    out.push_back(w);

    const double step = std::pow(2.0, 10.0 / 255) - 1, rounding = std::pow(2.0, 5.0 / 255) - 1;
    record g{"zoo-constants", {}};
    g.set("constant", std::string("gloss n = 2^(10 g + 1), g = k/255 in 8 bits: n from 2 to 2048"))
        .set("n", 2048.0)
        .set("n_input", std::string("2048"))
        .set("rel_error", rounding)
        .set("code_step_rel", step)
        .set("largest_step_n", 2048.0 * (1 - std::pow(2.0, -10.0 / 255)))
        .set("note", std::string("rel_error: worst relative error of n when an exponent is rounded to the nearest code"));
    out.push_back(g);
    return out;
}

inline table_info zoo_constants_info() {
    table_info info{
        "zoo-constants",
        "Shader constants beside the zoo: microfacet (n+2)/(8 pi), the (n+8)/(8 pi) approximation, 8-bit gloss",
        {"microfacet: closed form against the heightfield NDF quadrature (binary128) / 4",
         "approx: relative error (n+8)/(8 pi) / exact - 1, rewritten without cancellation, in " +
             std::string(number_type_name<wide>) + "; largest by log-spaced scan and golden section",
         "gloss: every 8-bit code in gloss-8bit",
         "n_input: the exponent as given, a decimal: the quadrature's estimate covers its rounding to binary128, "
         "the closed forms take it in 50 digits"},
        {"constant", "n_input", "value", "reference", "rel_error", "pass"}};
    info.id_keys = {"constant", "n"};
    return info;
}

// All 256 codes of the 8-bit gloss decoding, with the step to the next code.
inline std::vector<record> gloss_table() {
    std::vector<record> out;
    auto decode = [](int k) { return std::pow(2.0, 10.0 * k / 255 + 1); };
    for (int k = 0; k < 256; ++k) {
        const double n = decode(k), norm = (n + 2) / (8 * M_PI);
        record r{"gloss-8bit", {}};
        r.set("code", static_cast<std::int64_t>(k))
            .set("g", k / 255.0)
            .set("n", n)
            .set("norm_microfacet", norm)
            .set("n_step_rel", k < 255 ? decode(k + 1) / n - 1 : 0.0)
            .set("norm_step_rel", k < 255 ? (decode(k + 1) + 2) / (n + 2) - 1 : 0.0);
        out.push_back(r);
    }
    return out;
}

inline table_info gloss_info() {
    return {"gloss-8bit",
            "Gloss decoding n = 2^(10 g + 1) for every 8-bit code g = k/255",
            {"double precision; n_step_rel and norm_step_rel: relative change to the next code"},
            {"code", "g", "n", "norm_microfacet", "n_step_rel", "norm_step_rel"}};
}

}  // namespace verify
