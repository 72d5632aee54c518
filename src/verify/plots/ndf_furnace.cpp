// ndf-furnace.svg: Smith G1 against view angle, a panel per NDF, a curve per alpha: the closed
// form on a fine angle grid as lines, the table's G1 from the masking equation as points.
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <normzoo/geometry.hpp>
#include <normzoo/registry.hpp>

#include <sstream>

namespace verify {

bool plot_ndf_furnace(const table_output& furnace, file_set& files) {
    plots::blocks data;
    std::vector<plots::panel> panels;
    for (const auto& [id, of_ndf] : plots::group_by(plots::all_rows(furnace.records), plots::by_text("ndf"))) {
        plots::panel p{id, "", {}};
        const auto alphas = plots::group_by(of_ndf, plots::by_number("alpha"));
        std::vector<std::size_t> shown;  // 0.1, 0.3, 0.5, 1, 2 where present, else five spread over the grid
        for (double a : {0.1, 0.3, 0.5, 1.0, 2.0})
            for (std::size_t i = 0; i < alphas.size(); ++i)
                if (alphas[i].first == a) shown.push_back(i);
        const std::size_t spread = std::min<std::size_t>(alphas.size(), 5);
        if (shown.empty())
            for (std::size_t i = 0; i < spread; ++i)
                shown.push_back(spread > 1 ? i * (alphas.size() - 1) / (spread - 1) : 0);
        for (std::size_t i : shown) {
            const double a = alphas[i].first;
            const auto quadrature = plots::xy(alphas[i].second, "theta_v_deg", "g1_quadrature");
            double last = 0;
            for (const auto& q : quadrature) last = std::max(last, q.first);
            plots::points closed;
            normzoo::with_ndf(id, [&](auto d) {  // angles crowd towards the last, where G1 falls fastest
                const normzoo::microfacet::ndf_params<double> roughness{a, a};
                for (int k = 0; k <= 200; ++k) {
                    const double s = 1 - k / 200.0;
                    const normzoo::degrees_angle<double> v(last * (1 - s * s));
                    const normzoo::vec3<double> w(v.sin_t, 0, v.cos_t);
                    closed.emplace_back(last * (1 - s * s), normzoo::microfacet::smith_g1<decltype(d)>(w, roughness));
                }
            });
            std::ostringstream t;
            t << "alpha = " << a;
            const char* colour = plots::palette[p.curves.size() / 2 % plots::palette_size];
            p.curves.push_back(plots::curve(data.add(closed), "lines lw 2", colour, t.str()));
            p.curves.push_back(plots::curve(data.add(quadrature), "points pt 7 ps 0.6", colour, ""));
        }
        panels.push_back(std::move(p));
    }
    return plots::draw_panels("ndf-furnace.svg",
                              "Smith G1 against view angle: closed form (lines), masking equation by quadrature (points)",
                              data,
                              "set xrange [0:90]\nset xtics 15\nset yrange [0:1.05]\nset key bottom left\n"
                              "set xlabel 'view angle of V (degrees)'\nset ylabel 'G1'\n",
                              panels, 2, 600, 460, files);
}

}  // namespace verify
