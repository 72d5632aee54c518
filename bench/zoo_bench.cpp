// Times one zoo integral at a time (1D binary128 and 2D long double) for every row and exponent
// of the default grid: warm-up, then the median of several runs. One JSON object per line.
#include <normzoo/normzoo.hpp>
#include <verify/tables/grid.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace {
template <class F>
double median_seconds(const F& f, int runs) {
    f();  // warm-up: node tables, caches
    std::vector<double> t;
    for (int i = 0; i < runs; ++i) {
        const auto a = std::chrono::steady_clock::now();
        f();
        t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

volatile double sink;
}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::atoi(argv[1]) : 21;
    normzoo::for_each_zoo_row([&](auto row) {
        using Row = decltype(row);
        std::vector<normzoo::decimal> grid = verify::default_zoo_exponents();
        if (!Row::has_exponent) grid = {normzoo::decimal()};
        for (const auto& nd : grid) {
            const double n = nd.to<double>();
            // As the table computes it: at the decimal (its bound covers the rounding to binary128),
            // and beside it the same integral at the double, to see what the exact input costs.
            const double t1 = median_seconds([&] { sink = static_cast<double>(normzoo::zoo_norm_1d<Row>(nd).norm); }, runs);
            const double t1d = median_seconds([&] { sink = static_cast<double>(normzoo::zoo_norm_1d<Row>(n).norm); }, runs);
            const double t2 = median_seconds([&] { sink = static_cast<double>(normzoo::zoo_norm_2d<Row>(nd).norm); }, runs);
            const auto q = normzoo::zoo_norm_1d<Row>(nd);
            // The double path: the same rule in double, against the closed form in ulps.
            const double td = median_seconds([&] { sink = normzoo::zoo_norm_1d<Row, double>(n).norm; }, runs);
            const double d = normzoo::zoo_norm_1d<Row, double>(n).norm;
            const normzoo::quad closed = Row::closed_form(normzoo::quad(Row::has_exponent ? n : 0.0));
            int e = 0;
            std::frexp(static_cast<double>(closed), &e);
            const double ulps = static_cast<double>(abs(normzoo::quad(d) - closed)) / std::ldexp(1.0, e - 53);
            std::printf("{\"row\":\"%s\",\"n\":%.17g,\"n_input\":\"%s\",\"seconds_1d\":%.6e,\"seconds_1d_double_input\":%.6e,"
                        "\"seconds_2d\":%.6e,\"evaluations_1d\":%zu,\"error_estimate\":%.3e,"
                        "\"seconds_double\":%.6e,\"ulps_double\":%.3f}\n",
                        Row::id, n, nd.text().c_str(), t1, t1d, t2, q.evaluations, static_cast<double>(q.rel_error), td, ulps);
        }
    });
}
