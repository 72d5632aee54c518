// lut-check-STEM.svg: a checked table's error per texel over its own coordinates (docs/lut.md,
// "The error map"): a map per channel (and of E = F0 A + B at F0 = 0.04), log10 |stored - exact|
// in viridis, and a map of the texels beyond their tolerance; for E_avg, curves.
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace verify {

namespace {

// Viridis (matplotlib's), at eleven evenly spaced stops: perceptually uniform, legible in grey.
const char* viridis = "set palette defined (0 '#440154', 1 '#482475', 2 '#414487', 3 '#355f8d', 4 '#2a788e', 5 '#21918c', "
                      "6 '#22a884', 7 '#44bf70', 8 '#7ad151', 9 '#bddf26', 10 '#fde725')\n";

// The decades the maps span: from the largest finite error down, at most 8 (an error of 0, or
// below the range, is drawn at its foot).
std::pair<double, double> decades(const lut_error_map& m) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& e : m.errors)
        for (double x : e)
            if (x > 0 && std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    if (!(hi > 0)) return {-12, -11};
    const double top = std::ceil(std::log10(hi) + 1e-9);
    return {std::max(std::floor(std::log10(lo)), top - 8), top};
}

// The settings of an axis drawn from its cells' coordinates: the label, and the range that holds
// the cells whole and the axis from 0 to 1.
std::string axis_settings(const char* which, const std::string& label, const std::vector<double>& cells) {
    const double half = cells.size() > 1 ? (cells[1] - cells[0]) / 2 : 0.5;
    std::ostringstream s;
    s << "set " << which << "label " << plots::quoted(label == "sqrt-mu" ? "sqrt(mu), mu = N.V" : label == "mu" ? "mu = N.V"
                                                      : label == "r" ? "r (alpha = r^2)" : "alpha")
      << "\nset " << which << "range [" << std::min(0.0, cells.front() - half) << ":" << std::max(1.0, cells.back() + half) << "]\n";
    return s.str();
}

bool draw_maps(const lut_error_map& m, const std::string& name, const std::string& title, file_set& files) {
    plots::blocks data;
    data.precision = 9;
    const auto [lo, hi] = decades(m);
    std::vector<int> maps;
    for (const auto& e : m.errors) {
        for (std::size_t j = 0; j < m.ys.size(); ++j) {
            for (std::size_t i = 0; i < m.xs.size(); ++i) {
                const double x = e[j * m.xs.size() + i];
                data.row({m.xs[i], m.ys[j], std::isnan(x) ? x : std::clamp(std::log10(std::max(x, 1e-300)), lo, hi)});
            }
            data.text += "\n";
        }
        maps.push_back(data.end());
    }
    plots::points marked;  // a few cells beyond their tolerance are circled as well: one texel of 1024 is a dot
    for (std::size_t j = 0; j < m.ys.size(); ++j)
        for (std::size_t i = 0; i < m.xs.size(); ++i) {
            data.row({m.xs[i], m.ys[j], double(m.above[j * m.xs.size() + i])});
            if (m.above[j * m.xs.size() + i]) marked.emplace_back(m.xs[i], m.ys[j]);
        }
    const int above = data.end();
    const std::string circles = !marked.empty() && marked.size() <= 500
                                    ? ", " + plots::curve(data.add(marked), "points pt 6 ps 1.5", "black", "")
                                    : std::string();
    const std::size_t panels = maps.size() + 1;
    const int cols = panels > 2 ? 2 : int(panels), rows = int((panels + 1) / 2);
    std::ostringstream g;
    g << "set multiplot layout " << rows << "," << cols << " title " << plots::quoted(title) << " noenhanced\n"
      << axis_settings("x", m.mu_axis, m.xs) << axis_settings("y", m.roughness_axis, m.ys) << "set size ratio -1\n";
    const std::string cell = m.block > 1 ? " (a cell: the largest of " + std::to_string(m.block) + " x " + std::to_string(m.block) + " texels)" : "";
    for (std::size_t k = 0; k < maps.size(); ++k)
        g << viridis << "set cbrange [" << lo << ":" << hi << "]\nset cbtics 1\nset format cb '10^{%.0f}'\nset title "
          << plots::quoted("|stored - exact|, " + m.names[k] + cell) << "\nplot data index " << maps[k] << " using 1:2:3 with image notitle\n";
    // which channels are beyond their tolerance: one colour per combination
    const std::size_t kinds = std::size_t(1) << m.checked.size();
    g << "set palette maxcolors " << kinds << "\nset palette defined (0 '#f2f2f2', 1 '#d62728'"
      << (kinds > 2 ? ", 2 '#1f77b4', 3 '#9467bd'" : "") << ")\nset cbrange [-0.5:" << double(kinds) - 0.5 << "]\nset cbtics (";
    for (std::size_t b = 0; b < kinds; ++b) {
        std::string label;
        for (std::size_t c = 0; c < m.checked.size(); ++c)
            if (b >> c & 1) label += (label.empty() ? "" : " and ") + m.checked[c];
        g << (b ? ", " : "") << plots::quoted(b ? label : "within") << " " << b;
    }
    g << ")\nset format cb '%g'\nset title " << plots::quoted("texels beyond their tolerance" + cell) << "\nplot data index " << above
      << " using 1:2:3 with image notitle" << circles << "\nunset multiplot\n";
    return plots::draw(name, data, {560 * cols, 500 * rows, 11}, g.str(), files);
}

// E_avg: one axis, the error a curve, the texels beyond their tolerance circled.
bool draw_curves(const lut_error_map& m, const std::string& name, const std::string& title, file_set& files) {
    plots::blocks data;
    data.precision = 9;
    plots::points all, above;
    for (std::size_t j = 0; j < m.ys.size(); ++j) {
        const double e = m.errors[0][j];
        if (std::isnan(e)) continue;
        all.emplace_back(m.ys[j], std::max(e, 1e-17));  // an error of 0 at the foot of the log scale
        if (m.above[j]) above.emplace_back(m.ys[j], std::max(e, 1e-17));
    }
    const std::string cell = m.block > 1 ? " (the largest of " + std::to_string(m.block) + " texels a point)" : "";
    std::string plot = "plot " + plots::curve(data.add(all), "linespoints lw 1.5 pt 7 ps 0.5", plots::palette[0], "|stored - exact|, E_{avg}" + cell);
    if (!above.empty()) plot += ", " + plots::curve(data.add(above), "points pt 6 ps 1.5", "#d62728", "beyond its tolerance");
    return plots::draw(name, data, {900, 520, 11},
                       "set title " + plots::quoted(title) + " noenhanced\nset grid\nset logscale y\nset format y '10^{%L}'\nset key top left\n" +
                           axis_settings("x", m.roughness_axis, m.ys) + plot + "\n",
                       files);
}

}  // namespace

bool plot_lut_check(const lut_error_map& m, const std::string& name, const std::string& title, file_set& files) {
    if (m.ys.empty() || m.errors.empty()) return false;
    return m.xs.size() == 1 && m.mu_axis == "mu" && m.errors.size() == 1 && m.names[0] == "E_avg" ? draw_curves(m, name, title, files)
                                                                                                   : draw_maps(m, name, title, files);
}

}  // namespace verify
