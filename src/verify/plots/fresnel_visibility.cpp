// fresnel-visibility.svg: the seed's three F V graphs, minimalist against Schlick with Kelemen /
// Szirmay-Kalos, a panel per k_s, with the points where they cross.
#include "../plots.hpp"
#include "../tables/fresnel_visibility.hpp"
#include "gnuplot.hpp"

#include <sstream>

namespace verify {

bool plot_fresnel_visibility(const table_output& fv, file_set& files) {
    // Blocks: per k_s (L.H, minimalist, Schlick), then per k_s its crossings, from the summary's
    // closed form, as points.
    plots::blocks data;
    std::vector<double> ks;
    for (const auto& [k, rows] : plots::group_by(plots::all_rows(fv.records), plots::by_number("specular"))) {
        for (const auto* r : rows)
            data.row({r->number("l_dot_h"), r->number("fv_minimalist"), r->number("fv_schlick_ksk")});
        data.end();
        ks.push_back(k);
    }
    std::vector<plots::panel> panels;
    for (double k : ks) {
        for (double x : fresnel_visibility_crossings(k))
            data.row({x, normzoo::brdf::minimalist_cook_torrance::fresnel_visibility(k, x)});
        data.row({1.0, k / 4});
        std::ostringstream title;
        title << "k_s = " << k;
        const int block = static_cast<int>(panels.size());
        panels.push_back({title.str(),
                          "",
                          {plots::curve(block, "lines lw 2", plots::palette[3], "minimalist"),
                           plots::curve(block, "lines lw 2", plots::palette[0], "Schlick + Kelemen/Szirmay-Kalos", "1:3"),
                           plots::curve(data.end(), "points pt 7 ps 0.6", "black", "crossings")}});
    }
    return plots::draw_panels("fresnel-visibility.svg",
                              "F V: minimalist k_s/(4 (L.H)^3) against Schlick with Kelemen / Szirmay-Kalos", data,
                              "set logscale y\nset format y '10^{%L}'\nset xrange [0:1]\nset key top right\n"
                              "set xlabel 'L.H'\nset ylabel 'F V'\n",
                              panels, 1, 700, 300, files);
}

}  // namespace verify
