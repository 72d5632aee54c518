// energy-albedo.svg: directional albedo against incident angle, a panel per form, a curve per
// exponent (up to four of the table's).
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <sstream>

namespace verify {

namespace {

// 1, 16, 256 and 1e4 where the grid has them, else four spread over it.
std::vector<double> shown_exponents(const std::vector<double>& all) {
    std::vector<double> pick;
    for (double n : {1.0, 16.0, 256.0, 1e4})
        if (std::find(all.begin(), all.end(), n) != all.end()) pick.push_back(n);
    if (pick.empty())
        for (std::size_t i = 0; i < all.size() && i < 4; ++i) pick.push_back(all[i * (all.size() - 1) / 3]);
    return pick;
}

}  // namespace

bool plot_albedo(const table_output& energy, file_set& files) {
    plots::blocks data;
    std::vector<plots::panel> panels;
    for (const auto& [model, of_model] : plots::group_by(plots::all_rows(energy.records), plots::by_text("model"))) {
        plots::panel p{model, "", {}};
        const auto by_n = plots::group_by(of_model, plots::by_number("value"));
        std::vector<double> exponents;
        for (const auto& g : by_n) exponents.push_back(g.first);
        for (double n : shown_exponents(exponents)) {
            const auto& rows =
                std::find_if(by_n.begin(), by_n.end(), [&](const auto& g) { return g.first == n; })->second;
            std::ostringstream title;
            title << "n = " << n;
            p.curves.push_back(plots::curve(data.add(plots::xy(rows, "theta_deg", "albedo")), "lines lw 2",
                                            plots::palette[p.curves.size() % 4], title.str()));
        }
        p.curves.push_back("1 with lines lw 1 dt 2 lc rgb 'black' notitle");
        panels.push_back(std::move(p));
    }
    return plots::draw_panels("energy-albedo.svg",
                              "Directional albedo against incident angle (1 = energy conserved exactly)", data,
                              "set xrange [0:90]\nset yrange [0:1.6]\nset xtics 15\nset key top left opaque\n"
                              "set xlabel 'incident angle (degrees)'\nset ylabel 'albedo'\n",
                              panels, 3, 420, 330, files);
}

}  // namespace verify
