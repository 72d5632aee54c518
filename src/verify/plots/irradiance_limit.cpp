// irradiance-limit.svg: log-log convergence to the point light. Left, the irradiance's deviation
// against r0/r (irradiance table); right, the tiny cone's against its half-angle (punctual-limit).
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <cmath>
#include <sstream>

namespace verify {

namespace {

// A curve of |deviation| against `x_key`, of the rows where the deviation stands clear of its
// error estimate (by 1e3), added to the panel; none when fewer than two do.
void add_resolved(const plots::selection& rows, const char* x_key, const std::string& title, const char* with,
                  plots::blocks& data, plots::panel& p) {
    plots::points resolved;
    for (const auto* r : rows) {
        const double d = std::abs(r->number("deviation"));
        if (d > 1e3 * r->number("error_estimate") && d > 0) resolved.emplace_back(r->number(x_key), d);
    }
    if (resolved.size() < 2) return;
    p.curves.push_back(plots::curve(data.add(resolved), with, "", title));
}

}  // namespace

bool plot_limits(const std::vector<normzoo::record>& irradiance, const table_output& punctual, file_set& files) {
    plots::blocks data;
    plots::panel left{"Light of fixed intensity: |E r^2 / (I cos t_c) - 1| against r_0/r",
                      "set xlabel 'r_0 / r'\nset ylabel 'deviation from the point light'\n",
                      {}};
    const auto by_light_and_tilt = [](const normzoo::record& r) {
        std::ostringstream k;
        k << r.text("light") << " tilt " << r.number("tilt_deg");
        return k.str();
    };
    for (const auto& [key, rows] : plots::group_by(plots::all_rows(irradiance), by_light_and_tilt))
        add_resolved(rows, "ratio", key, "linespoints lw 2", data, left);

    plots::panel right{"Tiny cone of half-angle e (l_c at 45 deg, V near the mirror direction, n = 32)",
                       "set xlabel 'e (radians)'\nset ylabel '|cone / point light - 1|'\nset key bottom right font ',9'\n",
                       {}};
    plots::selection pairs;  // one pair per form: l_c at 45 deg, V near the mirror
    for (const auto& r : punctual.records)
        if (r.number("lc_theta_deg") == 45) pairs.push_back(&r);
    for (const auto& [model, rows] : plots::group_by(pairs, plots::by_text("model")))
        add_resolved(rows, "epsilon", model, "linespoints lw 1.5", data, right);
    return plots::draw_panels("irradiance-limit.svg", "", data,
                              "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset key bottom right\n",
                              {left, right}, 2, 600, 520, files);
}

}  // namespace verify
