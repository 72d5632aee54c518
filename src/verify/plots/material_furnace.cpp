// material-furnace.svg: the albedo of the whole over roughness, a panel per furnace configuration
// and incidence, a curve per compensation (the specification's separable masking solid, the
// height-correlated form dashed); OpenPBR's configurations beside glTF's where they share a name,
// in panels of their own elsewhere.
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <algorithm>
#include <string>

namespace verify {

bool plot_material_furnace(const table_output& furnace, file_set& files) {
    plots::blocks data;
    std::vector<plots::panel> panels;
    for (double mu : {1.0, 0.125}) {
        for (const auto& [config, rows] : plots::group_by(plots::all_rows(furnace.records), plots::by_text("configuration"))) {
            plots::panel p{config + ", mu = " + detail::format_number(mu), "", {}};
            plots::selection at;
            double lo = 1e300, hi = -1e300;
            for (const auto* r : rows)
                if (r->number("mu") == mu) at.push_back(r), lo = std::min(lo, r->number("albedo")), hi = std::max(hi, r->number("albedo"));
            // a flat panel (a preserving configuration: 1 to rounding) gets a range of its own
            p.settings = hi - lo < 1e-6 ? "set yrange [0.99:1.01]\n" : "set yrange [*:*]\n";
            auto name = [](const record& r) { return r.text("material") + ", " + r.text("masking"); };
            for (const auto& [n, curve] : plots::group_by(at, name)) {
                const bool separable = curve.front()->text("masking") == "smith-separable";
                const char* colour = plots::palette[(p.curves.size() / 2) % plots::palette_size];
                p.curves.push_back(plots::curve(data.add(plots::xy(curve, "roughness", "albedo")),
                                                separable ? "linespoints lw 2 pt 7 ps 0.6" : "linespoints lw 2 dt 2 pt 5 ps 0.6",
                                                colour, n));
            }
            panels.push_back(std::move(p));
        }
    }
    if (panels.empty()) return false;
    return plots::draw_panels("material-furnace.svg", "The white furnace: albedo of the whole glTF and OpenPBR materials, V held", data,
                              "set key bottom left font ',8'\nset xlabel 'roughness'\nset ylabel 'albedo'\n",
                              panels, 3, 640, 420, files);
}

}  // namespace verify
