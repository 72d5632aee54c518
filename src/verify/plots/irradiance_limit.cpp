// irradiance-limit.svg: log-log convergence to the point light. Left, the irradiance's deviation
// against r0/r (irradiance table); right, the tiny cone's against its half-angle (punctual-limit).
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace verify {

namespace {

// A curve of |deviation| against `x_key`, of the rows where the deviation stands clear of its
// error estimate (by 1e3), added to the panel (and its y extent); none when fewer than two do.
void add_resolved(const plots::selection& rows, const char* x_key, const std::string& title, const char* with,
                  plots::blocks& data, plots::panel& p, std::pair<double, double>& extent) {
    plots::points resolved;
    for (const auto* r : rows) {
        const double d = std::abs(r->number("deviation"));
        if (d > 1e3 * r->number("error_estimate") && d > 0) resolved.emplace_back(r->number(x_key), d);
    }
    if (resolved.size() < 2) return;
    for (const auto& pt : resolved) extent = {std::min(extent.first, pt.second), std::max(extent.second, pt.second)};
    p.curves.push_back(plots::curve(data.add(resolved), with, "", title));
}

// Where a panel's data are flat (or it has none, and shows only its line at 1), gnuplot would
// warn of an empty y range, widen it by 1% and round it out to decades: that range is set instead,
// so it draws the same without the warning. Returns whether it set one.
bool fix_flat_range(plots::panel& p, std::pair<double, double> extent) {
    if (p.curves.empty()) extent = {1, 1};
    if (extent.first != extent.second) return false;
    std::ostringstream range;
    range << "set yrange [" << std::pow(10.0, std::floor(std::log10(0.99 * extent.first))) << ":"
          << std::pow(10.0, std::ceil(std::log10(1.01 * extent.second))) << "]\n";
    p.settings += range.str();
    return true;
}

}  // namespace

bool plot_limits(const std::vector<record>& irradiance, const table_output& punctual, file_set& files) {
    plots::blocks data;
    plots::panel left{"Light of fixed intensity: |E r^2 / (I cos t_c) - 1| against r_0/r",
                      "set xlabel 'r_0 / r'\nset ylabel 'deviation from the point light'\n",
                      {}};
    const auto by_light_and_tilt = [](const record& r) {
        std::ostringstream k;
        k << r.text("light") << " tilt " << r.number("tilt_deg");
        return k.str();
    };
    const double inf = std::numeric_limits<double>::infinity();
    std::pair<double, double> left_extent{inf, -inf}, right_extent{inf, -inf};
    for (const auto& [key, rows] : plots::group_by(plots::all_rows(irradiance), by_light_and_tilt))
        add_resolved(rows, "ratio", key, "linespoints lw 2", data, left, left_extent);

    plots::panel right{"Tiny cone of half-angle e (l_c at 45 deg, V near the mirror direction, n = 32)",
                       "set xlabel 'e (radians)'\nset ylabel '|cone / point light - 1|'\n"
                       "set key bottom right font ',9'\n",
                       {}};
    plots::selection pairs;  // one pair per form: l_c at 45 deg, V near the mirror
    for (const auto& r : punctual.records)
        if (r.number("lc_theta_deg") == 45) pairs.push_back(&r);
    for (const auto& [model, rows] : plots::group_by(pairs, plots::by_text("model")))
        add_resolved(rows, "epsilon", model, "linespoints lw 1.5", data, right, right_extent);
    if (fix_flat_range(left, left_extent)) right.settings = "set autoscale y\n" + right.settings;
    fix_flat_range(right, right_extent);
    return plots::draw_panels("irradiance-limit.svg", "", data,
                              "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset key bottom right\n",
                              {left, right}, 2, 600, 520, files);
}

}  // namespace verify
