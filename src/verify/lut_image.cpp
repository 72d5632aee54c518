// The baked tables as C headers (lut_image.hpp), and the one entry by which `verify lut --check`
// reads an image or a source file's array (lut_formats/read.cpp).
#include "lut_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <stdexcept>

#include "lut_formats/read.hpp"
#include "lut_formats/texels.hpp"

namespace verify {
namespace {

bool is_c_identifier(const std::string& s) {
    static const std::set<std::string> keywords = {
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum", "extern",
        "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return", "short", "signed",
        "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void", "volatile", "while", "_Alignas",
        "_Alignof", "_Atomic", "_Bool", "_Complex", "_Generic", "_Imaginary", "_Noreturn", "_Static_assert", "_Thread_local"};
    const auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (s.empty() || !alpha(s[0]) || keywords.count(s)) return false;
    return std::all_of(s.begin(), s.end(), [&](char c) { return alpha(c) || (c >= '0' && c <= '9'); });
}

}  // namespace

std::string encode_c_header(const lut_image& im, const std::string& name, const std::string& comment) {
    check_image(im);
    if (!is_c_identifier(name)) throw std::invalid_argument("C header: \"" + name + "\" is not a C identifier");
    std::string s = "#pragma once\n";
    for (std::size_t b = 0; b < comment.size();) {
        const std::size_t e = std::min(comment.find('\n', b), comment.size());
        std::string line = comment.substr(b, e - b);
        line.erase(line.find_last_not_of(" \t") + 1);
        if (!line.empty() && line.back() == '\\') line += '.';  // a backslash would join the next line to the comment
        s += line.empty() ? "//\n" : "// " + line + "\n";
        b = e + 1;
    }
    s += "static const float " + name + "[" + std::to_string(im.height) + "][" + std::to_string(im.width) + "][" +
         std::to_string(im.channels) + "] = {\n";
    char buf[48];
    for (std::size_t j = 0; j < im.height; ++j) {
        s += "    {";
        for (std::size_t i = 0; i < im.width; ++i) {
            s += i ? ", {" : "{";
            for (std::size_t c = 0; c < im.channels; ++c) {
                // the float's own value to 9 digits reads back as that float
                const float v = float(im.at(j, i, c));
                if (!std::isfinite(v))
                    throw std::invalid_argument("C header: value " + std::to_string(im.at(j, i, c)) + " is not a finite float");
                std::snprintf(buf, sizeof buf, "%.9g", double(v));
                s += (c ? ", " : "") + std::string(buf);
                if (!std::strpbrk(buf, ".e")) s += ".";  // "1f" is no C literal; "1.f" is
                s += "f";
            }
            s += "}";
        }
        s += j + 1 < im.height ? "},\n" : "}\n";
    }
    return s + "};\n";
}

decoded_lut read_lut_image(const std::string& path) { return read_lut_file(path, {}); }

}  // namespace verify
