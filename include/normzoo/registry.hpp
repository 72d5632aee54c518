// The registries: the zoo rows (docs/method.md) and the BRDF forms (brdf/brdf.hpp, docs/energy.md,
// docs/models.md). Tables, the CLI and the tests iterate over them; adding a row or a form is one
// header and one entry.
#pragma once
#include <array>
#include <string_view>
#include <tuple>
#include <vector>

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

// The microfacet NDFs indexed by roughness alpha (docs/models.md): tables ndf, ndf-furnace.
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

// Every BRDF form, once: the seed's exponent forms, then the forms of docs/models.md indexed by
// roughness alpha, exponent n or Disney roughness r (each declares its parameters). One line a
// form: the list also names what the command compiles once (detail/compiled_kernels.hpp).
#define NORMZOO_BRDF_FORMS(X)                                                                         \
    X(brdf::lambert) X(brdf::phong) X(brdf::phong_modified) X(brdf::blinn_phong)                      \
    X(brdf::blinn_phong_modified) X(brdf::blinn_phong_modified_approx) X(brdf::microfacet_blinn)      \
    X(brdf::minimalist_cook_torrance) X(brdf::cook_torrance_ksk) X(brdf::ward) X(brdf::ward_aniso)    \
    X(brdf::ward_duer) X(brdf::ward_gmd) X(brdf::ward_gmd_aniso) X(brdf::ashikhmin_shirley)           \
    X(brdf::ashikhmin_shirley_aniso) X(brdf::ashikhmin_shirley_diffuse) X(brdf::disney_diffuse)       \
    X(brdf::disney_diffuse_renormalized)
#define NORMZOO_DETAIL_TUPLE_OF(T) std::tuple<T>{},
using brdf_forms = decltype(std::tuple_cat(NORMZOO_BRDF_FORMS(NORMZOO_DETAIL_TUPLE_OF) std::tuple<>{}));
#undef NORMZOO_DETAIL_TUPLE_OF

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
    bool found = false;
    for_each_zoo_brdf([&](auto form) {
        if (!found && id == decltype(form)::id) found = true, f(form);
    });
    return found;
}

namespace detail {
// What the forms declare agrees with what their code reads.
template <class... Form>
constexpr bool forms_declared_consistently(std::tuple<Form...>*) {
    auto one = [](auto form) {
        using F = decltype(form);
        bool has_n = false, has_specular = false;
        for (const brdf::parameter& p : F::parameters) {
            has_n = has_n || p.name == "n";
            has_specular = has_specular || p.name == "specular";
        }
        return (!has_n || F::has_exponent) && has_specular == F::has_specular;
    };
    return (one(Form{}) && ...);
}
static_assert(forms_declared_consistently(static_cast<brdf_forms*>(nullptr)),
              "a form's declared parameters disagree with has_exponent or has_specular");
}  // namespace detail

}  // namespace normzoo

#ifdef NORMZOO_COMPILED_KERNELS
#include "detail/compiled_kernels.hpp"
#endif
