// A library material as `verify --brdf FILE --against MATERIAL` reads it (docs/materials.md, "A
// shader's conformance to a material"): its parameters by name, f(L, V) per channel and its albedo
// with V held, at values given one per parameter. The materials themselves are the library's
// (normzoo/material/); this is the command's view of one, so that the conformance check does not
// depend on how a material is built.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <normzoo/geometry.hpp>
#include <normzoo/quadrature/estimate.hpp>

namespace verify {

using rgb_value = std::array<double, 3>;

struct reference_parameter {
    std::string name;
    bool colour = false;  // three numbers; otherwise one (value[0])
    rgb_value default_value{};
    double min = 0, max = 1;
};

struct reference_material {
    std::string id;  // as given: NAME or NAME/COMPENSATION
    std::vector<reference_parameter> parameters;
    // values: one per parameter, in `parameters` order (a scalar's in [0])
    std::function<rgb_value(const normzoo::vec3<double>& l, const normzoo::vec3<double>& v, const std::vector<rgb_value>& values)> f;
    // The albedo with V = (sqrt(1 - mu^2), 0, mu) held, per channel, to `tolerance`.
    std::function<std::array<normzoo::quadrature::estimate<double>, 3>(double mu, const std::vector<rgb_value>& values,
                                                                       double tolerance)>
        albedo;
    // The index of the parameter `name`, or parameters.size().
    std::size_t index_of(const std::string& name) const {
        std::size_t k = 0;
        while (k < parameters.size() && parameters[k].name != name) ++k;
        return k;
    }
};

// The library's material named `id` (a compensation suffix allowed); bad_input naming `option`
// and the materials known when there is none.
reference_material reference_material_named(const std::string& id, const std::string& option);

}  // namespace verify
