// shader-precision.svg: relative error of the shader formulas in fp16 and fp32 until each breaks,
// drawn from the audits the table was made of (their curves over the whole grid).
#include "../plots.hpp"
#include "../tables/shader_precision.hpp"
#include "gnuplot.hpp"

#include <sstream>

namespace verify {

bool plot_shader_precision(const std::vector<shader_precision_audit>& audits, file_set& files) {
    // Panels: 0 exponent formulas fp16, 1 fp32, 2 L.H formulas fp16, 3 fp32. Each curve is thinned
    // to the largest error in each run of `thin` grid points, and zeros (exact) are left out.
    plots::blocks data;
    data.precision = 6;
    std::vector<plots::panel> panels{{"fp16: normalizations and lobes against n", "", {}},
                                     {"fp32: normalizations and lobes against n", "", {}},
                                     {"fp16: Schlick forms against L.H", "", {}},
                                     {"fp32: Schlick forms against L.H", "", {}}};
    for (const auto kind : {shader_precision_kind::fp16, shader_precision_kind::fp32})
        for (const auto& [f, precision, a] : audits) {
            const bool by_n = f->dom == normzoo::shader::domain::exponent;
            if (precision != kind || (!by_n && f->dom != normzoo::shader::domain::unit)) continue;
            const std::size_t thin = by_n ? 4 : 16;
            for (std::size_t i = 0; i < a.curve.size(); i += thin) {
                std::pair<double, double> worst{0, 0};
                for (std::size_t j = i; j < std::min(a.curve.size(), i + thin); ++j)
                    if (a.curve[j].second > worst.second) worst = a.curve[j];
                if (worst.second > 0 && (!by_n || worst.first > 0)) data.row({worst.first, worst.second});
            }
            // The legend says where it breaks.
            std::ostringstream title;
            title << f->id;
            if (a.breaks_at) title << " (" << a.breaks_because << " at " << *a.breaks_at << ")";
            auto& curves = panels[(by_n ? 0 : 2) + (kind == shader_precision_kind::fp16 ? 0 : 1)].curves;
            curves.push_back(plots::curve(data.end(), "lines lw 1.5", plots::palette[curves.size() % plots::palette_size],
                                          title.str()));
        }
    for (std::size_t p = 0; p < panels.size(); ++p) {
        panels[p].settings = p < 2
                                 ? "set logscale x\nset format x '10^{%L}'\nset xrange [1e-3:1e9]\nset xlabel 'exponent n'\n"
                                 : "unset logscale x\nset format x '%g'\nset xrange [0:1]\nset xlabel 'x = L.H'\n";
        std::ostringstream roundoff;  // dashed at the unit roundoff, solid at 1
        roundoff << unit_roundoff(p % 2 == 0 ? shader_precision_kind::fp16
                                                      : shader_precision_kind::fp32)
                 << " with lines lw 1 dt 2 lc rgb 'black' title 'unit roundoff'";
        panels[p].curves.push_back(roundoff.str());
        panels[p].curves.push_back("1 with lines lw 1 lc rgb 'black' title 'all accuracy lost'");
    }
    return plots::draw_panels("shader-precision.svg",
                              "Relative error of shader formulas against their exact value (until each breaks)", data,
                              "set logscale y\nset format y '10^{%L}'\nset yrange [1e-9:2]\nset key outside below font "
                              "',9'\nset ylabel 'relative error'\n",
                              panels, 2, 650, 650, files);
}

}  // namespace verify
