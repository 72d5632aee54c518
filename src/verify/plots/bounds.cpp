// bounds.svg: each Blinn-Phong normalization over its lower bound against n, with its upper bound.
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <map>

namespace verify {

bool plot_bounds(const table_output& bounds, file_set& files) {
    // Per row its (n, norm / lower, upper / lower); n = 0 has no place on a log axis.
    std::map<std::string, std::vector<const record*>> rows;
    for (const auto& r : bounds.records)
        if (r.number("n") > 0) rows[r.text("row")].push_back(&r);
    plots::blocks data;
    for (const char* row : {"blinn-phong", "blinn-phong-modified"}) {
        for (const auto* r : rows[row]) {
            const double lower = r->number("lower");
            data.row({r->number("n"), r->number("norm") / lower, r->number("upper") / lower});
        }
        data.end();
    }
    const auto* blue = plots::palette[0];
    const auto* red = plots::palette[3];
    const std::string script =
        "set title 'Blinn-Phong normalizations over their lower bounds'\n"
        "set logscale x\nset format x '10^{%L}'\nset xrange [1e-6:1e7]\nset yrange [0.98:2.05]\n"
        "set xlabel 'exponent n'\nset ylabel 'normalization / lower bound'\nset key top right\nset grid\nplot " +
        plots::curve(0, "lines lw 2", blue, "blinn-phong: exact / ((n+2)/(8 pi))") + ", " +
        plots::curve(0, "lines lw 1 dt 2", blue, "upper (n+4)/(8 pi) / lower", "1:3") + ", " +
        plots::curve(1, "lines lw 2", red, "blinn-phong-modified: exact / ((n+6)/(8 pi))") + ", " +
        plots::curve(1, "lines lw 1 dt 2", red, "upper (n+8)/(8 pi) / lower", "1:3") + ", " +
        "1 with lines lw 1 lc rgb 'black' title 'lower bound'\n";
    return plots::draw("bounds.svg", data, {900, 560, 13}, script, files);
}

}  // namespace verify
