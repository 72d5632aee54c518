// An independent check of an OpenPBR material's albedo (tests/test_material_openpbr*.cpp): each
// lobe's f(L, V) integrated over L by plain Gauss-Kronrod in polar coordinates, broken at V's polar
// angle and at phi = pi/2 (FON's kink), against openpbr_albedo's per lobe and channel: every lobe,
// or the `lobes` given (each is its own nested integral, and f(L, V) is costly under a film).
#pragma once
#include <catch2/catch.hpp>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstddef>
#include <vector>

#include <normzoo/material/openpbr.hpp>

namespace normzoo_test {

inline void check_lobes_over_l(const normzoo::material::openpbr& m, double mu, double tolerance,
                               std::vector<std::size_t> lobes = {0, 1, 2, 3, 4}) {
    using boost::math::quadrature::gauss_kronrod;
    namespace mat = normzoo::material;
    const double tv = std::acos(mu), pi = normzoo::pi<double>();
    const normzoo::vec3<double> v(std::sqrt(1 - mu * mu), 0, mu);
    const auto e = mat::openpbr_albedo(m, mu);
    const auto terms = mat::openpbr_terms(m, mu).values();
    const double relative = tolerance / 100;  // Gauss-Kronrod's target, well inside the comparison's
    for (const std::size_t i : lobes)
        for (std::size_t k = 0; k < 3; ++k) {
            auto over_phi = [&](double t) {
                auto g = [&](double phi) {
                    const normzoo::vec3<double> l(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t));
                    return m.f_lobes(l, v, terms)[i][k] * std::cos(t) * std::sin(t);
                };
                return 2 * (gauss_kronrod<double, 61>::integrate(g, 0, pi / 2, 10, relative) +
                            gauss_kronrod<double, 61>::integrate(g, pi / 2, pi, 10, relative));
            };
            const double q = gauss_kronrod<double, 61>::integrate(over_phi, 0, tv, 10, relative) +
                             gauss_kronrod<double, 61>::integrate(over_phi, tv, pi / 2, 10, relative);
            INFO("lobe " << i << " channel " << k);
            CHECK(std::abs(q - e.lobes[i].value[k]) <= tolerance);
        }
}

}  // namespace normzoo_test
