// The registries: the zoo rows (docs/method.md) and the BRDF forms (brdf/brdf.hpp, docs/energy.md,
// docs/models.md). Tables, the CLI and the tests iterate over them; adding a row or a form is one
// header and one entry.
#pragma once
#include <array>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "brdf/ashikhmin_shirley.hpp"
#include "brdf/blinn_phong.hpp"
#include "brdf/disney.hpp"
#include "brdf/eon.hpp"
#include "brdf/lambert.hpp"
#include "brdf/microfacet.hpp"
#include "brdf/phong.hpp"
#include "brdf/ward.hpp"
#include "detail/by_id.hpp"
#include "microfacet/distribution.hpp"
#include "zoo/blinn_phong.hpp"
#include "zoo/lambert.hpp"
#include "zoo/phong.hpp"

namespace normzoo {

using zoo_rows = std::tuple<zoo::lambert, zoo::phong, zoo::phong_modified, zoo::blinn_phong,
                            zoo::blinn_phong_modified, zoo::blinn_phong_ndf,
                            zoo::blinn_phong_heightfield>;

// Calls f(Row{}) for every row, in registry order.
template <class F>
void for_each_zoo_row(F&& f) {
    detail::for_each_of<zoo_rows>(f);
}

// Calls f(Row{}) for the zoo row with this id; false if there is none.
template <class F>
bool with_zoo_row(std::string_view id, F&& f) {
    return detail::with_id<zoo_rows>(id, f);
}

inline constexpr std::size_t zoo_row_count = std::tuple_size_v<zoo_rows>;

inline std::array<std::string_view, zoo_row_count> zoo_row_ids() { return detail::id_array<zoo_rows>(); }

// The rows of the tables ndf and ndf-furnace (docs/models.md): the D parts whose non-projected
// integral has a closed form (Beckmann, GGX), in the parts' order.
template <class F>
void for_each_ndf(F&& f) {
    detail::for_each_of<microfacet::distribution_parts>([&](auto part) {
        if constexpr (decltype(part)::has_non_projected) f(part);
    });
}

// Calls f(D{}) for the ndf table's row with this id; false if there is none.
template <class F>
bool with_ndf(std::string_view id, F&& f) {
    return detail::first_with_id(id, [](auto&& visit) { for_each_ndf(visit); }, f);
}

// Every BRDF form, once: the seed's exponent forms, then the forms of docs/models.md indexed by
// roughness alpha, exponent n or Disney roughness r (each declares its parameters). One line a
// form: the list also names what the command compiles once (detail/compiled_kernels.hpp).
#define NORMZOO_BRDF_FORMS(X)                                                                         \
    X(brdf::lambert) X(brdf::phong) X(brdf::phong_modified) X(brdf::blinn_phong)                      \
    X(brdf::blinn_phong_modified) X(brdf::blinn_phong_modified_approx) X(brdf::microfacet_blinn)      \
    X(brdf::minimalist_cook_torrance) X(brdf::cook_torrance_ksk) X(brdf::ward) X(brdf::ward_aniso)    \
    X(brdf::ward_duer) X(brdf::ward_gmd) X(brdf::ward_gmd_aniso) X(brdf::ashikhmin_shirley)           \
    X(brdf::ashikhmin_shirley_aniso) X(brdf::ashikhmin_shirley_diffuse) X(brdf::disney_diffuse)       \
    X(brdf::disney_diffuse_renormalized) X(brdf::eon)
#define NORMZOO_DETAIL_TUPLE_OF(T) std::tuple<T>{},
using brdf_forms = decltype(std::tuple_cat(NORMZOO_BRDF_FORMS(NORMZOO_DETAIL_TUPLE_OF) std::tuple<>{}));
#undef NORMZOO_DETAIL_TUPLE_OF

template <class F>
void for_each_brdf(F&& f) {
    detail::for_each_of<brdf_forms>(f);
}

inline constexpr std::size_t brdf_count = std::tuple_size_v<brdf_forms>;

// Calls f(Form{}) for the form with this id; false if there is none.
template <class F>
bool with_brdf(std::string_view id, F&& f) {
    return detail::with_id<brdf_forms>(id, f);
}

inline std::array<std::string_view, brdf_count> brdf_ids() { return detail::id_array<brdf_forms>(); }

// The forms normalized by a zoo row (brdf::zoo_normalized: they have zoo_row, constant(n) and
// exact_constant(n)), in registry order: the tables about the zoo's constants and exponents
// (stability, shader normalization, punctual limit, error audit) take these.
template <class F>
void for_each_zoo_brdf(F&& f) {
    for_each_brdf([&](auto form) {
        if constexpr (brdf::zoo_normalized<decltype(form)>) f(form);
    });
}

inline std::vector<std::string_view> zoo_brdf_ids() {
    std::vector<std::string_view> ids;
    for_each_zoo_brdf([&](auto form) { ids.push_back(decltype(form)::id); });
    return ids;
}

// Calls f(Form{}) for the zoo-normalized form with this id; false if there is none.
template <class F>
bool with_zoo_brdf(std::string_view id, F&& f) {
    return detail::first_with_id(id, [](auto&& visit) { for_each_zoo_brdf(visit); }, f);
}

namespace detail {
// One idea of a model (docs/architecture.md, "One idea of a model"): whatever a registry lists
// has an id, its literature and its parameters declared as `parameter`s; and what a zoo row or a
// form declares agrees with what its code reads (has_exponent, has_specular).
template <class T>
constexpr bool declared_as_a_model() {
    using list = std::decay_t<decltype(T::parameters)>;
    return std::is_same_v<typename list::value_type, parameter> && !std::string_view(T::id).empty() &&
           !std::string_view(T::literature).empty();
}
template <class... T>
constexpr bool all_declared_as_models(std::tuple<T...>*) {
    return (declared_as_a_model<T>() && ...);
}
template <class... Row>
constexpr bool rows_declared_consistently(std::tuple<Row...>*) {
    return ((declares(Row::parameters, "n") == Row::has_exponent) && ...);
}
template <class... Form>
constexpr bool forms_declared_consistently(std::tuple<Form...>*) {
    return (((!declares(Form::parameters, "n") || Form::has_exponent) &&
             declares(Form::parameters, "specular") == Form::has_specular) && ...);
}
template <class Tuple>
constexpr Tuple* list = nullptr;
static_assert(all_declared_as_models(list<zoo_rows>) && all_declared_as_models(list<brdf_forms>) &&
                  all_declared_as_models(list<microfacet::distribution_parts>) &&
                  all_declared_as_models(list<microfacet::masking_parts>) &&
                  all_declared_as_models(list<microfacet::fresnel_parts>),
              "a model or part lacks its id, literature or declared parameters");
static_assert(rows_declared_consistently(list<zoo_rows>), "a zoo row's parameters disagree with has_exponent");
static_assert(forms_declared_consistently(list<brdf_forms>),
              "a form's declared parameters disagree with has_exponent or has_specular");
}  // namespace detail

}  // namespace normzoo

#ifdef NORMZOO_COMPILED_KERNELS
#include "detail/compiled_kernels.hpp"
#endif
