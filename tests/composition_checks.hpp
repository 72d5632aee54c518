// A check shared by the composition tests: an albedo against the generic lobe-centred integral.
#pragma once
#include <catch2/catch.hpp>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <normzoo/albedo.hpp>
#include <normzoo/brdf/microfacet.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <normzoo/detail/complete_elliptic.hpp>
#include <normzoo/real.hpp>
#include <normzoo/detail/sign_changes.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/composition.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>
#include <normzoo/microfacet/split_sum.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace composition_checks {

using namespace normzoo;
using microfacet::composition;

// An albedo e of c against the generic lobe-centred integral of albedo.hpp, which shares no
// coordinates with the others, at 1e-12: within the two bounds, and e's bound within 1e-10.
inline void check_against_generic(const std::string& id, const composition& c, double mu, double alpha, double f0,
                           const quadrature::estimate<double>& e) {
    const auto g = albedo<composition>(microfacet::angle_of_cosine(mu), composition::node_exponent(alpha), f0,
                                       albedo_settings{1e-12}, alpha, c);
    CAPTURE(id, alpha, mu, e.value, e.abs_error, g.value, g.abs_error);
    CHECK(std::abs(e.value - g.value) <= e.abs_error + g.abs_error);
    CHECK(e.abs_error <= 1e-10);
}

}  // namespace composition_checks
