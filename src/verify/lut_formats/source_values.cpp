// A source file's array: its elements read strictly, its shape from the request, its declaration
// or the file, and a base64 PNG string decoded (source_parts.hpp).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <string_view>

#include "../args.hpp"
#include "printed.hpp"
#include "source_parts.hpp"

namespace verify {
namespace {

constexpr std::size_t npos = std::string::npos;

// One element: its value, whether it was written in hex, whether it is an integer, and the
// decimal's digits as printed (printed.hpp).
struct element {
    double value;
    bool hex, integer;
    printed_digits digits;
    double rounding = 0;  // what the literal's type rounds it to, relative: f 2^-24, h (binary16) 2^-11
};

bool all_digits(std::string_view s, const char* set = "0123456789") {
    return !s.empty() && s.find_first_not_of(set) == npos;
}

element element_of(const std::string& path, const number_ref& n) {
    const auto bad = [&](const std::string& why) {
        return bad_input(path + ":" + std::to_string(n.line) + ": '" + n.written() + "' " + why);
    };
    const std::string s(n.text);
    const bool negative = n.sign == '-';
    if (s.size() > 1 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {  // C's and JavaScript's, WGSL's u suffix
        std::string digits = s.substr(2, s.find_last_not_of("uUlL") - 1);
        if (!all_digits(digits, "0123456789abcdefABCDEF")) throw bad("is not a hex integer");
        if (negative) throw bad("is a negative hex integer");
        digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
        if (digits.size() > 8) throw bad("does not fit in 32 bits");
        return {double(std::strtoull(digits.c_str(), nullptr, 16)), true, true, {}};
    }
    // suffixes: f, F (C, GLSL, WGSL), h (WGSL's f16), lf (GLSL's double), u (WGSL's unsigned)
    std::string body = s;
    double rounding = 0;
    if (body.size() > 2 && (body.compare(body.size() - 2, 2, "lf") == 0 || body.compare(body.size() - 2, 2, "LF") == 0))
        body.resize(body.size() - 2);
    else if (body.size() > 1 && std::strchr("fFhH", body.back()))
        rounding = std::strchr("fF", body.back()) ? 0x1p-24 : 0x1p-11, body.pop_back();
    else if (body.size() > 1 && std::strchr("uU", body.back()) && all_digits(body.substr(0, body.size() - 1))) body.pop_back();
    // digits [. digits] [e [+-] digits], a digit in the mantissa, at most 4 in the exponent
    const std::size_t e = body.find_first_of("eE");
    const std::string mantissa = body.substr(0, e), exponent = e == npos ? "" : body.substr(e + 1);
    const std::size_t dot = mantissa.find('.');
    const std::string whole = mantissa.substr(0, dot), fraction = dot == npos ? "" : mantissa.substr(dot + 1);
    const std::string exp_digits = !exponent.empty() && (exponent[0] == '+' || exponent[0] == '-') ? exponent.substr(1) : exponent;
    if ((whole.empty() && fraction.empty()) || (!whole.empty() && !all_digits(whole)) || (!fraction.empty() && !all_digits(fraction)) ||
        (e != npos && (!all_digits(exp_digits) || exp_digits.size() > 4)))
        throw bad("is not a number");
    if (dot == npos && e == npos && whole.size() > 1 && whole[0] == '0') throw bad("is octal in C: write it as a decimal");
    const double v = std::strtod(((negative ? "-" : "") + body).c_str(), nullptr);
    if (!std::isfinite(v)) throw bad("is not a finite number");
    return {v, false, dot == npos && e == npos, digits_of(body), rounding};
}

struct shape {
    std::size_t width = 0, height = 0, channels = 0;
    std::string from;
};

// The integer constants the file defines: #define NAME N, and NAME = N where the statement ends
// there; each name with every value it is given.
std::map<std::string, std::set<std::size_t>> integer_constants(const std::vector<source_token>& t) {
    std::map<std::string, std::set<std::size_t>> c;
    const auto integer = [](std::string_view s) { return all_digits(s) && s.size() <= 9; };
    for (std::size_t k = 0; k < t.size(); ++k) {
        if (t[k].what == source_token::kind::directive) {
            char name[128] = "", value[32] = "", rest[2] = "";
            if (std::sscanf(std::string(t[k].text).c_str(), " define %127s %31s %1s", name, value, rest) == 2 && integer(value))
                c[name].insert(std::stoul(value));
        } else if (k + 2 < t.size() && t[k].what == source_token::kind::name && t[k + 1].is("=") &&
                   t[k + 2].what == source_token::kind::number && integer(t[k + 2].text) &&
                   (k + 3 == t.size() || t[k + 3].is(";") || t[k + 3].is(",") || t[k + 3].line > t[k + 2].line)) {
            c[std::string(t[k].text)].insert(std::stoul(std::string(t[k + 2].text)));
        }
    }
    return c;
}

// The shape: the request's, the declaration's [H][W][C] (both must fit the values: bad_input),
// else a call handing the array on with its size, else the file's one size constant (used where
// they fit); channels = values / (W H), 1 to 4.
shape shape_of(const std::string& where, const std::vector<source_token>& t, const found_array& a, const array_request& r,
               std::size_t n) {
    const auto fits = [&](std::size_t w, std::size_t h) {
        return w >= 1 && h >= 1 && w <= max_side && h <= max_side && n % (w * h) == 0 && n / (w * h) >= 1 && n / (w * h) <= 4;
    };
    const auto strict = [&](std::size_t w, std::size_t h, const std::string& from) {
        if (!fits(w, h))
            throw bad_input(where + "'" + a.name + "' holds " + std::to_string(n) + " values, not a " + std::to_string(w) + " x " +
                            std::to_string(h) + " table of 1 to 4 channels (" + from + ")");
        return shape{w, h, n / (w * h), from};
    };
    if (r.width || r.height) return strict(r.width, r.height, "size=" + std::to_string(r.width) + "x" + std::to_string(r.height) + ", given");
    const auto constants = integer_constants(t);
    const auto value = [&](std::string_view s) -> std::size_t {
        if (all_digits(s) && s.size() <= 9) return std::stoul(std::string(s));
        const auto it = constants.find(std::string(s));
        return it != constants.end() && it->second.size() == 1 ? *it->second.begin() : 0;
    };
    if (a.dims.size() == 3 && value(a.dims[0]) && value(a.dims[1]) && value(a.dims[2])) {
        const std::size_t h = value(a.dims[0]), w = value(a.dims[1]), c = value(a.dims[2]);
        const std::string from = "declared [" + a.dims[0] + "][" + a.dims[1] + "][" + a.dims[2] + "]";
        if (c > 4 || n != w * h * c) throw bad_input(where + "'" + a.name + "' holds " + std::to_string(n) + " values; it is " + from);
        return strict(w, h, from);
    }
    for (std::size_t p = 1; p + 4 < t.size(); ++p)  // DataTexture(DATA, 16, 16, ...)
        if (t[p].what == source_token::kind::name && t[p].text == a.name && t[p - 1].is("(") && t[p + 1].is(",") &&
            all_digits(t[p + 2].text) && t[p + 3].is(",") && all_digits(t[p + 4].text) && t[p + 2].text.size() <= 9 &&
            t[p + 4].text.size() <= 9 && fits(value(t[p + 2].text), value(t[p + 4].text)))
            return {value(t[p + 2].text), value(t[p + 4].text), n / (value(t[p + 2].text) * value(t[p + 4].text)),
                    "line " + std::to_string(t[p].line) + " hands '" + a.name + "' on with " + std::string(t[p + 2].text) + ", " +
                        std::string(t[p + 4].text)};
    std::set<std::size_t> sizes;
    std::string named;
    for (const auto& [name, values] : constants) {
        std::string lower = name;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
        if (lower.find("size") == npos && lower.find("resolution") == npos) continue;
        sizes.insert(values.begin(), values.end());
        named = name + " = " + std::to_string(*values.begin());
    }
    if (sizes.size() == 1 && fits(*sizes.begin(), *sizes.begin())) return {*sizes.begin(), *sizes.begin(), n / (*sizes.begin() * *sizes.begin()), named};
    return {};
}

int base64_digit(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : c == '/' ? 63 : -1;
}

}  // namespace

std::optional<std::string> base64_png(const std::string& text) {
    std::string s = text;
    if (s.rfind("data:", 0) == 0) {  // data:[<mediatype>];base64,<data>
        const std::size_t comma = s.find(',');
        if (comma == npos || comma < 12 || s.compare(comma - 7, 7, ";base64") != 0) return std::nullopt;
        s.erase(0, comma + 1);
    }
    if (s.empty() || s.size() % 4 != 0) return std::nullopt;
    const std::size_t pad = s.size() - s.find_last_not_of('=') - 1;
    if (pad > 2) return std::nullopt;
    std::string out;
    out.reserve(s.size() / 4 * 3);
    for (std::size_t k = 0; k < s.size(); k += 4) {
        std::uint32_t quad = 0;
        for (std::size_t q = 0; q < 4; ++q) {
            const bool padding = k + q >= s.size() - pad;
            const int v = padding ? 0 : base64_digit(s[k + q]);
            if (v < 0) return std::nullopt;
            quad = quad << 6 | std::uint32_t(v);
        }
        out += char(quad >> 16 & 0xff);
        if (k + 4 < s.size() || pad < 2) out += char(quad >> 8 & 0xff);
        if (k + 4 < s.size() || pad < 1) out += char(quad & 0xff);
    }
    if (out.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return std::nullopt;
    return out;
}

decoded_lut array_values(const std::string& path, const std::vector<source_token>& t, const found_array& a,
                         const array_request& request) {
    const std::string where = path + ":" + std::to_string(a.line) + ": ";
    const std::size_t n = a.numbers.size();
    if (n > max_side * max_side * 4)
        throw bad_input(where + "'" + a.name + "' holds " + std::to_string(n) + " values, more than a table of 4096 x 4096 x 4");
    std::vector<element> el;
    el.reserve(n);
    for (const number_ref& number : a.numbers) el.push_back(element_of(path, number));
    const auto hex = std::find_if(el.begin(), el.end(), [](const element& e) { return e.hex; });
    if (hex != el.end())
        for (std::size_t k = 0; k < n; ++k)
            if (!el[k].integer || el[k].value < 0 || el[k].value > 4294967295.0)
                throw bad_input(path + ":" + std::to_string(a.numbers[k].line) + ": '" + a.numbers[k].written() +
                                "' in an array of hex integers ('" + a.numbers[std::size_t(hex - el.begin())].written() +
                                "'): a table's array is all decimals or all integers of 32 bits");
    const shape s = shape_of(where, t, a, request, n);
    decoded_lut d;
    d.image.width = s.from.empty() ? n : s.width, d.image.height = s.from.empty() ? 1 : s.height;
    d.image.channels = s.from.empty() ? 1 : s.channels;
    d.shaped = !s.from.empty();
    d.shape_from = s.from, d.array_name = a.name, d.element_type = a.element_type;
    for (const element& e : el) d.image.data.push_back(e.value);
    if (hex != el.end()) {
        d.format = "array-hex", d.encoding = value_encoding::hex_integer;
        return d;  // exact integers, for interpret_hex
    }
    d.format = "array-decimal", d.encoding = value_encoding::decimal_text;
    // each channel a column: its finest value shows how the column was printed (printed.hpp)
    const std::size_t c = d.image.channels;
    std::vector<printed_digits> finest(c, printed_digits{std::numeric_limits<long>::min() / 2, 0});
    for (std::size_t k = 0; k < n; ++k) {
        const printed_digits& p = el[k].digits;
        finest[k % c].decimals = std::max(finest[k % c].decimals, p.decimals);
        finest[k % c].significant = std::max(finest[k % c].significant, p.significant);
    }
    // a float or half literal, or an array of them, is the value rounded to that type
    static const char* const floats[] = {"float", "f32", "Float32Array", "GLfloat", "vec2", "vec3", "vec4"};
    static const char* const halves[] = {"f16", "half", "vec2<f16>", "vec3<f16>", "vec4<f16>"};
    const auto named = [&](const char* const* list, std::size_t count) { return std::find(list, list + count, a.element_type) != list + count; };
    const double typed = named(halves, 5) ? 0x1p-11 : named(floats, 7) ? 0x1p-24 : 0;
    for (std::size_t k = 0; k < n; ++k)
        d.precision.push_back(std::max(printed_precision(el[k].value, finest[k % c]), std::max(typed, el[k].rounding) * std::abs(el[k].value)));
    return d;
}

}  // namespace verify
