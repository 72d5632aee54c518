#include "brdf_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <cctype>
#include <sstream>

#include "../args.hpp"
#include "../toml_text.hpp"

namespace verify {

namespace {

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
    throw bad_input(path + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what);
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> w;
    for (std::string s; in >> s;) w.push_back(s);
    return w;
}

double number(const std::string& path, int line, const std::string& name, const std::string& text) {
    std::size_t used = 0;
    double x = 0;
    try {
        x = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !std::isfinite(x)) fail(path, line, "parameter " + name + ": '" + text + "' is not a number");
    return x;
}

bool valid_identifier(const std::string& s) {
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

// One line of BRDF Explorer's parameters block.
shader_parameter parameter_line(const std::string& path, int line, const std::vector<std::string>& w) {
    shader_parameter p;
    p.line = line;
    const std::string& type = w[0];
    if (w.size() < 2) fail(path, line, "a parameter needs a name");
    p.name = w[1];
    if (!valid_identifier(p.name)) fail(path, line, "'" + p.name + "' is not a parameter name");
    auto count = [&](std::size_t n, const char* shape) {
        if (w.size() != n) fail(path, line, "parameter " + p.name + ": expected '" + shape + "'");
    };
    if (type == "float") {
        count(5, "float NAME MIN MAX DEFAULT");
        p.type = shader_parameter::kind::real;
        p.min = number(path, line, p.name, w[2]);
        p.max = number(path, line, p.name, w[3]);
        p.default_value = {number(path, line, p.name, w[4])};
        if (!(p.min <= p.max)) fail(path, line, "parameter " + p.name + ": its range " + w[2] + " .. " + w[3] + " is empty");
        if (!(p.default_value[0] >= p.min && p.default_value[0] <= p.max))
            fail(path, line, "parameter " + p.name + ": its default " + w[4] + " is outside its range " + w[2] + " .. " + w[3]);
    } else if (type == "bool") {
        count(3, "bool NAME DEFAULT");
        p.type = shader_parameter::kind::boolean;
        p.min = 0, p.max = 1;
        const double d = number(path, line, p.name, w[2]);
        if (d != 0 && d != 1) fail(path, line, "parameter " + p.name + ": a bool's default is 0 or 1, not " + w[2]);
        p.default_value = {d};
    } else if (type == "color") {
        count(5, "color NAME R G B");
        p.type = shader_parameter::kind::color;
        p.min = 0, p.max = HUGE_VAL;
        for (int c = 0; c < 3; ++c) {
            const double x = number(path, line, p.name, w[2 + c]);
            if (x < 0) fail(path, line, "parameter " + p.name + ": a color's channels are >= 0, not " + w[2 + c]);
            p.default_value.push_back(x);
        }
    } else {
        fail(path, line, "unknown parameter type '" + type + "' (float, bool or color)");
    }
    return p;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw bad_input(path + ": cannot be read");
    std::ostringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    if (text.find('\0') != std::string::npos) throw bad_input(path + ": not a text file");
    return text;
}

shader_source read_brdf_explorer(const std::string& path, const std::string& text) {
    shader_source s;
    s.path = path;
    std::istringstream in(text);
    enum { outside, parameters, shader } where = outside;
    bool saw_parameters = false, saw_shader = false, shader_ended = false;
    int line_no = 0;
    std::ostringstream code;
    for (std::string line; std::getline(in, line);) {
        ++line_no;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const auto w = words(line);
        if (!w.empty() && w[0].rfind("::", 0) == 0) {
            if (w.size() == 2 && w[0] == "::begin" && w[1] == "parameters" && where == outside && !saw_parameters)
                where = parameters, saw_parameters = true;
            else if (w.size() == 2 && w[0] == "::end" && w[1] == "parameters" && where == parameters)
                where = outside;
            else if (w.size() == 2 && w[0] == "::begin" && w[1] == "shader" && where == outside && !saw_shader)
                where = shader, saw_shader = true, s.first_line = line_no + 1;
            else if (w.size() == 2 && w[0] == "::end" && w[1] == "shader" && where == shader)
                where = outside, shader_ended = true;
            else
                fail(path, line_no, "unexpected '" + line + "' (the blocks are ::begin/::end parameters and shader)");
            continue;
        }
        if (where == parameters) {
            if (w.empty() || w[0][0] == '#') continue;
            auto p = parameter_line(path, line_no, w);
            for (const auto& q : s.parameters)
                if (q.name == p.name) fail(path, line_no, "parameter " + p.name + " is declared twice (line " + std::to_string(q.line) + ")");
            s.parameters.push_back(p);
        } else if (where == shader) {
            code << line << "\n";
        }
    }
    if (!saw_shader) fail(path, 0, "no '::begin shader' block");
    if (!shader_ended) fail(path, line_no, "the shader block has no '::end shader'");
    if (where == parameters) fail(path, line_no, "the parameters block has no '::end parameters'");
    s.code = code.str();
    return s;
}

// A plain shader file: a TOML header in // comments before the code, ending at the first empty
// comment line or the first line that is not a comment, e.g.
//   // [brdf]
//   // function = "MyBRDF"
//   // language = "hlsl"
//   // [parameters.roughness]
//   // type = "float"
//   // range = [0.01, 1]
//   // default = 0.5
shader_source read_plain(const std::string& path, const std::string& text) {
    shader_source s;
    s.path = path;
    std::istringstream in(text);
    std::ostringstream header, code;
    int line_no = 0, header_lines = 0;
    bool in_header = true;
    for (std::string line; std::getline(in, line);) {
        ++line_no;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        // the header: the leading // lines, up to the first empty one ("//" alone)
        if (in_header && line.rfind("//", 0) == 0 && line.find_first_not_of(" \t", 2) != std::string::npos) {
            header << line.substr(2) << "\n";
            ++header_lines;
            code << "\n";  // keeps the code's line numbers those of the file
            continue;
        }
        in_header = false;
        code << line << "\n";
    }
    if (header_lines == 0) fail(path, 1, "a plain shader file starts with its TOML header in // comments (docs/brdf-code.md#plain-files)");
    const toml::table t = parse_ascii_toml(header.str(), path, "a shader file's TOML header");
    const auto* brdf = t["brdf"].as_table();
    if (!brdf) fail(path, 1, "the TOML header has no [brdf] table");
    if (const auto* f = (*brdf)["function"].node()) {
        if (!f->is_string()) fail(path, 1, "[brdf] function = \"NAME\": the name of the BRDF function, a string");
        s.function = *f->value<std::string>();
    }  // else BRDF, as BRDF Explorer's files name it
    if (!valid_identifier(s.function)) fail(path, 1, "function '" + s.function + "' is not an identifier");
    const auto ends_with = [&](const char* e) { return path.size() > 5 && path.substr(path.size() - 5) == e; };
    const std::string lang = (*brdf)["language"].value_or(std::string(ends_with(".hlsl") ? "hlsl" : ends_with(".wgsl") ? "wgsl" : "glsl"));
    if (lang == "glsl") s.lang = shader_source::language::glsl;
    else if (lang == "hlsl") s.lang = shader_source::language::hlsl;
    else if (lang == "wgsl") s.lang = shader_source::language::wgsl;
    else fail(path, 1, "language '" + lang + "' is not glsl, hlsl or wgsl");
    if (ends_with(".wgsl") && lang != "wgsl") fail(path, 1, "language '" + lang + "' in a .wgsl file: a .wgsl file holds WGSL (docs/brdf-code.md#wgsl)");
    for (const auto& [key, node] : brdf->ref<toml::table>())
        if (key != "function" && key != "language") fail(path, 1, "[brdf] has no key '" + std::string(key.str()) + "'");
    if (const auto* params = t["parameters"].as_table()) {
        for (const auto& [key, node] : *params) {
            const auto* p = node.as_table();
            const int line = static_cast<int>(node.source().begin.line);
            if (!p) fail(path, line, "parameters." + std::string(key.str()) + " is not a table");
            std::vector<std::string> w{(*p)["type"].value_or(std::string("float")), std::string(key.str())};
            auto num = [&](const toml::node* n, const std::string& what) -> std::string {
                if (!n || !(n->is_integer() || n->is_floating_point())) fail(path, line, "parameter " + w[1] + ": " + what + " must be a number");
                std::ostringstream o;
                o.precision(17);
                o << n->value<double>().value();
                return o.str();
            };
            if (w[0] == "float") {
                const auto* range = (*p)["range"].as_array();
                if (!range || range->size() != 2) fail(path, line, "parameter " + w[1] + ": range = [MIN, MAX]");
                w.push_back(num(range->get(0), "range"));
                w.push_back(num(range->get(1), "range"));
                w.push_back(num((*p)["default"].node(), "default"));
            } else if (w[0] == "bool") {
                const auto d = (*p)["default"].value<bool>();
                if (!d) fail(path, line, "parameter " + w[1] + ": default = true or false");
                w.push_back(*d ? "1" : "0");
            } else if (w[0] == "color") {
                const auto* d = (*p)["default"].as_array();
                if (!d || d->size() != 3) fail(path, line, "parameter " + w[1] + ": default = [R, G, B]");
                for (std::size_t c = 0; c < 3; ++c) w.push_back(num(d->get(c), "default"));
            }
            s.parameters.push_back(parameter_line(path, line, w));
        }
    }
    // toml++ iterates a table by key; the parameters' order is the header's
    std::stable_sort(s.parameters.begin(), s.parameters.end(),
                     [](const shader_parameter& a, const shader_parameter& b) { return a.line < b.line; });
    s.code = code.str();
    s.first_line = 1;
    return s;
}

}  // namespace

shader_source read_shader_file(const std::string& path) { return parse_shader_text(path, slurp(path)); }

shader_source parse_shader_text(const std::string& path, const std::string& text) {
    if (text.find('\0') != std::string::npos) throw bad_input(path + ": not a text file");
    const bool explorer = path.size() > 5 && path.substr(path.size() - 5) == ".brdf";
    return explorer ? read_brdf_explorer(path, text) : read_plain(path, text);
}

std::string shader_source::place(int line) const {
    const long k = static_cast<long>(line) - first_line;
    if (k >= 0 && static_cast<std::size_t>(k) < origin.size())
        return origin[static_cast<std::size_t>(k)].file + ":" + std::to_string(origin[static_cast<std::size_t>(k)].line);
    return path + (origin.empty() && line > 0 ? ":" + std::to_string(line) : "");
}

}  // namespace verify
