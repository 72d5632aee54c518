// Every zoo row against its closed form, computed independently in 50 digits.
#include <catch2/catch.hpp>
#include <normzoo/normzoo.hpp>
#include <verify/tables/tables.hpp>
#include <random>

using normzoo::wide;

namespace {
template <class Row>
void check_row(double n) {
    const auto q1 = normzoo::zoo_norm_1d<Row>(n);
    const auto q2 = normzoo::zoo_norm_2d<Row>(n);
    const wide truth = Row::closed_form(wide(Row::has_exponent ? n : 0.0));
    const double err1 = static_cast<double>(abs(wide(q1.norm) - truth) / truth);
    const double err2 = static_cast<double>(abs(wide(q2.norm) - truth) / truth);
    CAPTURE(Row::id, n, err1, static_cast<double>(q1.rel_error), err2, static_cast<double>(q2.rel_error));
    CHECK(err1 <= static_cast<double>(q1.rel_error));  // the estimate is never below the true error
    CHECK(q1.rel_error < 1e-32);                        // >= 32 correct digits
    CHECK(err2 <= static_cast<double>(q2.rel_error));
    CHECK(q2.rel_error < 1e-14);                        // >= 14 correct digits
}
}  // namespace

TEST_CASE("each zoo row, 1D and 2D, against its closed form") {
    const double n = GENERATE(0.0, 1e-6, 0.1, 0.5, 1.0, 2.0, 3.7, 10.0, 64.0, 255.5, 1024.0, 2048.0, 1e4, 3.3e5,
                              1e6, 1e7, 1e8);
    normzoo::for_each_zoo_row([&](auto row) { check_row<decltype(row)>(n); });
}

TEST_CASE("1D estimates are honest over 300 random exponents per row") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> log_n(-6, 7);
    double worst = 0;
    normzoo::for_each_zoo_row([&](auto row) {
        using Row = decltype(row);
        for (int i = 0; i < 300; ++i) {
            const double n = std::pow(10.0, log_n(rng));
            const auto q = normzoo::zoo_norm_1d<Row>(n);
            const wide truth = Row::closed_form(wide(Row::has_exponent ? n : 0.0));
            const double ratio = static_cast<double>(abs(wide(q.norm) - truth) / truth / wide(q.rel_error));
            worst = std::max(worst, ratio);
            CAPTURE(Row::id, n);
            REQUIRE(ratio <= 1);
        }
    });
    INFO("largest true error / estimate: " << worst);
    CHECK(worst < 1);
}

TEST_CASE("the zoo table on the default grid passes, with lambert once") {
    const auto records = verify::zoo_table(verify::default_zoo_exponents(), 2);
    CHECK(records.size() == 1 + 6 * verify::default_zoo_exponents().size());
    for (const auto& r : records) {
        CAPTURE(std::get<std::string>(*r.find("row")), std::get<double>(*r.find("n")));
        CHECK_FALSE(r.failed());
        CHECK(std::get<double>(*r.find("digits")) >= 32);
        CHECK(std::get<double>(*r.find("digits_2d")) >= 14);
    }
}

namespace {
// The table's verdict compares two independent numbers: perturb one and it must fail.
struct wrong_phong : normzoo::zoo::phong {
    template <class T>
    static T closed_form(const T& n) { return (n + 1) / (2 * normzoo::pi<T>()) * (1 + T(1e-30)); }
};
}  // namespace

TEST_CASE("a wrong closed form is caught") {
    const auto r = verify::zoo_record<wrong_phong>(normzoo::decimal("8"), {});
    CHECK(r.failed());
}
