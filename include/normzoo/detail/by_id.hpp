// The one lookup every registry shares (registry.hpp; the microfacet parts' lists): a registry is
// a std::tuple of small value types, each with a static `id`; these visit it by position or id.
#pragma once
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

// Calls f(T{}) for the first type T of the tuple whose id is `id`; false if there is none.
template <class Tuple, class F>
bool with_id(std::string_view id, F&& f) {
    bool found = false;
    for_each_of<Tuple>([&](auto t) {
        if (!found && id == decltype(t)::id) {
            found = true;
            f(t);
        }
    });
    return found;
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

// The ids, comma-separated, for messages.
template <class Tuple>
std::string ids_of() {
    std::string s;
    for_each_of<Tuple>([&](auto t) { s += (s.empty() ? "" : ", ") + std::string(decltype(t)::id); });
    return s;
}

}  // namespace normzoo::detail
