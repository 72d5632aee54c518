// Whether the tests run under the sanitizers (tests/run with NORMZOO_SANITIZE, which defines
// NORMZOO_TEST_SANITIZED), and a case table thinned there. The sanitizers look for memory errors
// and undefined behaviour, which a code path shows at one point as at many; the plain build runs
// every case. Used for the slowest numeric tables only (docs/architecture.md, "Tests under the
// sanitizers").
#pragma once
#include <catch2/catch.hpp>

#include <cstddef>
#include <memory>

namespace normzoo_test {

#ifdef NORMZOO_TEST_SANITIZED
inline constexpr bool sanitized = true;
#else
inline constexpr bool sanitized = false;
#endif

// The cases of `cases` in the plain build; under the sanitizers every `stride`-th, the first one
// included.
template <class T>
Catch::Generators::GeneratorWrapper<T> thinned_under_sanitizers(std::size_t stride, Catch::Generators::GeneratorWrapper<T>&& cases) {
    auto seen = std::make_shared<std::size_t>(0);
    return Catch::Generators::filter([seen, stride](const T&) { return !sanitized || (*seen)++ % stride == 0; }, std::move(cases));
}

}  // namespace normzoo_test
