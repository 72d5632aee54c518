// WGSL's arithmetic and comparison operators (#arithmetic-expr, #comparison-expr): the operand
// types they take (no conversion between concrete types; an abstract operand converted to the
// other's type), their values in a const-expression, and the GLSL of each: integer division and
// remainder, and the floating-point remainder, by helpers that compute what WGSL defines.
#include <cmath>
#include <cstdint>

#include "wgsl_checker.hpp"

namespace verify::wgsl {

namespace {

bool arithmetic_element(scalar s) { return s != scalar::boolean; }

}  // namespace

typed checker::arithmetic(const std::string& op, typed a, typed b, int line) {
    if (!numeric(a.t) || !numeric(b.t) || !arithmetic_element(a.t.s) || !arithmetic_element(b.t.s))
        fail(line, "'" + op + "' takes numbers, not " + a_type(a.t) + " and " + a_type(b.t));
    type e;
    if (!join(scalar_type(a.t.s), scalar_type(b.t.s), e))
        fail(line, "'" + op + "' cannot take " + a_type(a.t) + " and " + a_type(b.t) +
                       ": WGSL converts neither concrete type to the other (write f32(...), i32(...) or u32(...))");
    const type ta = with_element(a.t, e.s), tb = with_element(b.t, e.s);
    typed r;
    r.constant = a.constant && b.constant;
    const bool ma = a.t.k == type::kind::matrix, mb = b.t.k == type::kind::matrix;
    if (ma || mb) {
        if (op == "*") return matrix_product(a, b, line);
        if ((op != "+" && op != "-") || !ma || !mb || a.t.n != b.t.n || a.t.rows != b.t.rows)
            fail(line, "'" + op + "' is not defined for " + a_type(a.t) + " and " + a_type(b.t));
        r.t = ta;
    } else {
        const bool va = a.t.k == type::kind::vector, vb = b.t.k == type::kind::vector;
        if (va && vb && a.t.n != b.t.n) fail(line, "'" + op + "' takes vectors of one size, not " + a_type(a.t) + " and " + a_type(b.t));
        r.t = va ? ta : tb;
    }
    typed ca = a, cb = b;
    std::string why;
    if (!convert_value(ca.v, a.t, ta, why) || !convert_value(cb.v, b.t, tb, why)) fail(line, why);
    ca.t = ta, cb.t = tb;
    fold(r, op, ca, cb, line);
    if (is_abstract(r.t)) return r;
    std::string x = as(a, ta, line), y = as(b, tb, line);
    if (op == "%" && r.t.k == type::kind::vector) {  // the remainder's helper takes two vectors
        if (ta.k == type::kind::scalar) x = "vec" + std::to_string(r.t.n) + "(" + x + ")";
        if (tb.k == type::kind::scalar) y = "vec" + std::to_string(r.t.n) + "(" + y + ")";
    }
    r.text = operator_text(op, r, x, y);
    return r;
}

typed checker::matrix_product(typed a, typed b, int line) {
    type e;
    if (!join(scalar_type(a.t.s), scalar_type(b.t.s), e) || !is_float(e.s))
        fail(line, "'*' cannot take " + a_type(a.t) + " and " + a_type(b.t));
    if (e.s == scalar::abstract_int) e.s = scalar::abstract_float;
    const type ta = with_element(a.t, e.s), tb = with_element(b.t, e.s);
    typed r;
    r.constant = a.constant && b.constant;
    const auto ka = a.t.k, kb = b.t.k;
    const int n = a.t.k == type::kind::matrix ? a.t.n : b.t.n;
    if (ka == type::kind::scalar || kb == type::kind::scalar) r.t = ka == type::kind::scalar ? tb : ta;
    else if (ka == type::kind::matrix && kb == type::kind::matrix && a.t.n == b.t.rows) r.t = matrix_type(b.t.n, a.t.rows, e.s);
    else if (ka == type::kind::matrix && kb == type::kind::vector && b.t.n == a.t.n) r.t = vector_type(a.t.rows, e.s);
    else if (ka == type::kind::vector && kb == type::kind::matrix && a.t.n == b.t.rows) r.t = vector_type(b.t.n, e.s);
    else fail(line, "'*' cannot take " + a_type(a.t) + " and " + a_type(b.t));
    typed ca = a, cb = b;
    std::string why;
    if (!convert_value(ca.v, a.t, ta, why) || !convert_value(cb.v, b.t, tb, why)) fail(line, why);
    r.v.known = ca.v.known && cb.v.known;
    if (r.v.known && (ka == type::kind::scalar || kb == type::kind::scalar)) {
        ca.t = ta, cb.t = tb;
        fold(r, "*", ca, cb, line);
    } else if (r.v.known) {
        // element (column c, row i) of a product: sum over k of left(k, i) right(c, k)
        auto at = [&](const typed& m, int column, int row) {
            return m.t.k == type::kind::vector ? m.v.c[static_cast<std::size_t>(column + row)] : m.v.c[static_cast<std::size_t>(column * m.t.rows + row)];
        };
        const int columns = r.t.k == type::kind::matrix ? r.t.n : 1, rows = r.t.k == type::kind::matrix ? r.t.rows : r.t.n;
        r.v.c.assign(static_cast<std::size_t>(columns * rows), 0);
        for (int c = 0; c < columns; ++c)
            for (int i = 0; i < rows; ++i) {
                double sum = 0;
                for (int k = 0; k < n; ++k) {
                    const bool vec_mat = ka == type::kind::vector;
                    const double left = static_cast<double>(vec_mat ? at(ca, 0, k) : at(ca, k, i));
                    const double right = static_cast<double>(vec_mat ? at(cb, i, k) : kb == type::kind::vector ? at(cb, 0, k) : at(cb, c, k));
                    sum += left * right;
                }
                if (e.s == scalar::f32) sum = static_cast<float>(sum);
                r.v.c[static_cast<std::size_t>(c * rows + i)] = sum;
            }
    }
    if (!is_abstract(r.t)) r.text = "(" + as(a, ta, line) + " * " + as(b, tb, line) + ")";
    return r;
}

typed checker::comparison(const std::string& op, typed a, typed b, int line) {
    if (a.t.k == type::kind::vector || b.t.k == type::kind::vector)
        fail(line, "'" + op + "' on vectors gives a vector of bool, outside the subset normzoo runs: compare components (v.x " + op + " w.x)");
    if (a.t.k != type::kind::scalar || b.t.k != type::kind::scalar) fail(line, "'" + op + "' compares scalars, not " + a_type(a.t) + " and " + a_type(b.t));
    type e;
    if (!join(a.t, b.t, e)) fail(line, "'" + op + "' cannot compare " + a_type(a.t) + " with " + a_type(b.t) + ": WGSL converts neither");
    if (e.s == scalar::boolean && op != "==" && op != "!=") fail(line, "'" + op + "' does not order bools");
    typed r;
    r.t = scalar_type(scalar::boolean);
    r.constant = a.constant && b.constant;
    typed ca = a, cb = b;
    std::string why;
    if (!convert_value(ca.v, a.t, e, why) || !convert_value(cb.v, b.t, e, why)) fail(line, why);
    r.v.known = ca.v.known && cb.v.known;
    if (r.v.known) {
        const long double x = ca.v.c[0], y = cb.v.c[0];
        const bool t = op == "<" ? x < y : op == ">" ? x > y : op == "<=" ? x <= y : op == ">=" ? x >= y : op == "==" ? x == y : x != y;
        r.v.c = {t ? 1.0L : 0.0L};
    }
    r.text = "(" + as(a, e, line) + " " + op + " " + as(b, e, line) + ")";
    return r;
}

// One component of a const-expression's arithmetic, in the element type `s`.
static long double component(const std::string& op, long double x, long double y, scalar s, bool& bad, std::string& why) {
    const char o = op[0];
    if (s == scalar::abstract_float || s == scalar::f32) {
        const bool f32 = s == scalar::f32;
        double a = static_cast<double>(x), b = static_cast<double>(y), z = 0;
        if (f32) {
            const float fa = static_cast<float>(a), fb = static_cast<float>(b);
            z = o == '+' ? fa + fb : o == '-' ? fa - fb : o == '*' ? fa * fb : o == '/' ? fa / fb : fa - fb * std::trunc(fa / fb);
        } else {
            z = o == '+' ? a + b : o == '-' ? a - b : o == '*' ? a * b : o == '/' ? a / b : a - b * std::trunc(a / b);
        }
        if (!std::isfinite(z)) bad = true, why = "the const-expression overflows or is not a number (WGSL refuses it)";
        return z;
    }
    const auto a = static_cast<std::int64_t>(x), b = static_cast<std::int64_t>(y);
    const std::int64_t lowest = s == scalar::abstract_int ? INT64_MIN : s == scalar::i32 ? INT32_MIN : 0;
    if ((o == '/' || o == '%') && b == 0) return bad = true, why = "division by zero in a const-expression", 0;
    if ((o == '/' || o == '%') && b == -1 && a == lowest && s != scalar::u32)
        return bad = true, why = "the const-expression overflows (the most negative value divided by -1)", 0;
    long double z = 0;
    if (o == '/') z = static_cast<long double>(a / b);
    else if (o == '%') z = static_cast<long double>(a % b);
    else z = o == '+' ? x + y : o == '-' ? x - y : x * y;
    if (s == scalar::abstract_int && (z > 9223372036854775807.0L || z < -9223372036854775808.0L))
        bad = true, why = "the AbstractInt overflows (64 bits)";
    if (s == scalar::i32 || s == scalar::u32) {  // concrete integers wrap (#integer-types)
        const auto bits = static_cast<std::uint32_t>(static_cast<std::int64_t>(std::fmod(z, 4294967296.0L)));
        z = s == scalar::i32 ? static_cast<long double>(static_cast<std::int32_t>(bits)) : static_cast<long double>(bits);
    }
    return z;
}

void checker::fold(typed& r, const std::string& op, const typed& a, const typed& b, int line) {
    r.v.known = a.v.known && b.v.known;
    const bool integer = is_integer(r.t.s);
    if (integer && (op == "/" || op == "%") && b.v.known && b.constant)
        for (long double c : b.v.c)
            if (c == 0) fail(line, "division by zero in a const-expression (WGSL refuses it)");
    if (!r.v.known) return;
    const std::size_t n = static_cast<std::size_t>(components(r.t));
    r.v.c.assign(n, 0);
    bool bad = false;
    std::string why;
    for (std::size_t i = 0; i < n; ++i) {
        const long double x = a.v.c.size() == 1 ? a.v.c[0] : a.v.c[i];
        const long double y = b.v.c.size() == 1 ? b.v.c[0] : b.v.c[i];
        r.v.c[i] = component(op, x, y, r.t.s, bad, why);
    }
    if (bad && (r.constant || is_abstract(r.t))) fail(line, why);
    if (bad) r.v.known = false;
}

std::string checker::operator_text(const std::string& op, const typed& r, const std::string& a, const std::string& b) {
    if (op != "/" && op != "%") return "(" + a + " " + op + " " + b + ")";
    if (op == "/" && !is_integer(r.t.s)) return "(" + a + " / " + b + ")";
    // WGSL's integer division and remainder are defined at zero; its float remainder truncates
    const std::string h = is_integer(r.t.s) ? (op == "/" ? "idiv" : "imod") : "fmod";
    helpers_.insert(h);
    return prefix_ + "h" + h + "(" + a + ", " + b + ")";
}

}  // namespace verify::wgsl
