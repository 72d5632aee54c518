// ndf.svg: the non-projected integral of Beckmann and GGX less 1 against alpha, log-log: the
// closed form on a fine alpha grid as lines, the table's quadrature as points.
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <normzoo/real.hpp>
#include <normzoo/wide.hpp>
#include <normzoo/registry.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace verify {

namespace {

// value - 1 of a value printed near 1 in 20 digits: parsed in long double, which keeps about 11
// digits of it at 1 + 5e-9 (a double would keep 8).
double minus_one(const record& r, const std::string& key) {
    const std::string decimal = r.text(key);
    if (!decimal.empty()) return static_cast<double>(std::strtold(decimal.c_str(), nullptr) - 1);
    return r.number(key) - 1;
}

}  // namespace

bool plot_ndf(const table_output& ndf, file_set& files) {
    plots::blocks data;
    plots::panel p{"Non-projected integral of D(h) less 1 against alpha: closed form (lines), quadrature (points)",
                   "",
                   {}};
    for (const auto& [id, of_ndf] : plots::group_by(plots::all_rows(ndf.records), plots::by_text("ndf"))) {
        plots::points quadrature, closed;
        double lo = std::numeric_limits<double>::infinity(), hi = 0;
        for (const auto* r : of_ndf) {
            const double a = r->number("alpha");
            quadrature.emplace_back(a, minus_one(*r, "non_projected_quadrature"));
            lo = std::min(lo, a), hi = std::max(hi, a);
        }
        normzoo::with_ndf(id, [&](auto row) {  // 50 digits: e^(1/a^2) overflows double below a = 0.04
            for (int k = 0; k <= 200; ++k) {
                const double a = lo * std::pow(hi / lo, k / 200.0);
                closed.emplace_back(a, static_cast<double>(decltype(row)::non_projected(normzoo::wide(a)) - 1));
            }
        });
        const char* colour = plots::palette[p.curves.size() / 2 % plots::palette_size];
        p.curves.push_back(plots::curve(data.add(closed), "lines lw 2", colour, id + ": closed form"));
        p.curves.push_back(plots::curve(data.add(quadrature), "points pt 7 ps 0.8", colour, id + ": quadrature"));
    }
    if (p.curves.empty()) return false;
    return plots::draw_panels("ndf.svg", "", data,
                              "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset key top left\n"
                              "set xlabel 'roughness alpha'\nset ylabel 'integral of D(h) over the hemisphere - 1'\n",
                              {p}, 1, 900, 560, files);
}

}  // namespace verify
