// The one lookup every registry shares (registry.hpp; the microfacet parts' lists): a registry is
// a std::tuple of small value types, each with a static `id`; these visit it by position or id.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>

namespace normzoo::detail {

// Calls f(T{}) for every type T of the tuple, in order.
template <class Tuple, class F>
void for_each_of(F&& f) {
    std::apply([&](auto... t) { (f(t), ...); }, Tuple{});
}

// Calls f(t) for the first t whose id is `id` among those each(visitor) visits (a registry or a
// part of it, such as the forms a zoo row normalizes); false if there is none.
template <class Each, class F>
bool first_with_id(std::string_view id, Each&& each, F&& f) {
    bool found = false;
    each([&](auto t) {
        if (!found && id == decltype(t)::id) {
            found = true;
            f(t);
        }
    });
    return found;
}

// Calls f(T{}) for the first type T of the tuple whose id is `id`; false if there is none.
template <class Tuple, class F>
bool with_id(std::string_view id, F&& f) {
    return first_with_id(id, [](auto&& visit) { for_each_of<Tuple>(visit); }, f);
}

// f(T{}) for the type at `index`, its result as R (R{} past the end).
template <class Tuple, class R, class F>
R visit_index(std::size_t index, const F& f) {
    R out{};
    std::size_t i = 0;
    for_each_of<Tuple>([&](auto t) {
        if (i++ == index) out = f(t);
    });
    return out;
}

// The index of the type whose id is `id`, or the tuple's size.
template <class Tuple>
std::size_t index_of(std::string_view id) {
    std::size_t i = 0, found = std::tuple_size_v<Tuple>;
    for_each_of<Tuple>([&](auto t) {
        if (found == std::tuple_size_v<Tuple> && id == decltype(t)::id) found = i;
        ++i;
    });
    return found;
}

// The ids, in order.
template <class Tuple>
std::array<std::string_view, std::tuple_size_v<Tuple>> id_array() {
    std::array<std::string_view, std::tuple_size_v<Tuple>> ids{};
    std::size_t i = 0;
    for_each_of<Tuple>([&](auto t) { ids[i++] = decltype(t)::id; });
    return ids;
}

// The ids, comma-separated, for messages.
template <class Tuple>
std::string ids_of() {
    std::string s;
    for_each_of<Tuple>([&](auto t) { s += (s.empty() ? "" : ", ") + std::string(decltype(t)::id); });
    return s;
}

}  // namespace normzoo::detail
