// The shader-precision audit: every formula of shader/formulas.hpp evaluated as a shader does, in
// fp16 (every operation rounded to binary16) and fp32, against the exact value of the same
// expression at the same inputs (binary128). Per formula and precision: the largest relative error
// over its working range and where, and the first input where it breaks (overflow, underflow, NaN,
// or a relative error of 1 or more).
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <normzoo/detail/parallel.hpp>
#include <normzoo/real.hpp>
#include <normzoo/shader/formulas.hpp>

#include "../record.hpp"
#include "grid_text.hpp"

namespace verify {

enum class shader_precision_kind { fp16, fp32 };

inline const char* precision_name(shader_precision_kind p) { return p == shader_precision_kind::fp16 ? "fp16" : "fp32"; }

// Unit roundoff of the working type: 2^-11 (half), 2^-24 (float).
inline double unit_roundoff(shader_precision_kind p) { return p == shader_precision_kind::fp16 ? 0x1p-11 : 0x1p-24; }

// n = 0 and 100 log-spaced exponents per decade from 1e-3 to 1e9.
inline std::vector<double> shader_precision_exponents() {
    std::vector<double> n{0};
    for (int i = 0; i <= 1200; ++i) n.push_back(std::pow(10.0, -3 + i / 100.0));
    return n;
}

// x = L.H: k / 4096 for k = 0..4096, and 1 - 2^-j (j = 13..40) towards normal incidence.
inline std::vector<double> shader_precision_unit_grid() {
    std::vector<double> x;
    for (int k = 0; k <= 4096; ++k) x.push_back(k / 4096.0);
    for (int j = 13; j <= 40; ++j) x.push_back(1 - std::ldexp(1.0, -j));
    std::sort(x.begin(), x.end());
    return x;
}

// Depths into a lobe where its N.H is taken: the lobe's exact value there is 2^-u (u = 0 is the peak).
inline std::vector<double> lobe_depths() { return {0, 1.0 / 64, 1.0 / 16, 0.25, 0.5, 1, 2, 4, 8, 12}; }

inline std::vector<double> shader_precision_grid(shader::domain d) {
    switch (d) {
        case shader::domain::none: return {0};
        case shader::domain::exponent: return shader_precision_exponents();
        case shader::domain::unit: return shader_precision_unit_grid();
        case shader::domain::gloss_code: {
            std::vector<double> k;
            for (int i = 0; i < 256; ++i) k.push_back(i);
            return k;
        }
    }
    return {};
}

// "n = 0, 1e-3 to 1e9; L.H in [0, 1]; gloss codes 0 to 255": the grids in the table's head.
inline std::string shader_precision_grid_text() {
    const auto n = shader_precision_grid(shader::domain::exponent);
    const auto x = shader_precision_grid(shader::domain::unit);
    const auto k = shader_precision_grid(shader::domain::gloss_code);
    return "n = " + value_text(n.front()) + ", " + range_text(n[1], n.back()) + "; L.H in [" + value_text(x.front()) +
           ", " + value_text(x.back()) + "]; gloss codes " + range_text(k);
}

// The second inputs (N.H) at first input n, or {0} for a one-input formula.
inline std::vector<double> lobe_cosines(shader::lobe_grid l, double n) {
    std::vector<double> c;
    for (double u : lobe_depths()) {
        if (l == shader::lobe_grid::power) c.push_back(std::exp2(-u / std::max(n, 1.0)));
        // (N.H < 0 is outside the lobe: the broad Gaussians at small n stop at N.H = 0)
        if (l == shader::lobe_grid::gaussian && 1 - u * std::log(2.0) / (n + 1) >= 0)
            c.push_back(1 - u * std::log(2.0) / (n + 1));
    }
    return l == shader::lobe_grid::none ? std::vector<double>{0} : c;
}

// How one evaluation went.
struct shader_point {
    double rel_error = 0;   // |fp / exact - 1| (0 when both are 0)
    double c = 0;           // the second input it was found at
    const char* breaks = nullptr;  // null, or what broke
};

// One input x (and every lobe cosine at x): the worst relative error, and whether it breaks.
// Breaking, in this order: "input overflow" (x itself is inf in the type), "nan", "overflow" (the
// result is inf), "underflow" (the result is 0 where the exact value is not, or subnormal where
// the exact value is normal in the type), "accuracy" (relative error >= 1).
template <class T>
shader_point evaluate_shader_point(const shader::formula& f, const std::function<T(T, T)>& fp, double x, T min_normal) {
    using std::abs;
    shader_point worst;
    for (double c : lobe_cosines(f.lobe, x)) {
        const T xt = T(x), ct = T(c);
        const double xr = static_cast<double>(xt), cr = static_cast<double>(ct);  // the inputs as the shader holds them
        shader_point p;
        p.c = c;
        if (std::isinf(xr)) {
            p.breaks = "input overflow";
            p.rel_error = INFINITY;
        } else {
            const double v = static_cast<double>(fp(xt, ct));
            const quad exact = f.exact(quad(xr), quad(cr));
            const double lo = static_cast<double>(min_normal);
            p.rel_error = exact == 0 ? (v == 0 ? 0.0 : double(INFINITY)) : static_cast<double>(abs(quad(v) / exact - 1));
            if (std::isnan(v)) p.breaks = "nan";
            else if (std::isinf(v)) p.breaks = "overflow";
            else if (exact != 0 && (v == 0 || (std::abs(v) < lo && abs(exact) >= lo))) p.breaks = "underflow";
            else if (p.rel_error >= 1) p.breaks = "accuracy";
            if (std::isnan(p.rel_error)) p.rel_error = INFINITY;
        }
        if (!worst.breaks && (p.breaks || p.rel_error > worst.rel_error)) worst = p;
    }
    return worst;
}

struct shader_audit {
    double max_rel_error = 0, at = 0, at_c = 0;
    double max_rel_error_to_2048 = 0;  // over inputs <= 2048 (the exponents of 8-bit gloss), below the break
    std::optional<double> breaks_at;
    std::string breaks_because;
    std::vector<std::pair<double, double>> curve;  // (x, relative error) at every grid point below the break
};

template <class T>
shader_audit audit_shader_formula(const shader::formula& f, const std::function<T(T, T)>& fp, T min_normal) {
    const auto grid = shader_precision_grid(f.dom);
    shader_audit a;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const auto p = evaluate_shader_point(f, fp, grid[i], min_normal);
        if (p.breaks) {
            // Bisect between the last grid point that works and this one, down to adjacent doubles:
            // the exact input where it starts to break, when breaking is monotone there.
            double lo = i > 0 ? grid[i - 1] : grid[i], hi = grid[i];
            const char* why = p.breaks;
            while (i > 0 && std::nextafter(lo, hi) < hi) {
                const double mid = lo + (hi - lo) / 2;
                if (mid <= lo || mid >= hi) break;
                const auto q = evaluate_shader_point(f, fp, mid, min_normal);
                if (q.breaks) hi = mid, why = q.breaks;
                else lo = mid;
            }
            a.breaks_at = hi;
            a.breaks_because = why;
            break;
        }
        a.curve.emplace_back(grid[i], p.rel_error);
        if (p.rel_error > a.max_rel_error || i == 0) a.max_rel_error = p.rel_error, a.at = grid[i], a.at_c = p.c;
        if (grid[i] <= 2048) a.max_rel_error_to_2048 = std::max(a.max_rel_error_to_2048, p.rel_error);
    }
    return a;
}

inline shader_audit audit_shader_formula(const shader::formula& f, shader_precision_kind p) {
    if (p == shader_precision_kind::fp16) return audit_shader_formula<shader::half>(f, f.f16, shader::half::min_normal());
    return audit_shader_formula<float>(f, f.f32, std::numeric_limits<float>::min());
}

// One formula audited in one precision: the table's row and the figure's curve are both drawn
// from it, so the audit runs once.
struct shader_precision_audit {
    const shader::formula* formula;
    shader_precision_kind precision;
    shader_audit audit;
};

// Every formula in fp16, then fp32, formulas in the order of shader::formulas().
inline std::vector<shader_precision_audit> shader_precision_audits(unsigned jobs) {
    const auto& fs = shader::formulas();
    const shader_precision_kind kinds[] = {shader_precision_kind::fp16, shader_precision_kind::fp32};
    std::vector<shader_precision_audit> out(2 * fs.size());
    detail::parallel_for(out.size(), jobs, [&](std::size_t i) {
        out[i] = {&fs[i / 2], kinds[i % 2], audit_shader_formula(fs[i / 2], kinds[i % 2])};
    });
    return out;
}

inline std::vector<record> shader_precision_table(const std::vector<shader_precision_audit>& audits) {
    std::vector<record> out;
    for (const auto& [formula, p, a] : audits) {
        const auto& f = *formula;
        const bool lobe = f.lobe != shader::lobe_grid::none;
        record r{"shader-precision", {}};
        r.set("formula", f.id)
            .set("precision", std::string(precision_name(p)))
            .set("expression", f.expression)
            .set("variable", f.variable)
            .set("max_rel_error", a.max_rel_error)
            .set("in_roundoffs", a.max_rel_error / unit_roundoff(p))
            .set("max_rel_error_n_to_2048",
                 f.dom == shader::domain::exponent && (!a.breaks_at || *a.breaks_at > 2048)
                     ? field_value(a.max_rel_error_to_2048)
                     : field_value(nullptr))
            .set("at_n", a.at)
            .set("at_c", lobe ? field_value(a.at_c) : field_value(nullptr))
            .set("breaks_at_n", a.breaks_at ? field_value(*a.breaks_at) : field_value(nullptr))
            .set("breaks_because", a.breaks_at ? field_value(a.breaks_because) : field_value(nullptr));
        out.push_back(std::move(r));
    }
    return out;
}

inline std::vector<record> shader_precision_table(unsigned jobs) {
    return shader_precision_table(shader_precision_audits(jobs));
}

inline table_info shader_precision_info() {
    return {"shader-precision",
            "Shader formulas in fp16 and fp32 against their exact value: largest relative error, and where each breaks",
            {"fp16: binary16 with every operation rounded to half (GCC _Float16, each operation computed in float and "
             "rounded explicitly, which is exact); fp32: binary32; exp2 and log2 correctly rounded in both (a GPU's "
             "approximate ones add up to their own ulps); pow(x, y) lowered as exp2(y * log2(x)); constants rounded "
             "to the type (PI, 0.04, 8.656170, 1.442695)",
             "reference: the same expression in binary128 at the inputs as the shader holds them (each input rounded "
             "to the type first), so the error is the formula's, not the input's storage",
             "grids: n = 0 and 100 log-spaced per decade from 1e-3 to 1e9; x = L.H = k/4096 and 1 - 2^-j (j = 13..40); "
             "gloss codes k = 0..255; lobes at every n with c = N.H where the exact lobe is 2^-u, u = 0, 1/64, 1/16, "
             "1/4, 1/2, 1, 2, 4, 8, 12 (pow: c = 2^(-u/max(n,1)); spherical gaussian: c = 1 - u ln2/(n+1) where >= 0)",
             "max_rel_error: largest |fp / exact - 1| over the grid points below breaks_at_n, at at_n (and at_c, the "
             "N.H, for lobes); in_roundoffs: the same over the unit roundoff (2^-11 fp16, 2^-24 fp32); at_n is the "
             "value of the formula's variable; max_rel_error_n_to_2048: the same over n <= 2048 (the exponents of "
             "8-bit gloss), for the formulas of n that work up to there",
             "breaks_at_n: the smallest grid input where the formula breaks, refined by bisection to adjacent doubles "
             "against the grid point below it; null if never on the grid. breaks_because: input overflow (the input "
             "is inf in the type), nan, overflow (inf), underflow (0 where the exact value is not, or subnormal where "
             "the exact value is normal in the type), accuracy (relative error >= 1)"},
            {"formula", "precision", "expression", "max_rel_error", "in_roundoffs", "at_n", "at_c",
             "max_rel_error_n_to_2048", "breaks_at_n", "breaks_because"},
            {"breaks_at_n"}};
}

}  // namespace verify
