// A shader's own normalization, checked (docs/tables.md): the expression
// it uses in place of a form's constant, against the exact factor over an exponent range (the
// largest relative error and where), and the largest directional albedo it gives (the form's
// albedo scales with the constant). This is what an engine's tests call (examples/).
#pragma once
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <normzoo/albedo.hpp>
#include <normzoo/real.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"
#include "energy.hpp"
#include "grid.hpp"

namespace verify {

// By id at run time; false when the id is not a BRDF form.
inline bool check_shader_normalization(const std::string& model, const std::function<double(double)>& expression,
                                       double n_lo, double n_hi, double specular, const std::vector<double>& angles,
                                       const albedo_settings& s, shader_normalization_verdict& out) {
    return with_zoo_brdf(model, [&](auto form) {
        out = normzoo::check_shader_normalization<decltype(form)>(expression, n_lo, n_hi, specular, angles, s);
    });
}

inline table_info shader_normalization_info() {
    table_info info{
        "shader-normalization",
        "Shader normalization expressions against the exact factor, and the albedo they give",
        {"max_rel_error: expression / exact constant - 1 of largest magnitude over the material's exponent range "
         "(400 log-spaced exponents and the ends, refined by Brent's method), at at_n",
         "max_albedo: the form's directional albedo times expression / the form's constant, over the energy "
         "exponents in the range, both ends and at_n, at every angle swept",
         "pass: |max_rel_error| within the scene's tolerance.normalization and max_albedo - its bound <= 1"},
        {"material", "model", "expression", "max_rel_error", "at_n", "max_albedo", "at_theta_deg", "conserving",
         "pass"},
        {"max_albedo"}};
    info.id_keys = {"material", "model"};
    info.check = {{{"max_albedo", "max_albedo_error", false}}, {"max_albedo_error", "verdict"}};
    return info;
}

}  // namespace verify
