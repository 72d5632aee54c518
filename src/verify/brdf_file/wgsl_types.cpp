#include "wgsl_types.hpp"

#include <charconv>
#include <cmath>
#include <limits>

namespace verify::wgsl {

type scalar_type(scalar s) {
    type t;
    t.k = type::kind::scalar;
    t.s = s;
    return t;
}

type vector_type(int n, scalar s) {
    type t = scalar_type(s);
    t.k = type::kind::vector;
    t.n = n;
    return t;
}

type matrix_type(int columns, int rows, scalar s) {
    type t = scalar_type(s);
    t.k = type::kind::matrix;
    t.n = columns;
    t.rows = rows;
    return t;
}

bool is_float(scalar s) { return s == scalar::abstract_float || s == scalar::f32 || s == scalar::f16; }
bool is_integer(scalar s) { return s == scalar::abstract_int || s == scalar::i32 || s == scalar::u32; }

bool supported_type(const type& t) {
    return (t.k == type::kind::scalar && !is_abstract(t) && t.s != scalar::f16) || t.k == type::kind::structure ||
           ((t.k == type::kind::vector || t.k == type::kind::matrix) && t.s == scalar::f32);
}

bool is_abstract(const type& t) {
    return (t.k == type::kind::scalar || t.k == type::kind::vector || t.k == type::kind::matrix) &&
           (t.s == scalar::abstract_int || t.s == scalar::abstract_float);
}

bool numeric(const type& t) {
    return (t.k == type::kind::scalar || t.k == type::kind::vector || t.k == type::kind::matrix) && t.s != scalar::boolean;
}

int components(const type& t) {
    if (t.k == type::kind::scalar) return 1;
    if (t.k == type::kind::vector) return t.n;
    if (t.k == type::kind::matrix) return t.n * t.rows;
    return 0;
}

type with_element(const type& t, scalar s) {
    type o = t;
    o.s = s;
    return o;
}

type concretized(const type& t) {
    if (!is_abstract(t)) return t;
    return with_element(t, t.s == scalar::abstract_int ? scalar::i32 : scalar::f32);
}

bool converts(const type& from, const type& to) {
    if (from == to) return true;
    if (!is_abstract(from) || from.k != to.k || from.n != to.n || from.rows != to.rows) return false;
    if (from.s == scalar::abstract_float) return is_float(to.s);
    return to.s != scalar::boolean;  // AbstractInt: to any number type
}

bool join(const type& a, const type& b, type& out) {
    if (converts(a, b)) return out = b, true;
    if (converts(b, a)) return out = a, true;
    return false;
}

std::string type_name(const type& t) {
    static const char* const names[] = {"AbstractInt", "AbstractFloat", "f32", "f16", "i32", "u32", "bool"};
    const std::string e = names[static_cast<int>(t.s)];
    switch (t.k) {
        case type::kind::scalar: return e;
        case type::kind::vector: return "vec" + std::to_string(t.n) + "<" + e + ">";
        case type::kind::matrix: return "mat" + std::to_string(t.n) + "x" + std::to_string(t.rows) + "<" + e + ">";
        case type::kind::structure:
        case type::kind::unsupported: return t.spelled;
        case type::kind::none: break;
    }
    return "no value";
}

std::string a_type(const type& t) {
    const std::string n = type_name(t);
    return (std::string("AEIOaeiof").find(n[0]) != std::string::npos ? "an " : "a ") + n;
}

std::string why_not(const type& from, const type& to) {
    if (from.s == scalar::abstract_float && is_integer(to.s))
        return " (a float literal or constant converts to f32 only: write an integer, or " + type_name(scalar_type(to.s)) + "(...))";
    if (is_abstract(from) && from.k != to.k) return " (WGSL converts a literal's type, never its shape)";
    return " (WGSL converts no concrete type to another: write " + type_name(to) + "(...))";
}

namespace {

// A float's value as an integer type takes it (#floating-point-conversion): truncated, clamped to
// the range that the source type can represent, NaN as 0.
long double float_to_integer(long double x, scalar from, scalar to) {
    if (std::isnan(x)) return 0;
    const bool f32 = from == scalar::f32;
    const long double hi = to == scalar::u32 ? (f32 ? 4294967040.0L : 4294967295.0L) : (f32 ? 2147483520.0L : 2147483647.0L);
    const long double lo = to == scalar::u32 ? 0.0L : -2147483648.0L;
    return std::fmax(lo, std::fmin(hi, std::trunc(x)));
}

long double wrap32(long double x, bool is_signed) {
    const auto bits = static_cast<std::uint32_t>(static_cast<std::int64_t>(x));
    return is_signed ? static_cast<long double>(static_cast<std::int32_t>(bits)) : static_cast<long double>(bits);
}

}  // namespace

bool convert_value(value& v, const type& from, const type& to, std::string& why) {
    if (!v.known || from.s == to.s) return true;
    for (long double& x : v.c) {
        if (to.s == scalar::boolean) {
            x = x != 0 ? 1 : 0;
        } else if (is_float(to.s)) {
            const double d = static_cast<double>(x);
            if (to.s == scalar::f32 && std::isinf(static_cast<float>(d)) && std::isfinite(d))
                return why = "the value " + std::to_string(d) + " overflows f32", false;
            if (to.s == scalar::f32 && !is_abstract(from)) x = static_cast<float>(d);
            else x = d;
        } else if (is_float(from.s)) {
            x = float_to_integer(x, from.s, to.s);
        } else if (from.s == scalar::abstract_int || from.s == scalar::boolean) {
            const long double lo = to.s == scalar::u32 ? 0.0L : to.s == scalar::i32 ? -2147483648.0L : -9223372036854775808.0L;
            const long double hi = to.s == scalar::u32 ? 4294967295.0L : to.s == scalar::i32 ? 2147483647.0L : 9223372036854775807.0L;
            if (x < lo || x > hi) {
                char text[32];
                std::snprintf(text, sizeof text, "%.0Lf", x);
                return why = std::string("the value ") + text + " does not fit in " + type_name(scalar_type(to.s)), false;
            }
        } else {
            x = wrap32(x, to.s == scalar::i32);  // i32 <-> u32: the same bits
        }
    }
    return true;
}

namespace {
std::string number_text(long double x, scalar s) {
    char buf[64];
    if (s == scalar::boolean) return x != 0 ? "true" : "false";
    if (is_integer(s)) {
        if (x == -2147483648.0L) return "(-2147483647 - 1)";
        std::snprintf(buf, sizeof buf, "%.0Lf", x);
        return x < 0 ? "(" + std::string(buf) + ")" : buf;
    }
    const double d = static_cast<double>(x);
    const auto r = std::to_chars(buf, buf + sizeof buf, d);
    std::string t(buf, r.ptr);
    if (t.find_first_of(".e") == std::string::npos) t += ".0";
    return d < 0 || std::signbit(d) ? "(" + t + ")" : t;
}
}  // namespace

std::string glsl_literal(const value& v, const type& t) {
    if (t.k == type::kind::scalar) return number_text(v.c.at(0), t.s);
    std::string o = t.k == type::kind::vector ? "vec" + std::to_string(t.n) : "mat" + std::to_string(t.n);
    o += "(";
    for (std::size_t i = 0; i < v.c.size(); ++i) o += (i ? ", " : "") + number_text(v.c[i], t.s);
    return o + ")";
}

std::string glsl_type(const type& t, const std::string& struct_name) {
    const char* e = t.s == scalar::boolean ? "bool" : is_integer(t.s) ? "int" : "float";
    switch (t.k) {
        case type::kind::scalar: return e;
        case type::kind::vector: return "vec" + std::to_string(t.n);
        case type::kind::matrix: return "mat" + std::to_string(t.n);
        case type::kind::structure: return struct_name;
        default: return "void";
    }
}

}  // namespace verify::wgsl
