// What every figure shares: the palette, data blocks, panels of curves, and running gnuplot
// (Debian gnuplot-nox) to write an SVG staged through the file_set like every other results file.
#pragma once
#include "../writers.hpp"

#include <algorithm>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace verify::plots {

// matplotlib's ten (tab10): the curves of a panel take them in turn.
inline constexpr const char* palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                          "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
inline constexpr int palette_size = sizeof palette / sizeof palette[0];

using points = std::vector<std::pair<double, double>>;
using selection = std::vector<const record*>;

selection all_rows(const std::vector<record>& records);
// (x, y) of each row, from two numeric fields.
points xy(const selection& rows, const char* x, const char* y);

inline auto by_text(const char* key) {
    return [key](const record& r) { return r.text(key); };
}
inline auto by_number(const char* key) {
    return [key](const record& r) { return r.number(key); };
}

// The rows grouped by a field, groups in order of appearance.
template <class Get>
auto group_by(const selection& rows, Get get) {
    std::vector<std::pair<decltype(get(*rows.front())), selection>> out;
    for (const auto* r : rows) {
        const auto k = get(*r);
        auto it = std::find_if(out.begin(), out.end(), [&](const auto& g) { return g.first == k; });
        if (it == out.end()) it = out.insert(out.end(), {k, {}});
        it->second.push_back(r);
    }
    return out;
}

// A gnuplot string literal: single quotes, a quote inside doubled (gnuplot's own escape), so that
// a title or path can neither end the string nor add a command.
std::string quoted(const std::string& text);

// Data blocks, for gnuplot's `index`, in the one file a script names `data`: rows of numbers, a
// block ended by two blank lines.
struct blocks {
    std::string text;
    int count = 0;
    int precision = 17;  // significant digits written

    void row(std::initializer_list<double> values);
    int end();                 // closes the block begun by row(); returns its index
    int add(const points& p);  // a block of (x, y) rows; returns its index
};

// One plot item over a data block, e.g. "data index 3 using 1:2 with lines lw 2 lc rgb '#1f77b4'
// title 'n = 16'". An empty colour leaves gnuplot's own; an empty title is notitle.
std::string curve(int block, const std::string& with, const std::string& colour, const std::string& title,
                  const std::string& columns = "1:2");

// The SVG canvas: size in pixels and the font's size in points.
struct canvas {
    int width, height, font;
};

// Writes the data, runs `script` (after the terminal, the output and `data = <the data file>`),
// and stages the SVG as `name`. Returns false, and says why on stderr, when gnuplot is missing or
// fails: the tables stand without their figure.
bool draw(const std::string& name, const blocks& data, const canvas& size, const std::string& script,
          file_set& files);

// One panel of a multiplot: its own settings, then its curves (plot items).
struct panel {
    std::string title, settings;
    std::vector<std::string> curves;
};

// The panels, `cols` across, each w by h at 11 points, after the settings they share (and a grid).
bool draw_panels(const std::string& name, const std::string& title, const blocks& data, const std::string& shared,
                 const std::vector<panel>& panels, int cols, int w, int h, file_set& files);

}  // namespace verify::plots
