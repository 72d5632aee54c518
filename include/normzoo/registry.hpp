// The one list of zoo rows. Tables, the CLI and the tests iterate over it; adding a row is one
// header and one entry here.
#pragma once
#include <array>
#include <string_view>
#include <tuple>

#include "models/blinn_phong.hpp"
#include "models/lambert.hpp"
#include "models/phong.hpp"

namespace normzoo {

using zoo_rows = std::tuple<models::lambert, models::phong, models::phong_modified, models::blinn_phong,
                            models::blinn_phong_modified, models::blinn_phong_ndf,
                            models::blinn_phong_heightfield>;

// Calls f(Row{}) for every row, in registry order.
template <class F>
void for_each_zoo_row(F&& f) {
    std::apply([&](auto... row) { (f(row), ...); }, zoo_rows{});
}

inline constexpr std::size_t zoo_row_count = std::tuple_size_v<zoo_rows>;

inline std::array<std::string_view, zoo_row_count> zoo_row_ids() {
    std::array<std::string_view, zoo_row_count> ids{};
    std::size_t i = 0;
    for_each_zoo_row([&](auto row) { ids[i++] = decltype(row)::id; });
    return ids;
}

}  // namespace normzoo
