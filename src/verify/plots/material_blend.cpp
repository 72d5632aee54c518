// material-blend.svg: what compensating the mixed F0 loses against mixing the compensated results,
// over roughness, a curve per compensation and metallic; a panel per base colour, at mu = 1.
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <string>

namespace verify {

bool plot_material_blend(const table_output& blend, file_set& files) {
    plots::blocks data;
    std::vector<plots::panel> panels;
    for (const auto& [color, rows] : plots::group_by(plots::all_rows(blend.records), plots::by_number("base_color"))) {
        plots::panel p{"base colour " + detail::format_number(color) + ", mu = 1", "", {}};
        plots::selection at_normal;
        for (const auto* r : rows)
            if (r->number("mu") == 1) at_normal.push_back(r);
        auto curve_of = [](const record& r) { return r.text("compensation") + ", metallic " + detail::format_number(r.number("metallic")); };
        for (const auto& [name, curve] : plots::group_by(at_normal, curve_of)) {
            const bool kulla = curve.front()->text("compensation") == "kulla-conty";
            const char* colour = plots::palette[p.curves.size() % plots::palette_size];
            p.curves.push_back(plots::curve(data.add(plots::xy(curve, "roughness", "difference")),
                                            kulla ? "linespoints lw 2 pt 7 ps 0.7" : "linespoints lw 2 dt 2 pt 5 ps 0.7",
                                            colour, name));
        }
        panels.push_back(std::move(p));
    }
    if (panels.empty()) return false;
    return plots::draw_panels("material-blend.svg", "Compensating the mixed F0 minus mixing the compensated results",
                              data, "set key bottom left\nset xlabel 'roughness r (alpha = r^2)'\nset ylabel 'albedo difference'\n",
                              panels, 2, 1100, 520, files);
}

}  // namespace verify
