// error-audit.svg: how many cases at each log10(estimate / true error), a curve per family and
// number type, the failing side (below 0) shaded.
#include "../plots.hpp"
#include "gnuplot.hpp"

namespace verify {

bool plot_error_audit(const table_output& histogram, file_set& files) {
    // One data block per family and number type: bin centre, count.
    const auto family_and_type = [](const record& r) {
        return r.text("family") + " (" + r.text("number_type") + ")";
    };
    plots::blocks data;
    std::string curves;
    for (const auto& [title, bins] : plots::group_by(plots::all_rows(histogram.records), family_and_type)) {
        for (const auto* r : bins) data.row({(r->number("log10_low") + r->number("log10_high")) / 2, r->number("count")});
        curves += (curves.empty() ? "" : ", ") +
                  plots::curve(data.end(), "histeps lw 2", "", title, "1:($2 > 0 ? $2 : 0.8)");
    }
    if (curves.empty()) return false;
    return plots::draw("error-audit.svg", data, {900, 520, 12},
                       "set title " + plots::quoted("Error audit: estimate / true error (" + histogram.parameters + ")") +
                           "\nset xlabel 'log10(estimate / true error)   (< 0: the estimate fails; end bins hold what "
                           "lies beyond)'\n"
                           "set ylabel 'cases'\nset logscale y\nset yrange [0.8:*]\nset xrange [-2:10]\nset xtics 1\n"
                           "set grid\nset key top right font ',10'\n"
                           "set object 1 rect from -2,0.8 to 0,graph 1 fc rgb '#f4cccc' fs solid 0.5 noborder behind\n"
                           "plot " + curves + "\n",
                       files);
}

}  // namespace verify
