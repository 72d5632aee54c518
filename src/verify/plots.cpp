#include "plots.hpp"

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace verify {

namespace {

double number(const normzoo::record& r, const std::string& key) {
    const auto* v = r.find(key);
    if (!v) return 0;
    if (std::holds_alternative<double>(*v)) return std::get<double>(*v);
    if (std::holds_alternative<std::string>(*v)) return std::strtod(std::get<std::string>(*v).c_str(), nullptr);
    return 0;
}

bool run_gnuplot(const std::string& script_path) {
    const std::string cmd = "gnuplot '" + script_path + "' 2>&1";
    return std::system(cmd.c_str()) == 0;
}

}  // namespace

bool plot_bounds(const table_output& bounds, file_set& files) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
        std::cerr << "verify: gnuplot not found: bounds.svg not drawn (apt-get install gnuplot-nox)\n";
        return false;
    }
    // One data block per row: n, norm/lower, upper/lower (n = 0 has no place on a log axis).
    std::map<std::string, std::ostringstream> blocks;
    for (const auto& r : bounds.records) {
        const double n = number(r, "n");
        if (!(n > 0)) continue;
        const double lower = number(r, "lower");
        auto& b = blocks[std::get<std::string>(*r.find("row"))];
        b.precision(17);
        b << n << " " << number(r, "norm") / lower << " " << number(r, "upper") / lower << "\n";
    }
    const auto data = files.temp_path("bounds.dat");
    const auto script = files.temp_path("bounds.gp");
    const auto svg = files.temp_path("bounds.svg");
    {
        std::ofstream d(data);
        for (const char* row : {"blinn-phong", "blinn-phong-modified"}) d << blocks[row].str() << "\n\n";
    }
    {
        std::ofstream g(script);
        g << "set terminal svg size 900,560 font 'sans,13' background rgb 'white'\n"
          << "set output '" << svg.string() << "'\n"
          << "set title 'Blinn-Phong normalizations over their lower bounds'\n"
          << "set logscale x\nset format x '10^{%L}'\nset xrange [1e-6:1e7]\nset yrange [0.98:2.05]\n"
          << "set xlabel 'exponent n'\nset ylabel 'normalization / lower bound'\nset key top right\nset grid\n"
          << "plot '" << data.string() << "' index 0 using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'blinn-phong: exact / ((n+2)/(8 pi))', \\\n"
          << "     '' index 0 using 1:3 with lines lw 1 dt 2 lc rgb '#1f77b4' title 'upper (n+4)/(8 pi) / lower', \\\n"
          << "     '' index 1 using 1:2 with lines lw 2 lc rgb '#d62728' title 'blinn-phong-modified: exact / ((n+6)/(8 pi))', \\\n"
          << "     '' index 1 using 1:3 with lines lw 1 dt 2 lc rgb '#d62728' title 'upper (n+8)/(8 pi) / lower', \\\n"
          << "     1 with lines lw 1 lc rgb 'black' title 'lower bound'\n";
    }
    const bool ok = run_gnuplot(script.string());
    std::error_code ignored;
    std::filesystem::remove(data, ignored);
    std::filesystem::remove(script, ignored);
    if (!ok) {
        std::filesystem::remove(svg, ignored);
        std::cerr << "verify: gnuplot failed: bounds.svg not drawn\n";
        return false;
    }
    files.adopt("bounds.svg", svg);
    return true;
}

}  // namespace verify
