// The formulas a shader evaluates beside its lobes, each written once, as HLSL / GLSL writes it
// (operation order, pow and exp2, constants rounded to the working type), over a generic number
// type: `half`, `float`, or binary128 for the reference. Adding one is one entry in formulas().
//
// The second argument is the cosine of a lobe (N.H) for the two-input lobes; the others ignore it.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "math.hpp"

namespace normzoo::shader {

// What a formula's first input is, and so which grid it is swept over.
enum class domain {
    none,       // a constant: evaluated once
    exponent,   // n >= 0 (and the lobes: n with N.H at 2^-u of the peak, u in lobe_depths())
    unit,       // x = L.H in [0, 1]
    gloss_code  // k = 0..255, g = k / 255
};

enum class lobe_grid {
    none,
    power,    // N.H = 2^(-u / max(n, 1)): where (N.H)^n = 2^-u
    gaussian  // N.H = 1 - u ln 2 / (n + 1): where exp((n+1)(N.H - 1)) = 2^-u
};

struct formula {
    std::string id;
    std::string expression;  // as the shader writes it
    std::string variable;    // what the first input is
    domain dom;
    lobe_grid lobe;
    std::function<half(half, half)> f16;
    std::function<float(float, float)> f32;
    std::function<quad(const quad&, const quad&)> exact;
};

// One entry: the same generic lambda instantiated for every number type.
template <class F>
formula make_formula(std::string id, std::string expression, std::string variable, domain d, lobe_grid l, F f) {
    return {std::move(id), std::move(expression), std::move(variable), d, l,
            [f](half x, half c) { return f(x, c); },
            [f](float x, float c) { return f(x, c); },
            [f](const quad& x, const quad& c) { return f(x, c); }};
}

inline const std::vector<formula>& formulas() {
    using D = domain;
    using L = lobe_grid;
    static const std::vector<formula> list = {
        // The zoo normalizations (rows sharing a constant share an entry) and the shader constants.
        make_formula("lambert", "1 / PI", "none", D::none, L::none, [](auto x, auto) { return 1 / pi(x); }),
        make_formula("phong, blinn-phong-ndf", "(n + 1) / (2 * PI)", "n", D::exponent, L::none,
                     [](auto n, auto) { return (n + 1) / (2 * pi(n)); }),
        make_formula("phong-modified, blinn-phong-heightfield", "(n + 2) / (2 * PI)", "n", D::exponent, L::none,
                     [](auto n, auto) { return (n + 2) / (2 * pi(n)); }),
        make_formula("blinn-phong", "(n + 2) / (4 * PI * (2 - exp2(-n / 2)))", "n", D::exponent, L::none,
                     [](auto n, auto) { return (n + 2) / (4 * pi(n) * (2 - exp2(-n / 2))); }),
        make_formula("blinn-phong-modified", "(n + 2) * (n + 4) / (8 * PI * (exp2(-n / 2) + n))", "n", D::exponent,
                     L::none, [](auto n, auto) { return (n + 2) * (n + 4) / (8 * pi(n) * (exp2(-n / 2) + n)); }),
        // The same, reordered so that no intermediate exceeds the result by a factor n.
        make_formula("blinn-phong-modified, reordered", "(n + 2) / (8 * PI) * ((n + 4) / (exp2(-n / 2) + n))", "n",
                     D::exponent, L::none, [](auto n, auto) { return (n + 2) / (8 * pi(n)) * ((n + 4) / (exp2(-n / 2) + n)); }),
        make_formula("microfacet-blinn (n+2)/(8 pi)", "(n + 2) / (8 * PI)", "n", D::exponent, L::none,
                     [](auto n, auto) { return (n + 2) / (8 * pi(n)); }),
        make_formula("approx (n+8)/(8 pi)", "(n + 8) / (8 * PI)", "n", D::exponent, L::none,
                     [](auto n, auto) { return (n + 8) / (8 * pi(n)); }),
        // Gloss decoding of an 8-bit code, and the microfacet constant straight from it.
        make_formula("gloss", "exp2(10 * (k / 255) + 1)", "k (8-bit gloss code)", D::gloss_code, L::none,
                     [](auto k, auto) { return exp2(10 * (k / 255) + 1); }),
        make_formula("gloss to (n+2)/(8 pi)", "(exp2(10 * (k / 255) + 1) + 2) / (8 * PI)", "k (8-bit gloss code)",
                     D::gloss_code, L::none, [](auto k, auto) { return (exp2(10 * (k / 255) + 1) + 2) / (8 * pi(k)); }),
        // Schlick's Fresnel (F0 = 0.04, a dielectric), its weight two ways, and the exp2 form.
        make_formula("schlick weight, pow", "pow(1 - x, 5)", "x = L.H", D::unit, L::none,
                     [](auto x, auto) { return pow(1 - x, decltype(x)(5)); }),
        make_formula("schlick weight, multiplied", "m = 1 - x; m2 = m * m; m2 * m2 * m", "x = L.H", D::unit, L::none,
                     [](auto x, auto) { const auto m = 1 - x; const auto m2 = m * m; return m2 * m2 * m; }),
        make_formula("schlick", "F0 + (1 - F0) * pow(1 - x, 5), F0 = 0.04", "x = L.H", D::unit, L::none,
                     [](auto x, auto) { const auto f0 = lit(x, "0.04"); return f0 + (1 - f0) * pow(1 - x, decltype(x)(5)); }),
        make_formula("schlick exp2", "F0 + (1 - F0) * exp2(-8.656170 * x), F0 = 0.04", "x = L.H", D::unit, L::none,
                     [](auto x, auto) { const auto f0 = lit(x, "0.04"); return f0 + (1 - f0) * exp2(-lit(x, "8.656170") * x); }),
        // The Blinn-Phong lobe and its spherical-Gaussian form, m = (n + 1) / ln 2.
        make_formula("lobe pow", "pow(c, n), c = N.H", "n", D::exponent, L::power,
                     [](auto n, auto c) { return pow(c, n); }),
        make_formula("spherical gaussian", "exp2(m * c - m), m = (n + 1) * 1.442695", "n", D::exponent, L::gaussian,
                     [](auto n, auto c) { const auto m = (n + 1) * lit(n, "1.442695"); return exp2(m * c - m); }),
        make_formula("spherical gaussian, factored", "exp2(m * (c - 1)), m = (n + 1) * 1.442695", "n", D::exponent,
                     L::gaussian, [](auto n, auto c) { const auto m = (n + 1) * lit(n, "1.442695"); return exp2(m * (c - 1)); }),
    };
    return list;
}

}  // namespace normzoo::shader
