#include "gnuplot.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace verify::plots {

namespace {

// A word for sh: single quotes, a quote inside written '\''.
std::string shell_quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

}  // namespace

selection all_rows(const std::vector<record>& records) {
    selection out;
    for (const auto& r : records) out.push_back(&r);
    return out;
}

points xy(const selection& rows, const char* x, const char* y) {
    points out;
    for (const auto* r : rows) out.emplace_back(r->number(x), r->number(y));
    return out;
}

std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

void blocks::row(std::initializer_list<double> values) {
    std::ostringstream b;
    b.precision(precision);
    const char* separator = "";
    for (double v : values) b << separator << v, separator = " ";
    text += b.str() + "\n";
}

int blocks::end() {
    text += "\n\n";
    return count++;
}

int blocks::add(const points& p) {
    for (const auto& [x, y] : p) row({x, y});
    return end();
}

std::string curve(int block, const std::string& with, const std::string& colour, const std::string& title,
                  const std::string& columns) {
    return "data index " + std::to_string(block) + " using " + columns + " with " + with +
           (colour.empty() ? "" : " lc rgb " + quoted(colour)) + " " +
           (title.empty() ? "notitle" : "title " + quoted(title));
}

bool draw(const std::string& name, const blocks& data, const canvas& size, const std::string& script,
          file_set& files) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
        std::cerr << "verify: gnuplot not found: " << name << " not drawn (apt-get install gnuplot-nox)\n";
        return false;
    }
    // Absolute paths begin with '/': gnuplot reads none of them as an option (-), inline data (-)
    // or a pipe from or to a command (<, |). Quoted, a quote in them cannot end the string; a line
    // break could, and a results folder has no need of one.
    const auto data_path = std::filesystem::absolute(files.temp_path(name + ".dat"));
    const auto script_path = std::filesystem::absolute(files.temp_path(name + ".gp"));
    const auto svg = std::filesystem::absolute(files.temp_path(name));
    if (svg.string().find_first_of("\n\r") != std::string::npos) {
        std::cerr << "verify: the output folder's path holds a line break: " << name << " not drawn\n";
        return false;
    }
    std::ofstream(data_path) << data.text;
    std::ofstream(script_path) << "set terminal svg size " << size.width << "," << size.height << " font 'sans,"
                               << size.font << "' background rgb 'white'\n"
                               << "set output " << quoted(svg.string()) << "\ndata = " << quoted(data_path.string())
                               << "\n" << script;
    const std::string cmd = "gnuplot " + shell_quoted(script_path.string()) + " 1>&2";  // stdout is for --json
    const bool ok = std::system(cmd.c_str()) == 0;
    std::error_code ignored;
    std::filesystem::remove(data_path, ignored);
    std::filesystem::remove(script_path, ignored);
    if (!ok) {
        std::filesystem::remove(svg, ignored);
        std::cerr << "verify: gnuplot failed: " << name << " not drawn\n";
        return false;
    }
    files.adopt(name, svg);
    return true;
}

bool draw_panels(const std::string& name, const std::string& title, const blocks& data, const std::string& shared,
                 const std::vector<panel>& panels, int cols, int w, int h, file_set& files) {
    if (panels.empty()) return false;
    cols = std::min(cols, static_cast<int>(panels.size()));
    const int rows = static_cast<int>((panels.size() + cols - 1) / cols);
    std::ostringstream g;
    g << "set multiplot layout " << rows << "," << cols << (title.empty() ? "" : " title " + quoted(title)) << "\n"
      << "set grid\n" << shared;
    for (const auto& p : panels) {
        g << p.settings << "set title " << quoted(p.title) << "\nplot ";
        for (std::size_t i = 0; i < p.curves.size(); ++i) g << (i ? ", " : "") << p.curves[i];
        g << (p.curves.empty() ? "1 notitle\n" : "\n");
    }
    g << "unset multiplot\n";
    return draw(name, data, {w * cols, h * rows, 11}, g.str(), files);
}

}  // namespace verify::plots
