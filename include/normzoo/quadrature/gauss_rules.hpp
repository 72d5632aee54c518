// The Gauss-Legendre and Gauss-Kronrod rules normzoo's integrators take: gauss_rule<Real, N> and
// kronrod_rule<Real, N>, each the rule's non-negative nodes ascending (abscissa()) and their
// weights (weights()), the shape of Boost.Math's gauss and gauss_kronrod.
//
// In double, long double and binary128 at the orders normzoo uses, they are Boost.Math's own
// nodes and weights, bit for bit, copied into gauss_tables.hpp (tools/update-gauss-tables;
// test_lobe_quadrature compares every bit with Boost). Why a copy: Boost's headers also compute
// other types' and orders' nodes at run time, and so parse its Legendre and gamma functions: about
// 80 MB, a quarter of what an engine's test pays to include normzoo (bench/header_cost). Another
// type or order is an incomplete type, a compile error, never a wrong node: add it to
// tools/gauss-tables.cpp's list and run tools/update-gauss-tables.
#pragma once
#include <array>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>

#include "gauss_tables.hpp"

namespace normzoo::quadrature {

namespace detail {

// The type gauss_tables.hpp holds a Real's values in, by its precision (void: none).
template <class Real>
using table_storage = std::conditional_t<
    std::numeric_limits<Real>::digits == 53, double,
    std::conditional_t<std::numeric_limits<Real>::digits == 64, long double,
                       std::conditional_t<std::numeric_limits<Real>::digits == 113, __float128, void>>>;

template <class Table, class = void>
struct has_table : std::false_type {};
template <class Table>
struct has_table<Table, std::void_t<decltype(sizeof(Table))>> : std::true_type {};

template <template <class, unsigned> class Table, class Real, unsigned N>
constexpr bool tabulated = !std::is_void_v<table_storage<Real>> && has_table<Table<table_storage<Real>, N>>::value;

// A table's nodes and weights in Real (exact: the table holds Real's own precision).
template <class Real, class Table>
struct tabulated_rule {
    static constexpr std::size_t size = sizeof(Table::x) / sizeof(Table::x[0]);
    static const std::array<Real, size>& abscissa() {
        static const std::array<Real, size> a = converted(Table::x);
        return a;
    }
    static const std::array<Real, size>& weights() {
        static const std::array<Real, size> w = converted(Table::w);
        return w;
    }

  private:
    template <class T>
    static std::array<Real, size> converted(const T (&v)[size]) {
        std::array<Real, size> out;
        for (std::size_t i = 0; i < size; ++i) out[i] = Real(value_of(v[i]));
        return out;
    }
    template <class T>
    static T value_of(const T& v) { return v; }
    static __float128 value_of(const binary128_bits& v) {
        static_assert(sizeof(__float128) == sizeof v.half, "binary128 is two 64-bit halves");
        __float128 x;
        std::memcpy(&x, v.half, sizeof x);
        return x;
    }
};

}  // namespace detail

template <class Real, unsigned N, class = void>
struct gauss_rule;
template <class Real, unsigned N, class = void>
struct kronrod_rule;

template <class Real, unsigned N>
struct gauss_rule<Real, N, std::enable_if_t<detail::tabulated<detail::gauss_table, Real, N>>>
    : detail::tabulated_rule<Real, detail::gauss_table<detail::table_storage<Real>, N>> {};

template <class Real, unsigned N>
struct kronrod_rule<Real, N, std::enable_if_t<detail::tabulated<detail::kronrod_table, Real, N>>>
    : detail::tabulated_rule<Real, detail::kronrod_table<detail::table_storage<Real>, N>> {};

}  // namespace normzoo::quadrature
