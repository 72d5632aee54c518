#include <catch2/catch.hpp>
#include <normzoo/normzoo.hpp>
#include <verify/tables/tables.hpp>

TEST_CASE("(n+8)/(8 pi): largest relative error, against an independent double scan") {
    const auto [worst, at] = verify::approx_worst_error();
    // Naive double evaluation is accurate to ~1e-15 for n in [1, 100], where the maximum is.
    double best = 0, best_n = 0;
    for (double n = 1; n <= 100; n += 1e-4) {
        const double exact = (n + 2) * (n + 4) / (8 * M_PI * (std::pow(2.0, -n / 2) + n));
        const double e = (n + 8) / (8 * M_PI) / exact - 1;
        if (e > best) best = e, best_n = n;
    }
    CHECK(worst == Approx(best).epsilon(1e-9));
    CHECK(at == Approx(best_n).epsilon(1e-3));
    CHECK(worst > 0.07);
}

TEST_CASE("microfacet constant and approximation records pass") {
    const auto rs = verify::zoo_constants_table(verify::shortest_decimals({0.0, 1.0, 2048.0, 1e7}), 2);
    for (const auto& r : rs) CHECK_FALSE(r.failed());
}

TEST_CASE("8-bit gloss decoding") {
    const auto rs = verify::gloss_table();
    REQUIRE(rs.size() == 256);
    CHECK(std::get<double>(*rs.front().find("n")) == 2.0);
    CHECK(std::get<double>(*rs.back().find("n")) == Approx(2048.0).epsilon(1e-15));
    CHECK(std::get<double>(*rs[100].find("n_step_rel")) == Approx(std::pow(2.0, 10.0 / 255) - 1));
}
