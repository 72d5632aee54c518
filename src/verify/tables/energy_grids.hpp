// The grids the BRDF forms declare for the energy sweep (brdf/brdf.hpp), in words: form by form
// for the energy tables' settings, and grid by grid for their heads. Both read the registry, so
// a form added or a grid changed changes them.
#pragma once
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include <normzoo/registry.hpp>

#include "../record.hpp"
#include "grid_text.hpp"

namespace verify {

// Each form's declared grid, as the tables' settings state it.
inline std::string energy_grids_text() {
    std::string text;
    for_each_brdf([&](auto form) {
        using Form = decltype(form);
        text += (text.empty() ? "" : "; ") + std::string(Form::id) + ": ";
        if constexpr (brdf::has_swept_parameter<Form>()) {
            const brdf::parameter& p = brdf::swept_parameter<Form>();
            text += std::string(p.name) + " =";
            for (std::size_t i = 0; i < p.sweep.size; ++i)
                text += (i ? ", " : " ") + detail::format_number(p.sweep.values[i]);
        } else {
            text += "once";
        }
    });
    return text;
}

namespace detail {
// "ashikhmin-shirley" -> "Ashikhmin-Shirley": a form's id as the head names its family.
inline std::string family_name(std::string_view id) {
    std::string name(id);
    for (std::size_t i = 0; i < name.size(); ++i)
        if (i == 0 || name[i - 1] == '-') name[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[i])));
    return name;
}
}  // namespace detail

// Each distinct grid the forms sweep, by parameter name in the order the registry first names
// it: "n = 1, 2, 4, ..., 2048, 1e4, 1e5; Ashikhmin-Shirley n = 1, 10, 100, 1000; alpha = ...".
// A name's first grid is its own; each further grid of that name is named after the first form
// that sweeps it.
inline std::string declared_grids_text() {
    struct grid {
        std::string_view name;
        std::vector<double> values;
        std::string_view first_form;
    };
    std::vector<grid> grids;
    std::vector<std::string_view> names;
    for_each_brdf([&](auto form) {
        using Form = decltype(form);
        if constexpr (brdf::has_swept_parameter<Form>()) {
            const brdf::parameter& p = brdf::swept_parameter<Form>();
            const std::vector<double> values(p.sweep.begin(), p.sweep.end());
            for (const auto& g : grids)
                if (g.name == p.name && g.values == values) return;
            grids.push_back({p.name, values, Form::id});
            bool named = false;
            for (auto n : names) named = named || n == p.name;
            if (!named) names.push_back(p.name);
        }
    });
    std::string text;
    for (auto name : names) {
        bool first = true;
        for (const auto& g : grids) {
            if (g.name != name) continue;
            text += (text.empty() ? "" : "; ") + (first ? std::string() : detail::family_name(g.first_form) + " ") +
                    std::string(name) + " = " + list_text(g.values);
            first = false;
        }
    }
    return text;
}

}  // namespace verify
