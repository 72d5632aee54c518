#include "scene_keys.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace verify::scene_keys {

namespace {

// The lines of the scene's text while a written_numbers lives; else none.
thread_local const std::vector<std::string>* scene_lines = nullptr;

}  // namespace

written_numbers::written_numbers(const std::string& toml_text) {
    std::istringstream text(toml_text);
    for (std::string line; std::getline(text, line);) lines_.push_back(line);
    scene_lines = &lines_;
}

written_numbers::~written_numbers() { scene_lines = nullptr; }

void only_keys(const toml::table& t, const place& p, const std::set<std::string>& allowed) {
    for (const auto& [k, v] : t) {
        const std::string key(k.str());
        if (!allowed.count(key)) {
            std::string list;
            for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
            p.at(key, &v).fail("unknown key (allowed: " + list + ")");
        }
    }
}

double number(const toml::node& n, const place& p) {
    if (auto v = n.value<double>()) {
        if (!std::isfinite(*v)) p.fail("must be a finite number");
        return *v;
    }
    p.fail("must be a number");
}

normzoo::decimal exact_number(const toml::node& n, const place& p) {
    const double value = number(n, p);
    const auto& r = n.source();
    if (scene_lines && r.begin.line == r.end.line && r.begin.line >= 1 && r.begin.line <= scene_lines->size()) {
        const std::string& line = (*scene_lines)[r.begin.line - 1];
        const std::size_t from = r.begin.column - 1, to = std::min<std::size_t>(r.end.column - 1, line.size());
        if (from < to) {
            std::string written = line.substr(from, to - from);
            written.erase(std::remove(written.begin(), written.end(), '_'), written.end());  // 1_000
            try {
                normzoo::decimal d(written);
                // toml++ reads 1e-400 as 0: refused as the command line refuses it (a decimal that is not 0 as a 0)
                if (!d.is_zero() && !std::isnormal(value)) p.fail("'" + written + "' is too small to hold in a double (underflow)");
                if (d.to<double>() == value) return d;
            } catch (const std::invalid_argument&) {
                // hexadecimal, octal or binary integers: exact as read
            }
        }
    }
    return normzoo::decimal::exactly(value);
}

std::string text(const toml::node& n, const place& p) {
    if (auto v = n.value<std::string>()) return *v;
    p.fail("must be a string");
}

std::vector<std::string> string_list(const toml::node& n, const place& p) {
    const auto* a = n.as_array();
    if (!a) p.fail("must be an array of strings");
    std::vector<std::string> out;
    for (const auto& e : *a) out.push_back(text(e, p));
    return out;
}

// A name goes into every table (Markdown, CSV, JSON, JUnit XML): one line of printable text.
std::string name_text(const toml::node& n, const place& p) {
    std::string s = text(n, p);
    if (s.empty()) p.fail("must not be empty");
    for (unsigned char c : s)
        if (c < 0x20 || c == 0x7f) p.fail("must not hold control characters (a tab, a new line, ...)");
    return s;
}

// [a, b] with a <= b, both finite, as the decimals written.
std::pair<normzoo::decimal, normzoo::decimal> exact_range(const toml::node& n, const place& p) {
    const auto* a = n.as_array();
    if (!a) p.fail("must be a range [min, max]");
    if (a->size() != 2) p.fail(a->empty() ? "the range is empty" : "a range has two numbers, [min, max]");
    auto lo = exact_number(*a->get(0), p), hi = exact_number(*a->get(1), p);
    if (lo > hi) p.fail("the range [" + lo.text() + ", " + hi.text() + "] is reversed");
    return {lo, hi};
}

}  // namespace verify::scene_keys
