#include "args.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <sstream>

namespace verify {

std::vector<normzoo::decimal> parse_decimal_list(const std::string& option, const std::string& text,
                                                 const std::string& min, const std::string& max, bool max_open,
                                                 bool min_open) {
    std::vector<normzoo::decimal> out;
    auto fail = [&](const std::string& item, const std::string& why) {
        throw bad_input(option + ": bad value '" + item + "' in '" + text + "': " + why);
    };
    const normzoo::decimal lo(min), hi(max);
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item.empty()) fail(item, "empty item");
        if (item.find_first_of(" \t\n") != std::string::npos) fail(item, "contains white space");
        std::optional<normzoo::decimal> v;
        try {
            v.emplace(item);
        } catch (const std::invalid_argument&) {
            fail(item, "not a decimal number");
        }
        if (*v < lo || *v > hi || (max_open && *v == hi) || (min_open && *v == lo))
            fail(item, "must be in " + std::string(min_open ? "(" : "[") + min + ", " + max + (max_open ? ")" : "]"));
        const double d = v->to<double>();
        if (!std::isfinite(d)) fail(item, "out of the range of a double");
        if (!v->is_zero() && !std::isnormal(d)) fail(item, "too small to hold in a double (underflow)");
        out.push_back(std::move(*v));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

std::vector<std::string> parse_name_list(const std::string& option, const std::string& text,
                                         const std::vector<std::string>& known) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (std::find(known.begin(), known.end(), item) == known.end()) {
            std::string list;
            for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
            throw bad_input(option + ": unknown name '" + item + "' (known: " + list + ")");
        }
        if (std::find(out.begin(), out.end(), item) == out.end()) out.push_back(item);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

std::uint64_t parse_count(const std::string& option, const std::string& text, std::uint64_t min, std::uint64_t max) {
    auto fail = [&](const std::string& why) { throw bad_input(option + ": bad value '" + text + "': " + why); };
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        fail("not a whole number written in decimal digits");
    errno = 0;
    const unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
    if (errno == ERANGE) fail("too large");
    if (v < min || v > max) fail("must be in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    return v;
}

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> items;
    std::size_t from = 0;
    while (true) {
        const std::size_t at = text.find(sep, from);
        items.push_back(text.substr(from, at == std::string::npos ? std::string::npos : at - from));
        if (at == std::string::npos) return items;
        from = at + 1;
    }
}

}  // namespace verify
