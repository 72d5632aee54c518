#include <catch2/catch.hpp>
#include <normzoo/normzoo.hpp>
#include <verify/tables/tables.hpp>

using normzoo::wide;

namespace {
const verify::record& find(const std::vector<verify::record>& rs, const std::string& row, double n) {
    for (const auto& r : rs)
        if (std::get<std::string>(*r.find("row")) == row && std::get<double>(*r.find("n")) == n) return r;
    throw std::runtime_error("no record");
}
bool flag(const verify::record& r, const char* k) { return std::get<bool>(*r.find(k)); }
}  // namespace

TEST_CASE("n = 0: the upper bounds are equalities, reported as such and not as failures") {
    const auto rs = verify::bounds_table(verify::shortest_decimals({0.0}));
    for (const char* row : {"blinn-phong", "blinn-phong-modified"}) {
        const auto& r = find(rs, row, 0.0);
        CHECK(flag(r, "equality"));
        CHECK_FALSE(flag(r, "holds"));
        CHECK_FALSE(r.failed());
    }
    // And the equality is real: the closed forms meet the upper bounds exactly.
    CHECK(normzoo::zoo::blinn_phong::closed_form(wide(0)) == 4 / (8 * normzoo::pi<wide>()));
    CHECK(normzoo::zoo::blinn_phong_modified::closed_form(wide(0)) == 8 / (8 * normzoo::pi<wide>()));
}

TEST_CASE("strict bounds where double cannot see the margin") {
    const double n = GENERATE(1e-6, 0.3, 200.0, 2048.0, 1e5, 1e7);
    const auto rs = verify::bounds_table(verify::shortest_decimals({n}));
    for (const char* row : {"blinn-phong", "blinn-phong-modified"}) {
        const auto& r = find(rs, row, n);
        CAPTURE(row, n);
        CHECK(flag(r, "holds"));
        CHECK_FALSE(flag(r, "equality"));
        CHECK_FALSE(r.failed());
    }
    // The blinn-phong lower margin is 2^(-n/2)/(2 - 2^(-n/2)): its log10 from logs alone.
    const double expected_log10 = -n / 2 * std::log10(2.0) - std::log10(2 - std::pow(2.0, -n / 2));
    CHECK(std::get<double>(*find(rs, "blinn-phong", n).find("lower_margin_log10")) ==
          Approx(expected_log10).epsilon(1e-12).margin(1e-12));
    if (n >= 200) CHECK_FALSE(flag(find(rs, "blinn-phong", n), "decided_in_double"));
}

TEST_CASE("margins rewritten without cancellation agree with the naive ones in 100 digits") {
    using hundred = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<100>>;
    for (double n : {1e-6, 0.01, 1.0, 9.0, 60.0}) {
        const auto m = normzoo::blinn_phong_modified_margins(wide(n));
        const hundred h = n;
        const hundred norm = (h + 2) * (h + 4) / (8 * boost::math::constants::pi<hundred>() * (pow(hundred(2), -h / 2) + h));
        const hundred upper = 1 - norm / ((h + 8) / (8 * boost::math::constants::pi<hundred>()));
        CAPTURE(n);
        CHECK(static_cast<double>(abs(hundred(m.upper_margin) - upper) / upper) < 1e-45);
    }
}

TEST_CASE("the default grid: 1000 log-spaced exponents plus 0, all decided") {
    const auto grid = verify::default_bounds_exponents();
    CHECK(grid.size() == 1001);
    CHECK(grid.front() == normzoo::decimal("0"));
    CHECK(grid[1] == normzoo::decimal("1e-6"));
    CHECK(grid.back() == normzoo::decimal("1e7"));
    const auto rs = verify::bounds_table(grid);
    std::size_t fails = 0;
    for (const auto& r : rs) fails += r.failed();
    CHECK(fails == 0);
}
