// microfacet-energy.svg: E(mu, alpha) of each reference composition as a map over log mu and log
// alpha, its colour range fitted to the panel's data; microfacet-shortcuts.svg: the shortcuts' error
// maps alike; microfacet-eavg.svg: E_avg(alpha) curves.
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace verify {

namespace {

// One map of a multiplot: its title, its data block (scans of constant alpha) and its colour range.
struct map_panel {
    std::string title;
    int block;
    double lo, hi;
};

// Maps over log mu and log alpha, three across, each coloured over its own range.
bool draw_maps(const std::string& name, const std::string& title, const plots::blocks& data,
               const std::vector<map_panel>& panels, file_set& files) {
    if (panels.empty()) return false;
    const int cols = std::min<int>(3, int(panels.size())), rows = int((panels.size() + cols - 1) / cols);
    std::ostringstream g;
    g << "set multiplot layout " << rows << "," << cols << " title " << plots::quoted(title) << "\n"
      << "set view map\nset pm3d map corners2color c1\nset logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
      << "set xlabel 'mu = cos t'\nset ylabel 'alpha'\nset palette rgbformulae 33,13,10\n";
    for (const auto& p : panels)
        g << "set title " << plots::quoted(p.title) << "\nset cbrange [" << p.lo << ":" << p.hi << "]\nsplot data index "
          << p.block << " using 1:2:3 with pm3d notitle\n";
    g << "unset multiplot\n";
    return plots::draw(name, data, {520 * cols, 420 * rows, 11}, g.str(), files);
}

}  // namespace

bool plot_microfacet_energy(const table_output& energy, file_set& files) {
    plots::blocks data;
    std::vector<map_panel> panels;
    for (const auto& [model, rows] : plots::group_by(plots::all_rows(energy.records), plots::by_text("model"))) {
        std::map<double, std::map<double, double>> grid;  // alpha -> mu -> E
        for (const auto* r : rows) grid[r->number("alpha")][r->number("mu")] = r->number("albedo");
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const auto& [alpha, by_mu] : grid) {
            for (const auto& [mu, e] : by_mu) data.row({mu, alpha, e}), lo = std::min(lo, e), hi = std::max(hi, e);
            data.text += "\n";  // one scan per alpha: pm3d draws the grid between scans
        }
        const int block = data.end();
        if (hi - lo < 1e-6) lo -= 1e-6, hi += 1e-6;  // a flat map (a furnace at 1) still gets a scale
        panels.push_back({model, block, lo, hi});
    }
    return draw_maps("microfacet-energy.svg", "Directional albedo E(mu, alpha), F = 1", data, panels, files);
}

bool plot_error_maps(const std::vector<error_map>& maps, file_set& files) {
    plots::blocks data;
    std::vector<map_panel> panels;
    for (const auto& m : maps) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (std::size_t j = 0; j < m.alphas.size(); ++j) {
            for (std::size_t i = 0; i < m.mus.size(); ++i) {
                // |error| below 1e-16 is rounding: drawn at 1e-16
                const double e = std::log10(std::max(std::abs(m.values[j * m.mus.size() + i]), 1e-16));
                data.row({m.mus[i], m.alphas[j], e});
                lo = std::min(lo, e), hi = std::max(hi, e);
            }
            data.text += "\n";
        }
        const int block = data.end();
        if (hi - lo < 0.1) lo -= 0.05, hi += 0.05;
        panels.push_back({m.title, block, lo, hi});
    }
    return draw_maps("microfacet-shortcuts.svg", "log10 |shortcut - exact| over (mu, alpha)", data, panels, files);
}

bool plot_microfacet_eavg(const table_output& eavg, file_set& files) {
    plots::blocks data;
    plots::panel p{"E_avg(alpha) = 2 integral of E(mu) mu dmu (F = 1): what single scattering keeps", "", {}};
    for (const auto& [model, rows] : plots::group_by(plots::all_rows(eavg.records), plots::by_text("model"))) {
        plots::points pts;
        for (const auto* r : rows) pts.emplace_back(r->number("alpha"), r->number("E_avg"));
        const char* colour = plots::palette[p.curves.size() % plots::palette_size];
        p.curves.push_back(plots::curve(data.add(pts), "linespoints lw 2 pt 7 ps 0.7", colour, model));
    }
    if (p.curves.empty()) return false;
    return plots::draw_panels("microfacet-eavg.svg", "", data,
                              "set logscale x\nset format x '10^{%L}'\nset key bottom left\nset xlabel 'alpha'\n"
                              "set ylabel 'E_{avg}'\n",
                              {p}, 1, 900, 560, files);
}

}  // namespace verify
