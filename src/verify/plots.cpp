#include "plots.hpp"
#include "tables/fresnel_visibility.hpp"
#include "tables/shader_precision.hpp"

#include <normzoo/geometry.hpp>
#include <normzoo/real.hpp>
#include <normzoo/registry.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace verify {

namespace {

double number(const normzoo::record& r, const std::string& key) {
    const auto* v = r.find(key);
    if (!v) return 0;
    if (std::holds_alternative<double>(*v)) return std::get<double>(*v);
    if (std::holds_alternative<std::int64_t>(*v)) return static_cast<double>(std::get<std::int64_t>(*v));
    if (std::holds_alternative<std::string>(*v)) return std::strtod(std::get<std::string>(*v).c_str(), nullptr);
    return 0;
}

std::string text(const normzoo::record& r, const std::string& key) {
    const auto* v = r.find(key);
    return v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v) : std::string();
}

// Writes the data, runs the script (which reads `data` and writes `svg`), and stages the SVG.
// The script is given the paths by the caller's lambda.
template <class Script>
bool draw(const std::string& name, const std::string& data_text, file_set& files, const Script& script_for) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
        std::cerr << "verify: gnuplot not found: " << name << " not drawn (apt-get install gnuplot-nox)\n";
        return false;
    }
    const auto data = files.temp_path(name + ".dat");
    const auto script = files.temp_path(name + ".gp");
    const auto svg = files.temp_path(name);
    std::ofstream(data) << data_text;
    std::ofstream(script) << script_for(data.string(), svg.string());
    const std::string cmd = "gnuplot '" + script.string() + "' 1>&2";  // stdout is for --json
    const bool ok = std::system(cmd.c_str()) == 0;
    std::error_code ignored;
    std::filesystem::remove(data, ignored);
    std::filesystem::remove(script, ignored);
    if (!ok) {
        std::filesystem::remove(svg, ignored);
        std::cerr << "verify: gnuplot failed: " << name << " not drawn\n";
        return false;
    }
    files.adopt(name, svg);
    return true;
}

// ---- Panels of curves over data blocks (the issue-8 plots) ----

const char* const palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                               "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

using selection = std::vector<const normzoo::record*>;
using points = std::vector<std::pair<double, double>>;

selection all_rows(const std::vector<normzoo::record>& records) {
    selection out;
    for (const auto& r : records) out.push_back(&r);
    return out;
}

auto by_text(const char* key) {
    return [key](const normzoo::record& r) { return text(r, key); };
}
auto by_number(const char* key) {
    return [key](const normzoo::record& r) { return number(r, key); };
}

// The rows grouped by a field, groups in order of appearance.
template <class Get>
auto group_by(const selection& rs, Get get) {
    std::vector<std::pair<decltype(get(*rs.front())), selection>> out;
    for (const auto* r : rs) {
        const auto k = get(*r);
        auto it = std::find_if(out.begin(), out.end(), [&](const auto& g) { return g.first == k; });
        if (it == out.end()) it = out.insert(out.end(), {k, {}});
        it->second.push_back(r);
    }
    return out;
}

points xy(const selection& rs, const char* x, const char* y) {
    points out;
    for (const auto* r : rs) out.emplace_back(number(*r, x), number(*r, y));
    return out;
}

// value - 1 of a value printed near 1 in 20 digits: parsed in long double, which keeps about 11
// digits of it at 1 + 5e-9 (a double would keep 8).
double minus_one(const normzoo::record& r, const std::string& key) {
    const auto* v = r.find(key);
    if (v && std::holds_alternative<std::string>(*v))
        return static_cast<double>(std::strtold(std::get<std::string>(*v).c_str(), nullptr) - 1);
    return number(r, key) - 1;
}

// Data blocks for gnuplot's `index`, in one file the script names `data`.
struct blocks {
    std::string text;
    int count = 0;
    int add(const points& p) {
        std::ostringstream b;
        b.precision(17);
        for (const auto& [x, y] : p) b << x << " " << y << "\n";
        text += b.str() + "\n\n";
        return count++;
    }
};

std::string curve(int block, const std::string& with, const char* colour, const std::string& title,
                  const std::string& columns = "1:2") {
    return "data index " + std::to_string(block) + " using " + columns + " with " + with + " lc rgb '" + colour + "' " +
           (title.empty() ? "notitle" : "title '" + title + "'");
}

// One panel of a multiplot: its own settings, then its curves (gnuplot plot items).
struct panel {
    std::string title, settings;
    std::vector<std::string> curves;
};

// The panels, `cols` across, each w by h, after the settings they share.
bool draw_panels(const std::string& name, const std::string& title, const blocks& data, const std::string& shared,
                 const std::vector<panel>& panels, int cols, int w, int h, file_set& files) {
    if (panels.empty()) return false;
    cols = std::min(cols, static_cast<int>(panels.size()));
    const int rows = static_cast<int>((panels.size() + cols - 1) / cols);
    return draw(name, data.text, files, [&](const std::string& d, const std::string& svg) {
        std::ostringstream g;
        g << "set terminal svg size " << w * cols << "," << h * rows << " font 'sans,11' background rgb 'white'\n"
          << "set output '" << svg << "'\ndata = '" << d << "'\n"
          << "set multiplot layout " << rows << "," << cols << (title.empty() ? "" : " title '" + title + "'") << "\n"
          << "set grid\n" << shared;
        for (const auto& p : panels) {
            g << p.settings << "set title '" << p.title << "'\nplot ";
            for (std::size_t i = 0; i < p.curves.size(); ++i) g << (i ? ", " : "") << p.curves[i];
            g << (p.curves.empty() ? "1 notitle\n" : "\n");
        }
        g << "unset multiplot\n";
        return g.str();
    });
}

}  // namespace

bool plot_bounds(const table_output& bounds, file_set& files) {
    // One data block per row: n, norm/lower, upper/lower (n = 0 has no place on a log axis).
    std::map<std::string, std::ostringstream> blocks;
    for (const auto& r : bounds.records) {
        const double n = number(r, "n");
        if (!(n > 0)) continue;
        const double lower = number(r, "lower");
        auto& b = blocks[text(r, "row")];
        b.precision(17);
        b << n << " " << number(r, "norm") / lower << " " << number(r, "upper") / lower << "\n";
    }
    std::string data;
    for (const char* row : {"blinn-phong", "blinn-phong-modified"}) data += blocks[row].str() + "\n\n";
    return draw("bounds.svg", data, files, [](const std::string& d, const std::string& svg) {
        std::ostringstream g;
        g << "set terminal svg size 900,560 font 'sans,13' background rgb 'white'\n"
          << "set output '" << svg << "'\n"
          << "set title 'Blinn-Phong normalizations over their lower bounds'\n"
          << "set logscale x\nset format x '10^{%L}'\nset xrange [1e-6:1e7]\nset yrange [0.98:2.05]\n"
          << "set xlabel 'exponent n'\nset ylabel 'normalization / lower bound'\nset key top right\nset grid\n"
          << "plot '" << d << "' index 0 using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'blinn-phong: exact / ((n+2)/(8 pi))', \\\n"
          << "     '' index 0 using 1:3 with lines lw 1 dt 2 lc rgb '#1f77b4' title 'upper (n+4)/(8 pi) / lower', \\\n"
          << "     '' index 1 using 1:2 with lines lw 2 lc rgb '#d62728' title 'blinn-phong-modified: exact / ((n+6)/(8 pi))', \\\n"
          << "     '' index 1 using 1:3 with lines lw 1 dt 2 lc rgb '#d62728' title 'upper (n+8)/(8 pi) / lower', \\\n"
          << "     1 with lines lw 1 lc rgb 'black' title 'lower bound'\n";
        return g.str();
    });
}

bool plot_albedo(const table_output& energy, file_set& files) {
    // Forms in order of appearance; per form the exponents to draw (up to four, spread out).
    std::vector<std::string> models;
    std::map<std::string, std::vector<double>> exponents;
    for (const auto& r : energy.records) {
        const std::string m = text(r, "model");
        if (exponents.find(m) == exponents.end()) models.push_back(m);
        auto& e = exponents[m];
        if (std::find(e.begin(), e.end(), number(r, "value")) == e.end()) e.push_back(number(r, "value"));
    }
    auto shown = [](const std::vector<double>& all) {
        std::vector<double> pick;
        for (double n : {1.0, 16.0, 256.0, 1e4})
            if (std::find(all.begin(), all.end(), n) != all.end()) pick.push_back(n);
        if (pick.empty())
            for (std::size_t i = 0; i < all.size() && i < 4; ++i) pick.push_back(all[i * (all.size() - 1) / 3]);
        return pick;
    };
    std::ostringstream data;
    data.precision(17);
    std::vector<std::vector<double>> curves;  // per model, the exponents drawn (data blocks in that order)
    for (const auto& m : models) {
        curves.push_back(shown(exponents[m]));
        for (double n : curves.back()) {
            for (const auto& r : energy.records)
                if (text(r, "model") == m && number(r, "value") == n)
                    data << number(r, "theta_deg") << " " << number(r, "albedo") << "\n";
            data << "\n\n";
        }
    }
    const int cols = models.size() < 3 ? static_cast<int>(models.size()) : 3;
    const int rows = static_cast<int>((models.size() + 2) / 3);
    return draw("energy-albedo.svg", data.str(), files, [&](const std::string& d, const std::string& svg) {
        std::ostringstream g;
        const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728"};
        g << "set terminal svg size " << 420 * cols << "," << 330 * rows << " font 'sans,11' background rgb 'white'\n"
          << "set output '" << svg << "'\n"
          << "set multiplot layout " << rows << "," << cols
          << " title 'Directional albedo against incident angle (1 = energy conserved exactly)'\n"
          << "set xrange [0:90]\nset yrange [0:1.6]\nset xtics 15\nset grid\nset key top left opaque\n"
          << "set xlabel 'incident angle (degrees)'\nset ylabel 'albedo'\n";
        int block = 0;
        for (std::size_t i = 0; i < models.size(); ++i) {
            g << "set title '" << models[i] << "'\nplot ";
            for (std::size_t j = 0; j < curves[i].size(); ++j, ++block)
                g << "'" << d << "' index " << block << " using 1:2 with lines lw 2 lc rgb '" << colours[j % 4]
                  << "' title 'n = " << curves[i][j] << "', ";
            g << "1 with lines lw 1 dt 2 lc rgb 'black' notitle\n";
        }
        g << "unset multiplot\n";
        return g.str();
    });
}

bool plot_fresnel_visibility(const table_output& fv, file_set& files) {
    std::vector<double> ks;
    std::ostringstream data;
    data.precision(17);
    for (const auto& r : fv.records) {
        const double k = number(r, "specular");
        if (ks.empty() || ks.back() != k) {
            if (!ks.empty()) data << "\n\n";
            ks.push_back(k);
        }
        data << number(r, "l_dot_h") << " " << number(r, "fv_minimalist") << " " << number(r, "fv_schlick_ksk") << "\n";
    }
    // The crossings (from the summary's closed form, recomputed here) as points, one block per k.
    for (double k : ks) {
        data << "\n\n";
        for (double x : normzoo::fresnel_visibility_crossings(k))
            data << x << " " << normzoo::brdf::minimalist_cook_torrance::fresnel_visibility(k, x) << "\n";
        data << 1.0 << " " << k / 4 << "\n";
    }
    return draw("fresnel-visibility.svg", data.str(), files, [&](const std::string& d, const std::string& svg) {
        std::ostringstream g;
        g << "set terminal svg size 700," << 300 * ks.size() << " font 'sans,11' background rgb 'white'\n"
          << "set output '" << svg << "'\n"
          << "set multiplot layout " << ks.size() << ",1 title 'F V: minimalist k_s/(4 (L.H)^3) against Schlick with "
             "Kelemen / Szirmay-Kalos'\n"
          << "set logscale y\nset format y '10^{%L}'\nset xrange [0:1]\nset grid\nset key top right\n"
          << "set xlabel 'L.H'\nset ylabel 'F V'\n";
        for (std::size_t i = 0; i < ks.size(); ++i)
            g << "set title 'k_s = " << ks[i] << "'\nplot '" << d << "' index " << i
              << " using 1:2 with lines lw 2 lc rgb '#d62728' title 'minimalist', '' index " << i
              << " using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'Schlick + Kelemen/Szirmay-Kalos', '' index "
              << ks.size() + i << " using 1:2 with points pt 7 ps 0.6 lc rgb 'black' title 'crossings'\n";
        g << "unset multiplot\n";
        return g.str();
    });
}

bool plot_limits(const std::vector<table_output>& outputs, file_set& files) {
    const table_output* irr = nullptr;
    const table_output* punctual = nullptr;
    for (const auto& t : outputs) {
        if (t.info.name == "irradiance") irr = &t;
        if (t.info.name == "punctual-limit") punctual = &t;
    }
    if (!irr || !punctual) return false;
    // Blocks: one per (light, tilt) with a resolved deviation, then one per form (its first pair).
    std::ostringstream data;
    data.precision(17);
    std::vector<std::string> titles_left, titles_right;
    auto add_block = [&](const std::vector<const normzoo::record*>& rows, const char* x_key, std::vector<std::string>& titles,
                         const std::string& title) {
        std::ostringstream b;
        b.precision(17);
        int points = 0;
        for (const auto* r : rows) {
            const double d = std::abs(number(*r, "deviation"));
            if (d > 1e3 * number(*r, "error_estimate") && d > 0) b << number(*r, x_key) << " " << d << "\n", ++points;
        }
        if (points < 2) return;
        data << b.str() << "\n\n";
        titles.push_back(title);
    };
    std::vector<std::string> keys;
    std::map<std::string, std::vector<const normzoo::record*>> groups;
    for (const auto& r : irr->records) {
        std::ostringstream k;
        k << text(r, "light") << " tilt " << number(r, "tilt_deg");
        if (!groups.count(k.str())) keys.push_back(k.str());
        groups[k.str()].push_back(&r);
    }
    for (const auto& k : keys) add_block(groups[k], "ratio", titles_left, k);
    const std::size_t left_blocks = titles_left.size();
    keys.clear();
    groups.clear();
    for (const auto& r : punctual->records) {
        if (number(r, "lc_theta_deg") != 45) continue;  // one pair per form: l_c at 45 deg, V near the mirror
        const std::string k = text(r, "model");
        if (!groups.count(k)) keys.push_back(k);
        groups[k].push_back(&r);
    }
    for (const auto& k : keys) add_block(groups[k], "epsilon", titles_right, k);
    return draw("irradiance-limit.svg", data.str(), files, [&](const std::string& d, const std::string& svg) {
        std::ostringstream g;
        g << "set terminal svg size 1200,520 font 'sans,11' background rgb 'white'\n"
          << "set output '" << svg << "'\n"
          << "set multiplot layout 1,2\nset logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
          << "set grid\nset key bottom right\n"
          << "set title 'Light of fixed intensity: |E r^2 / (I cos t_c) - 1| against r_0/r'\n"
          << "set xlabel 'r_0 / r'\nset ylabel 'deviation from the point light'\nplot ";
        for (std::size_t i = 0; i < left_blocks; ++i)
            g << "'" << d << "' index " << i << " using 1:2 with linespoints lw 2 title '" << titles_left[i] << "'"
              << (i + 1 < left_blocks ? ", " : "\n");
        if (left_blocks == 0) g << "1 notitle\n";
        g << "set title 'Tiny cone of half-angle e (l_c at 45 deg, V near the mirror direction, n = 32)'\n"
          << "set xlabel 'e (radians)'\nset ylabel '|cone / point light - 1|'\nset key bottom right font ',9'\nplot ";
        for (std::size_t i = 0; i < titles_right.size(); ++i)
            g << "'" << d << "' index " << left_blocks + i << " using 1:2 with linespoints lw 1.5 title '"
              << titles_right[i] << "'" << (i + 1 < titles_right.size() ? ", " : "\n");
        if (titles_right.empty()) g << "1 notitle\n";
        g << "unset multiplot\n";
        return g.str();
    });
}

bool plot_shader_precision(const table_output& precision, file_set& files) {
    // The table holds the summaries; the curves are the same audits' grids, recomputed (0.2 s).
    // Panels: 0 exponent formulas fp16, 1 fp32, 2 L.H formulas fp16, 3 fp32. Each curve is thinned
    // to the largest error in each run of `thin` grid points, and zeros (exact) are left out.
    const auto& fs = normzoo::shader::formulas();
    const normzoo::shader_precision_kind kinds[] = {normzoo::shader_precision_kind::fp16,
                                                    normzoo::shader_precision_kind::fp32};
    std::ostringstream data;
    data.precision(6);
    std::vector<std::string> titles[4];
    int block = 0;
    std::vector<int> blocks[4];
    for (int k = 0; k < 2; ++k)
        for (const auto& f : fs) {
            const bool by_n = f.dom == normzoo::shader::domain::exponent;
            if (!by_n && f.dom != normzoo::shader::domain::unit) continue;
            const auto a = normzoo::audit_shader_formula(f, kinds[k]);
            const std::size_t thin = by_n ? 4 : 16;
            for (std::size_t i = 0; i < a.curve.size(); i += thin) {
                std::pair<double, double> worst{0, 0};
                for (std::size_t j = i; j < std::min(a.curve.size(), i + thin); ++j)
                    if (a.curve[j].second > worst.second) worst = a.curve[j];
                if (worst.second > 0 && (!by_n || worst.first > 0)) data << worst.first << " " << worst.second << "\n";
            }
            data << "\n\n";
            const int panel = (by_n ? 0 : 2) + k;
            blocks[panel].push_back(block++);
            // The legend says where it breaks, from the table.
            std::string title = f.id;
            for (const auto& r : precision.records)
                if (text(r, "formula") == f.id && text(r, "precision") == normzoo::precision_name(kinds[k]) &&
                    !text(r, "breaks_because").empty()) {
                    std::ostringstream b;
                    b << " (" << text(r, "breaks_because") << " at " << number(r, "breaks_at_n") << ")";
                    title += b.str();
                }
            titles[panel].push_back(title);
        }
    return draw("shader-precision.svg", data.str(), files, [&](const std::string& d, const std::string& svg) {
        std::ostringstream g;
        const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                 "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
        const char* panel_title[] = {"fp16: normalizations and lobes against n", "fp32: normalizations and lobes against n",
                                     "fp16: Schlick forms against L.H", "fp32: Schlick forms against L.H"};
        g << "set terminal svg size 1300,1300 font 'sans,11' background rgb 'white'\n"
          << "set output '" << svg << "'\n"
          << "set multiplot layout 2,2 title 'Relative error of shader formulas against their exact value (until "
             "each breaks)'\n"
          << "set logscale y\nset format y '10^{%L}'\nset yrange [1e-9:2]\nset grid\nset key outside below font "
             "',9'\nset ylabel 'relative error'\n";
        for (int p = 0; p < 4; ++p) {
            if (p < 2) g << "set logscale x\nset format x '10^{%L}'\nset xrange [1e-3:1e9]\nset xlabel 'exponent n'\n";
            else g << "unset logscale x\nset format x '%g'\nset xrange [0:1]\nset xlabel 'x = L.H'\n";
            const double u = p % 2 == 0 ? 0x1p-11 : 0x1p-24;
            g << "set title '" << panel_title[p] << "'\nplot ";
            for (std::size_t j = 0; j < blocks[p].size(); ++j)
                g << "'" << d << "' index " << blocks[p][j] << " using 1:2 with lines lw 1.5 lc rgb '" << colours[j % 10]
                  << "' title '" << titles[p][j] << "', ";
            g << u << " with lines lw 1 dt 2 lc rgb 'black' title 'unit roundoff', 1 with lines lw 1 lc rgb 'black' "
                 "title 'all accuracy lost'\n";
        }
        g << "unset multiplot\n";
        return g.str();
    });
}

bool plot_error_audit(const table_output& histogram, file_set& files) {
    // One data block per family and number type: bin centre, count.
    std::vector<std::string> titles;
    std::ostringstream data;
    data.precision(17);
    std::string current;
    for (const auto& r : histogram.records) {
        const std::string title = text(r, "family") + " (" + text(r, "number_type") + ")";
        if (title != current) {
            if (!current.empty()) data << "\n\n";
            titles.push_back(title);
            current = title;
        }
        data << (number(r, "log10_low") + number(r, "log10_high")) / 2 << " " << number(r, "count") << "\n";
    }
    if (titles.empty()) return false;
    return draw("error-audit.svg", data.str(), files, [&](const std::string& d, const std::string& svg) {
        std::ostringstream g;
        g << "set terminal svg size 900,520 font 'sans,12' background rgb 'white'\n"
          << "set output '" << svg << "'\n"
          << "set title 'Error audit: estimate / true error (" << histogram.parameters << ")'\n"
          << "set xlabel 'log10(estimate / true error)   (< 0: the estimate fails; end bins hold what lies beyond)'\n"
          << "set ylabel 'cases'\nset logscale y\nset yrange [0.8:*]\nset xrange [-2:10]\nset xtics 1\nset grid\n"
          << "set key top right font ',10'\n"
          << "set object 1 rect from -2,0.8 to 0,graph 1 fc rgb '#f4cccc' fs solid 0.5 noborder behind\n"
          << "plot ";
        for (std::size_t i = 0; i < titles.size(); ++i)
            g << "'" << d << "' index " << i << " using 1:($2 > 0 ? $2 : 0.8) with histeps lw 2 title '" << titles[i] << "'"
              << (i + 1 < titles.size() ? ", " : "\n");
        return g.str();
    });
}

bool plot_models_energy(const table_output& sweep, file_set& files) {
    blocks data;
    std::vector<panel> panels;
    for (const auto& [model, of_model] : group_by(all_rows(sweep.records), by_text("model"))) {
        panel p{model, "", {}};
        double top = 0;
        for (const auto& [value, of_value] : group_by(of_model, by_number("value"))) {
            const auto curve_points = xy(of_value, "theta_deg", "albedo");
            for (const auto& pt : curve_points) top = std::max(top, pt.second);
            std::ostringstream t;
            const std::string parameter = text(*of_value.front(), "parameter");
            if (parameter == "none") t << "albedo";
            else t << parameter << " = " << value;
            p.curves.push_back(curve(data.add(curve_points), "linespoints lw 1.5 pt 7 ps 0.5",
                                     palette[p.curves.size() % 10], t.str(), "(u($1)):2"));
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
    for (const auto& r : sweep.records) last = std::max(last, number(r, "theta_deg"));
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
    return draw_panels("models-energy.svg",
                       "White-furnace albedo against incident angle (above the dashed 1: the form gains energy)",
                       data, stretched.str() + "set key below font ',9'\nset ylabel 'albedo'\n", panels, 3, 420, 380, files);
}

bool plot_ndf(const table_output& ndf, file_set& files) {
    blocks data;
    panel p{"Non-projected integral of D(h) less 1 against alpha: closed form (lines), quadrature (points)", "", {}};
    for (const auto& [id, of_ndf] : group_by(all_rows(ndf.records), by_text("ndf"))) {
        points quadrature, closed;
        double lo = std::numeric_limits<double>::infinity(), hi = 0;
        for (const auto* r : of_ndf) {
            const double a = number(*r, "alpha");
            quadrature.emplace_back(a, minus_one(*r, "non_projected_quadrature"));
            lo = std::min(lo, a), hi = std::max(hi, a);
        }
        normzoo::with_ndf(id, [&](auto row) {  // 50 digits: e^(1/a^2) overflows double below a = 0.04
            for (int k = 0; k <= 200; ++k) {
                const double a = lo * std::pow(hi / lo, k / 200.0);
                closed.emplace_back(a, static_cast<double>(decltype(row)::non_projected(normzoo::wide(a)) - 1));
            }
        });
        const char* colour = palette[p.curves.size() / 2 % 10];
        p.curves.push_back(curve(data.add(closed), "lines lw 2", colour, id + ": closed form"));
        p.curves.push_back(curve(data.add(quadrature), "points pt 7 ps 0.8", colour, id + ": quadrature"));
    }
    if (p.curves.empty()) return false;
    return draw_panels("ndf.svg", "", data,
                       "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset key top left\n"
                       "set xlabel 'roughness alpha'\nset ylabel 'integral of D(h) over the hemisphere - 1'\n",
                       {p}, 1, 900, 560, files);
}

bool plot_ndf_furnace(const table_output& furnace, file_set& files) {
    blocks data;
    std::vector<panel> panels;
    for (const auto& [id, of_ndf] : group_by(all_rows(furnace.records), by_text("ndf"))) {
        panel p{id, "", {}};
        const auto alphas = group_by(of_ndf, by_number("alpha"));
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
            const auto quadrature = xy(alphas[i].second, "theta_v_deg", "g1_quadrature");
            double last = 0;
            for (const auto& q : quadrature) last = std::max(last, q.first);
            points closed;
            normzoo::with_ndf(id, [&](auto row) {  // angles crowd towards the last, where G1 falls fastest
                for (int k = 0; k <= 200; ++k) {
                    const double s = 1 - k / 200.0;
                    const normzoo::degrees_angle<double> v(last * (1 - s * s));
                    closed.emplace_back(last * (1 - s * s), decltype(row)::g1(v.cos_t, v.sin_t, a));
                }
            });
            std::ostringstream t;
            t << "alpha = " << a;
            const char* colour = palette[p.curves.size() / 2 % 10];
            p.curves.push_back(curve(data.add(closed), "lines lw 2", colour, t.str()));
            p.curves.push_back(curve(data.add(quadrature), "points pt 7 ps 0.6", colour, ""));
        }
        panels.push_back(std::move(p));
    }
    return draw_panels("ndf-furnace.svg", "Smith G1 against view angle: closed form (lines), masking equation by "
                                          "quadrature (points)",
                       data, "set xrange [0:90]\nset xtics 15\nset yrange [0:1.05]\nset key bottom left\n"
                             "set xlabel 'view angle of V (degrees)'\nset ylabel 'G1'\n",
                       panels, 2, 600, 460, files);
}

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
        if (number(r, "n") > 0) lo = std::min(lo, number(r, "n")), hi = std::max(hi, number(r, "n"));
    blocks data;
    std::vector<panel> panels;
    for (const auto& [row, of_row] : group_by(all_rows(enclosures.records), by_text("row"))) {
        selection shown;  // n = 0 has no place on the log axis
        for (const auto* r : of_row)
            if (number(*r, "n") > 0) shown.push_back(r);
        const bool flat = shown.empty() && hi > 0;  // lambert: no exponent, its one record drawn across
        panel p{flat ? row + " (no exponent: drawn flat)" : row, "", {}};
        for (const auto& [key, title] : quantities) {
            const double v = number(*of_row.front(), key);
            p.curves.push_back(curve(data.add(flat ? points{{lo, v}, {hi, v}} : xy(shown, "n", key)),
                                     flat ? "lines lw 1.5" : "linespoints lw 1.5 pt 7 ps 0.5",
                                     palette[p.curves.size()], panels.empty() ? title : ""));
        }
        panels.push_back(std::move(p));
    }
    return draw_panels("enclosures.svg",
                       "Relative error against n, a panel per zoo row (n = 0 left out: no place on the log axis)",
                       data,
                       "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset yrange [1e-50:1e-30]\n"
                       "set ytics 1e-50, 1e5\nset key center right font ',10'\nset xlabel 'exponent n'\n"
                       "set ylabel 'relative to |enclosure mid|'\n",
                       panels, 4, 340, 330, files);
}

}  // namespace verify
