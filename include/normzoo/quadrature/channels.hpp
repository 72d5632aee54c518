// Several integrals over one domain from the same nodes: a vector-valued integrand whose values
// are `channels` (the split-sum pair A, B of microfacet/split_sum.hpp is one). The adaptive rules
// (adaptive.hpp, periodic.hpp) take a number or channels alike: they bisect and stop on the
// magnitude, the sum of the channels' |values|, so that each channel's bound is at most the
// tolerance, and return each channel's value with its own bound.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>

namespace normzoo::quadrature {

template <class Real, std::size_t N>
struct channels {
    std::array<Real, N> c{};

    Real& operator[](std::size_t i) { return c[i]; }
    const Real& operator[](std::size_t i) const { return c[i]; }
    channels& operator+=(const channels& o) {
        for (std::size_t i = 0; i < N; ++i) c[i] += o.c[i];
        return *this;
    }
    channels& operator-=(const channels& o) {
        for (std::size_t i = 0; i < N; ++i) c[i] -= o.c[i];
        return *this;
    }
    friend channels operator+(channels a, const channels& b) { return a += b; }
    friend channels operator-(channels a, const channels& b) { return a -= b; }
    friend channels operator*(const Real& s, channels a) {
        for (auto& x : a.c) x = s * x;
        return a;
    }
    friend channels operator*(channels a, const Real& s) {
        for (auto& x : a.c) x = x * s;
        return a;
    }
    friend channels operator/(channels a, const Real& s) {
        for (auto& x : a.c) x = x / s;
        return a;
    }
    friend channels abs(channels a) {
        using std::abs;
        for (auto& x : a.c) x = abs(x);
        return a;
    }
    // channel by channel
    friend channels max(channels a, const channels& b) {
        for (std::size_t i = 0; i < N; ++i)
            if (b.c[i] > a.c[i]) a.c[i] = b.c[i];
        return a;
    }
};

// The size of a value that the adaptive rules compare with their tolerance: |x| for a number,
// the sum of the channels' |values|.
template <class Real>
Real magnitude(const Real& x) {
    using std::abs;
    return abs(x);
}
template <class Real, std::size_t N>
Real magnitude(const channels<Real, N>& x) {
    using std::abs;
    Real s = 0;
    for (const auto& v : x.c) s += abs(v);
    return s;
}

}  // namespace normzoo::quadrature
