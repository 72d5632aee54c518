// The registries: the zoo rows (SPEC section 2) and the BRDF forms (SPEC section 3). Tables,
// the CLI and the tests iterate over them; adding a row or a form is one header and one entry.
#pragma once
#include <array>
#include <string_view>
#include <tuple>

#include "brdf/ashikhmin_shirley.hpp"
#include "brdf/blinn_phong.hpp"
#include "brdf/disney.hpp"
#include "brdf/lambert.hpp"
#include "brdf/microfacet.hpp"
#include "brdf/phong.hpp"
#include "brdf/ward.hpp"
#include "models/beckmann.hpp"
#include "models/blinn_phong.hpp"
#include "models/ggx.hpp"
#include "models/lambert.hpp"
#include "models/phong.hpp"

namespace normzoo {

namespace detail {
// Calls f(T{}) for the first type T of the tuple whose id is `id`; false if there is none.
template <class Tuple, class F>
bool with_id(std::string_view id, F&& f) {
    bool found = false;
    auto visit = [&](auto t) {
        if (!found && id == decltype(t)::id) {
            found = true;
            f(t);
        }
    };
    std::apply([&](auto... t) { (visit(t), ...); }, Tuple{});
    return found;
}
}  // namespace detail

using zoo_rows = std::tuple<models::lambert, models::phong, models::phong_modified, models::blinn_phong,
                            models::blinn_phong_modified, models::blinn_phong_ndf,
                            models::blinn_phong_heightfield>;

// Calls f(Row{}) for every row, in registry order.
template <class F>
void for_each_zoo_row(F&& f) {
    std::apply([&](auto... row) { (f(row), ...); }, zoo_rows{});
}

// Calls f(Row{}) for the zoo row with this id; false if there is none.
template <class F>
bool with_zoo_row(std::string_view id, F&& f) {
    return detail::with_id<zoo_rows>(id, f);
}

inline constexpr std::size_t zoo_row_count = std::tuple_size_v<zoo_rows>;

inline std::array<std::string_view, zoo_row_count> zoo_row_ids() {
    std::array<std::string_view, zoo_row_count> ids{};
    std::size_t i = 0;
    for_each_zoo_row([&](auto row) { ids[i++] = decltype(row)::id; });
    return ids;
}

// The microfacet NDFs indexed by roughness alpha (issue 8): tables ndf, ndf-furnace.
using ndf_rows = std::tuple<models::beckmann, models::ggx>;

template <class F>
void for_each_ndf(F&& f) {
    std::apply([&](auto... row) { (f(row), ...); }, ndf_rows{});
}

// Calls f(Ndf{}) for the NDF with this id; false if there is none.
template <class F>
bool with_ndf(std::string_view id, F&& f) {
    return detail::with_id<ndf_rows>(id, f);
}

using brdf_forms = std::tuple<brdf::lambert, brdf::phong, brdf::phong_modified, brdf::blinn_phong,
                              brdf::blinn_phong_modified, brdf::blinn_phong_modified_approx, brdf::microfacet_blinn,
                              brdf::minimalist_cook_torrance, brdf::cook_torrance_ksk>;

template <class F>
void for_each_brdf(F&& f) {
    std::apply([&](auto... form) { (f(form), ...); }, brdf_forms{});
}

inline constexpr std::size_t brdf_count = std::tuple_size_v<brdf_forms>;

// Calls f(Form{}) for the form with this id; false if there is none.
template <class F>
bool with_brdf(std::string_view id, F&& f) {
    return detail::with_id<brdf_forms>(id, f);
}

inline std::array<std::string_view, brdf_count> brdf_ids() {
    std::array<std::string_view, brdf_count> ids{};
    std::size_t i = 0;
    for_each_brdf([&](auto form) { ids[i++] = decltype(form)::id; });
    return ids;
}

// The modern BRDF forms (issue 8), indexed by roughness alpha, exponent n or Disney roughness r
// (each form's `parameter`): tables models-energy and models-energy-summary.
using modern_brdf_forms =
    std::tuple<brdf::ward, brdf::ward_aniso, brdf::ward_duer, brdf::ward_gmd, brdf::ward_gmd_aniso,
               brdf::ashikhmin_shirley, brdf::ashikhmin_shirley_aniso, brdf::ashikhmin_shirley_diffuse,
               brdf::disney_diffuse, brdf::disney_diffuse_renormalized>;

template <class F>
void for_each_modern_brdf(F&& f) {
    std::apply([&](auto... form) { (f(form), ...); }, modern_brdf_forms{});
}

// Calls f(Form{}) for the modern form with this id; false if there is none.
template <class F>
bool with_modern_brdf(std::string_view id, F&& f) {
    return detail::with_id<modern_brdf_forms>(id, f);
}

}  // namespace normzoo
