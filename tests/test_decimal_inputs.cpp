// Inputs are decimals (docs/conventions.md, "Inputs are decimals"): random decimal inputs of up
// to 25 significant digits, each computed by the library from its text and compared with the
// closed form evaluated in 50 digits from the same text. The bound a result reports must hold
// against that decimal, not against the double nearest it. Each case prints the largest true
// error and the smallest ratio bound / true error it saw (docs/method.md, "Inputs"). Last, the
// decimals of the default grids as the tables' heads write them.
#include <catch2/catch.hpp>

#include <normzoo/albedo.hpp>
#include <normzoo/albedo_input.hpp>
#include <normzoo/decimal.hpp>
#include <normzoo/irradiance.hpp>
#include <normzoo/normalization.hpp>
#include <normzoo/registry.hpp>
#include <normzoo/wide.hpp>
#include <verify/tables/energy.hpp>
#include <verify/tables/energy_grids.hpp>
#include <verify/tables/grid.hpp>
#include <verify/tables/grid_text.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace normzoo;
using namespace verify;  // the tables under test

namespace {

// A decimal of 1 to 25 significant digits, log-uniform in [lo, hi]: random digits (not a
// double's), so most have no binary expansion.
std::string random_decimal(std::mt19937_64& rng, double lo, double hi) {
    std::uniform_real_distribution<double> u(0, 1);
    const int digits = 1 + static_cast<int>(rng() % 25);
    for (;;) {
        const double target = std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * u(rng));
        const int e = static_cast<int>(std::floor(std::log10(target)));
        std::string text(1, static_cast<char>('1' + rng() % 9));
        if (digits > 1) text += '.';
        for (int k = 1; k < digits; ++k) text += static_cast<char>('0' + rng() % 10);
        text += "e" + std::to_string(e);
        const decimal d(text);
        if (d >= decimal(std::to_string(lo)) && d <= decimal(std::to_string(hi))) return text;
    }
}

// An angle in degrees in [0, top): a whole part and up to 25 significant digits, a quarter of
// them within 1e-3 to 1e-12 of `near` (grazing incidence, a light at the horizon).
std::string random_degrees(std::mt19937_64& rng, int top, int near) {
    const int digits = 1 + static_cast<int>(rng() % 25);
    std::string fraction;
    if (rng() % 4 == 0) {
        // near - 0.000...0ddd or near + 0.000...0ddd
        const int zeros = 3 + static_cast<int>(rng() % 10);
        std::string small = "0." + std::string(zeros - 1, '0');
        for (int k = 0; k < std::max(1, digits - 2); ++k) small += static_cast<char>('0' + rng() % 10);
        small += static_cast<char>('1' + rng() % 9);
        const decimal d = rng() % 2 || near >= top ? decimal(std::to_string(near)) - decimal(small)
                                                   : decimal(std::to_string(near)) - (decimal("0") - decimal(small));
        return d.text();
    }
    const int whole = static_cast<int>(rng() % top);
    std::string text = std::to_string(whole);
    const int left = digits - static_cast<int>(text.size());
    if (left > 0) {
        text += '.';
        for (int k = 0; k < left; ++k) text += static_cast<char>('0' + rng() % 10);
    }
    return text;
}

// The largest true error and the smallest ratio bound / true error over a set of cases.
struct tally {
    const char* what;
    double worst_error = 0, smallest_ratio = HUGE_VAL;
    int cases = 0, inexact = 0;
    void add(double error, double bound, bool exact) {
        ++cases;
        inexact += !exact;
        worst_error = std::max(worst_error, error);
        if (error > 0) smallest_ratio = std::min(smallest_ratio, bound / error);
    }
    ~tally() {
        std::cout << what << ": " << cases << " decimal inputs (" << inexact << " without a binary expansion), largest "
                  << "true error " << worst_error << ", smallest bound / true error " << smallest_ratio << "\n";
    }
};

}  // namespace

TEST_CASE("zoo: 1000 decimal exponents, every row, against the closed form in 50 digits") {
    std::mt19937_64 rng(20261124);
    tally all{"zoo 1D (binary128)"};
    for (int i = 0; i < 1000; ++i) {
        const std::string text = random_decimal(rng, 1e-6, 1e7);
        const decimal n(text);
        for_each_zoo_row([&](auto row) {
            using Row = decltype(row);
            if (!Row::has_exponent) return;
            const auto q = zoo_norm_1d<Row>(n);
            const wide truth = Row::closed_form(wide(text));  // Boost.Multiprecision reads the text exactly
            const double error = static_cast<double>(abs(wide(q.norm) - truth) / truth);
            CAPTURE(Row::id, text, error, static_cast<double>(q.rel_error));
            // the bound, and the rounding of the result to binary128 (half an ulp, the bound's own scope)
            CHECK(error <= static_cast<double>(q.rel_error) + static_cast<double>(eps<quad>()) / 2);
            all.add(error, static_cast<double>(q.rel_error), n.exact_in<quad>());
        });
    }
}

TEST_CASE("zoo: the 2D vector integral at decimal exponents, against the closed form in 50 digits") {
    std::mt19937_64 rng(7);
    tally all{"zoo 2D (long double)"};
    for (int i = 0; i < 100; ++i) {
        const std::string text = random_decimal(rng, 1e-6, 1e7);
        const auto q = zoo_norm_2d<zoo::blinn_phong>(decimal(text));
        const wide truth = zoo::blinn_phong::closed_form(wide(text));
        const double error = static_cast<double>(abs(wide(static_cast<double>(q.norm)) - truth) / truth);
        CAPTURE(text, error, static_cast<double>(q.rel_error));
        // the comparison rounds the long double to double: half a double's ulp more
        CHECK(error <= static_cast<double>(q.rel_error) + eps<double>() / 2);
        all.add(error, static_cast<double>(q.rel_error) + eps<double>() / 2, decimal(text).exact_in<long double>());
    }
}

TEST_CASE("the library reads a number as the decimal its text denotes") {
    const auto from_text = zoo_norm_1d<zoo::phong>("0.37");
    const auto from_decimal = zoo_norm_1d<zoo::phong>(decimal("0.37"));
    const auto from_double = zoo_norm_1d<zoo::phong>(0.37);  // the double is the input
    CHECK(from_text.norm == from_decimal.norm);
    const wide truth = zoo::phong::closed_form(wide("0.37"));
    CHECK(static_cast<double>(abs(wide(from_decimal.norm) - truth) / truth) <= static_cast<double>(from_decimal.rel_error));
    // The double 0.37 is 0.36999999999999999555...: its normalization is that number's, 3e-18 away.
    CHECK(static_cast<double>(abs(wide(from_double.norm) - truth) / truth) > 1e-18);
}

TEST_CASE("the check fails where the input goes through a double") {
    // What the tables did before inputs were decimals: parse the text as a double, integrate at
    // that double and report the quadrature's own bound. Against the decimal it fails.
    std::mt19937_64 rng(20261124);
    int failing = 0;
    for (int i = 0; i < 100; ++i) {
        const std::string text = random_decimal(rng, 1e-6, 1e7);
        const auto q = zoo_norm_1d<zoo::phong>(quad(std::strtod(text.c_str(), nullptr)));
        const wide truth = zoo::phong::closed_form(wide(text));
        failing += static_cast<double>(abs(wide(q.norm) - truth) / truth) > static_cast<double>(q.rel_error) + 1e-34;
    }
    CHECK(failing > 50);
}

TEST_CASE("irradiance: 1000 decimal ratios and tilts, sphere and disk, against the closed forms in 50 digits") {
    std::mt19937_64 rng(1729);
    tally all{"irradiance (binary128)"};
    for (int i = 0; i < 1000; ++i) {
        const light_kind kind = i % 2 ? light_kind::sphere : light_kind::disk;
        const std::string ratio = random_decimal(rng, 1e-300, 0.9);
        const std::string tilt = random_degrees(rng, 180, 90);
        const auto q = cap_irradiance(kind, decimal(ratio), decimal(tilt));
        const auto cap = light_cap<wide>::of(kind, wide(ratio));
        const auto t = degrees_of<wide>(decimal(tilt));
        const wide truth = cap_irradiance_closed_form(cap, t).value;
        const double error = static_cast<double>(abs(wide(q.value) - truth));
        const double scale = truth != 0 ? static_cast<double>(truth) : 1.0;
        CAPTURE(light_name(kind), ratio, tilt, error / scale, static_cast<double>(q.abs_error) / scale);
        CHECK(error <= static_cast<double>(q.abs_error) + static_cast<double>(eps<quad>()) / 2 * scale);
        if (truth != 0)
            all.add(error / scale, static_cast<double>(q.abs_error) / scale,
                    decimal(ratio).exact_in<quad>() && decimal(tilt).exact_in<quad>());
    }
}

TEST_CASE("energy: decimal incident angles and exponents, against closed forms in 50 digits") {
    std::mt19937_64 rng(42);
    tally angles{"albedo at decimal angles (ashikhmin-shirley-diffuse)"};
    for (int i = 0; i < 200; ++i) {
        const std::string theta = random_degrees(rng, 90, 90);
        const decimal t(theta);
        if (!(t < decimal("90"))) continue;
        const auto e = albedo<brdf::ashikhmin_shirley_diffuse>(t, 0);
        const wide truth = brdf::ashikhmin_shirley_diffuse::albedo_at(degrees_of<wide>(t).cos_t);
        const double error = std::abs(static_cast<double>(wide(e.value) - truth));
        CAPTURE(theta, error, e.abs_error);
        CHECK(error <= e.abs_error);
        angles.add(error, e.abs_error, t.exact_in<double>());
    }
    tally exponents{"albedo at decimal exponents (phong, L = N)"};
    for (int i = 0; i < 100; ++i) {
        const std::string text = random_decimal(rng, 1e-6, 1e7);
        const auto a = energy_point<brdf::phong>(decimal(text), decimal("0"), energy_settings{});
        const wide n(text), truth = (n + 1) / (n + 2);
        const double error = std::abs(static_cast<double>(wide(a.albedo.value) - truth));
        CAPTURE(text, error, a.albedo.abs_error);
        CHECK(error <= a.albedo.abs_error);
        exponents.add(error, a.albedo.abs_error, decimal(text).exact_in<double>());
    }
}

TEST_CASE("decimal: exactness, rounding, comparison and difference") {
    CHECK(decimal("0.5").exact_in<double>());
    CHECK(decimal("1e22").exact_in<double>());
    CHECK_FALSE(decimal("1e23").exact_in<double>());
    CHECK_FALSE(decimal("0.1").exact_in<quad>());
    CHECK(decimal("0.1").rounding<double>() == eps<double>());
    CHECK(decimal("3").rounding<quad>() == 0);
    CHECK(decimal("4.9406564584124654e-324").to<double>() == std::numeric_limits<double>::denorm_min());
    CHECK(decimal("90") - decimal("89.99") == decimal("0.01"));
    CHECK(decimal("89.99999999999999999999") < decimal("90"));
    CHECK(decimal("-0") == decimal("0"));
    CHECK(decimal::exactly(0.1) > decimal("0.1"));  // the double 0.1 is 0.1000000000000000055...
    CHECK(decimal::shortest(0.1) == decimal("0.1"));
    const std::string bad = GENERATE("", "+", ".", "1e", "1.2.3", "0x10", "nan", "inf", "1 ", "1e100001");
    CAPTURE(bad);
    CHECK_THROWS_AS(decimal(bad), std::invalid_argument);
}

// A table's head states its grid in words made from the grid's values (tables/grid_text.hpp):
// the committed heads' texts, and a grid changed is a text changed.
TEST_CASE("grid text: a grid's values in words with its runs shortened") {
    CHECK(value_text(1e4) == "1e4");
    CHECK(value_text(1000) == "1000");
    CHECK(value_text(1e-3) == "1e-3");
    CHECK(value_text(0.05) == "0.05");
    CHECK(value_text(89.99) == "89.99");
    CHECK(value_text(2.5e-7) == "2.5e-7");
    CHECK(value_text(0) == "0");
    CHECK(list_text(default_zoo_exponents()) == "0, 0.1, 0.5, 1, 2, 4, ..., 2048, 1e4, 1e5, 1e6, 1e7");
    CHECK(list_text(default_energy_exponents()) == "1, 2, 4, ..., 2048, 1e4, 1e5");
    CHECK(list_text(default_energy_angles()) == "0, 1, ..., 89, 89.5, 89.9, 89.99");
    CHECK(list_text(decimals({"1", "2", "4", "8", "16", "32", "64", "128", "512", "2048"})) ==
          "1, 2, 4, ..., 128, 512, 2048");
    CHECK(list_text(decimals({"1e-4", "1e-3", "0.01", "0.05", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8",
                              "0.9", "1"})) == "1e-4, 1e-3, 0.01, 0.05, 0.1 to 1 by 0.1");
    std::vector<decimal> ratios;
    for (int k = 1; k <= 15; ++k) ratios.emplace_back("1e-" + std::to_string(k));
    for (const char* x : {"1e-30", "1e-100", "1e-300"}) ratios.emplace_back(x);
    CHECK(list_text(ratios) == "1e-1 to 1e-15 by decades, 1e-30, 1e-100, 1e-300");
    // four values are all shown: no run to shorten
    CHECK(list_text(std::vector<double>{1, 10, 100, 1000}) == "1, 10, 100, 1000");
    CHECK(list_text(std::vector<double>{0.1, 0.3, 0.5, 0.7, 1}) == "0.1, 0.3, 0.5, 0.7, 1");
    CHECK(list_text(std::vector<double>{0, 30, 60, 80, 85, 89, 89.9}) == "0, 30, 60, 80, 85, 89, 89.9");
    // the grid changed, the text with it
    auto longer = default_energy_exponents();
    longer.insert(longer.begin() + 12, 4096);
    CHECK(list_text(longer) == "1, 2, 4, ..., 4096, 1e4, 1e5");
    CHECK(range_text(decimals({"1e-1", "1e-2", "1e-8"})) == "1e-1 to 1e-8");
    CHECK(count_text(4) == "four");
    CHECK(default_bounds_grid.text() == "0 and 1000 log-spaced from 1e-6 to 1e7");
}

TEST_CASE("grid text: the forms' declared grids from the registry") {
    CHECK(declared_grids_text() ==
          "n = 1, 2, 4, ..., 2048, 1e4, 1e5; Ashikhmin-Shirley n = 1, 10, 100, 1000; alpha = 0.1, 0.3, 0.5, 0.7, 1; "
          "r = 0, 0.5, 1");
}
