// enclosures.svg: the enclosures table against n (log-log), a panel per zoo row: the enclosure's
// relative radius, the quadrature's error estimate and its true error as the enclosure certifies it.
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <limits>

namespace verify {

bool plot_enclosures(const table_output& enclosures, file_set& files) {
    // All three are relative already: enclosure_rel_radius is Arb's radius / |mid|, the estimate is
    // relative, and quadrature_error_certified is (|q - mid| + radius) / (|mid| - radius), taken
    // from q to 36 digits (norm_quadrature prints 34, whose rounding is of the same size).
    const std::pair<const char*, const char*> quantities[] = {
        {"enclosure_rel_radius", "enclosure: relative radius (Arb)"},
        {"quadrature_error_estimate", "quadrature: error estimate"},
        {"quadrature_error_certified", "quadrature: true error, certified"}};
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const auto& r : enclosures.records)
        if (r.number("n") > 0) lo = std::min(lo, r.number("n")), hi = std::max(hi, r.number("n"));
    plots::blocks data;
    std::vector<plots::panel> panels;
    for (const auto& [row, of_row] : plots::group_by(plots::all_rows(enclosures.records), plots::by_text("row"))) {
        plots::selection shown;  // n = 0 has no place on the log axis
        for (const auto* r : of_row)
            if (r->number("n") > 0) shown.push_back(r);
        const bool flat = shown.empty() && hi > 0;  // lambert: no exponent, its one record drawn across
        plots::panel p{flat ? row + " (no exponent: drawn flat)" : row, "", {}};
        for (const auto& [key, title] : quantities) {
            const double v = of_row.front()->number(key);
            p.curves.push_back(plots::curve(data.add(flat ? plots::points{{lo, v}, {hi, v}} : plots::xy(shown, "n", key)),
                                            flat ? "lines lw 1.5" : "linespoints lw 1.5 pt 7 ps 0.5",
                                            plots::palette[p.curves.size()], panels.empty() ? title : ""));
        }
        panels.push_back(std::move(p));
    }
    return plots::draw_panels("enclosures.svg",
                              "Relative error against n, a panel per zoo row (n = 0 left out: no place on the log axis)",
                              data,
                              "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
                              "set yrange [1e-50:1e-30]\n"
                              "set ytics 1e-50, 1e5\nset key center right font ',10'\nset xlabel 'exponent n'\n"
                              "set ylabel 'relative to |enclosure mid|'\n",
                              panels, 4, 340, 330, files);
}

}  // namespace verify
