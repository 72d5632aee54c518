// models-energy.svg: the modern forms' albedo against incident angle, a panel per form, a curve
// per parameter value; the y axis logarithmic where a form reaches 2 (Ward, Duer).
#include "../plots.hpp"
#include "gnuplot.hpp"

#include <sstream>

namespace verify {

bool plot_models_energy(const table_output& sweep, file_set& files) {
    plots::blocks data;
    std::vector<plots::panel> panels;
    for (const auto& [model, of_model] : plots::group_by(plots::all_rows(sweep.records), plots::by_text("model"))) {
        plots::panel p{model, "", {}};
        double top = 0;
        for (const auto& [value, of_value] : plots::group_by(of_model, plots::by_number("value"))) {
            const auto curve_points = plots::xy(of_value, "theta_deg", "albedo");
            for (const auto& pt : curve_points) top = std::max(top, pt.second);
            std::ostringstream t;
            const std::string parameter = of_value.front()->text("parameter");
            if (parameter == "none") t << "albedo";
            else t << parameter << " = " << value;
            p.curves.push_back(plots::curve(data.add(curve_points), "linespoints lw 1.5 pt 7 ps 0.5",
                                            plots::palette[p.curves.size() % plots::palette_size], t.str(),
                                            "(u($1)):2"));
        }
        std::ostringstream settings;  // log y where the albedo reaches 2, else linear from 0
        if (top > 2) settings << "set logscale y\nset format y '10^{%L}'\nset yrange [*:*]\n";
        else settings << "unset logscale y\nset format y '%g'\nset yrange [0:" << std::max(1.2, 1.1 * top) << "]\n";
        p.settings = settings.str();
        p.curves.push_back("1 with lines lw 1 dt 2 lc rgb 'black' notitle");
        panels.push_back(std::move(p));
    }
    // The sweep crowds its last angles into 85 to 89.9999 degrees, where Ward and Duer gain: the
    // axis is u(t) = t - 15 log10(1 - t/90), linear to about 60 degrees, and labelled in degrees.
    double last = 0;
    for (const auto& r : sweep.records) last = std::max(last, r.number("theta_deg"));
    std::ostringstream stretched;
    stretched.precision(10);
    stretched << "u(t) = t - 15 * log10(1 - t / 90.0)\nset xrange [0:u(" << last << ")]\nset xtics (";
    const char* separator = "";
    // Past 89.9 the labels drop the "89" they share (.99 is 89.99) and every other one is blank, so
    // they do not run together.
    for (const auto& [t, label] : std::vector<std::pair<double, const char*>>{
             {0, "0"}, {30, "30"}, {60, "60"}, {80, "80"}, {85, "85"}, {89, "89"}, {89.9, "89.9"}, {89.99, ".99"},
             {89.999, ""}, {89.9999, ".9999"}, {89.99999, ""}})
        if (t <= last) stretched << separator << "'" << label << "' u(" << t << ")", separator = ", ";
    stretched << ")\nset xlabel 'incident angle (degrees, scale stretched towards 90)'\n";
    return plots::draw_panels("models-energy.svg",
                              "White-furnace albedo against incident angle (above the dashed 1: the form gains energy)",
                              data, stretched.str() + "set key below font ',9'\nset ylabel 'albedo'\n", panels, 3, 420,
                              380, files);
}

}  // namespace verify
