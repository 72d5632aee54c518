// The built-in functions of the subset (https://www.w3.org/TR/WGSL/#builtin-functions): their
// overloads (one type T for all of a call's values, abstract arguments converted to it), their
// values in a const-expression, and the GLSL each becomes. GLSL's functions of the same name
// compute the same: GLSL 1.20 has no saturate, fma, trunc, round or determinant, nor an integer
// abs, min, max, clamp or sign, which the translation writes out or adds as helpers.
#include <cmath>
#include <map>

#include "wgsl_checker.hpp"

namespace verify::wgsl {

std::string type_hint(const std::string& n);

namespace {

enum class shape { float1, numeric1, signed1, float2, numeric2, float3, clamp, mix, dot, cross, length, distance, normalize,
                   reflect, refract, face_forward, select, transpose, determinant };

struct info {
    shape s;
    const char* glsl;  // GLSL's name; "" where the translation writes it out
};

const std::map<std::string, info>& table() {
    static const std::map<std::string, info> t{
        {"abs", {shape::numeric1, "abs"}}, {"acos", {shape::float1, "acos"}}, {"asin", {shape::float1, "asin"}},
        {"atan", {shape::float1, "atan"}}, {"atan2", {shape::float2, "atan"}}, {"ceil", {shape::float1, "ceil"}},
        {"clamp", {shape::clamp, "clamp"}}, {"cos", {shape::float1, "cos"}}, {"cross", {shape::cross, "cross"}},
        {"degrees", {shape::float1, "degrees"}}, {"determinant", {shape::determinant, ""}},
        {"distance", {shape::distance, "distance"}}, {"dot", {shape::dot, "dot"}}, {"exp", {shape::float1, "exp"}},
        {"exp2", {shape::float1, "exp2"}}, {"faceForward", {shape::face_forward, "faceforward"}},
        {"floor", {shape::float1, "floor"}}, {"fma", {shape::float3, ""}}, {"fract", {shape::float1, "fract"}},
        {"inverseSqrt", {shape::float1, "inversesqrt"}}, {"length", {shape::length, "length"}},
        {"log", {shape::float1, "log"}}, {"log2", {shape::float1, "log2"}}, {"max", {shape::numeric2, "max"}},
        {"min", {shape::numeric2, "min"}}, {"mix", {shape::mix, "mix"}}, {"normalize", {shape::normalize, "normalize"}},
        {"pow", {shape::float2, "pow"}}, {"radians", {shape::float1, "radians"}}, {"reflect", {shape::reflect, "reflect"}},
        {"refract", {shape::refract, "refract"}}, {"round", {shape::float1, ""}}, {"saturate", {shape::float1, ""}},
        {"select", {shape::select, ""}}, {"sign", {shape::signed1, "sign"}}, {"sin", {shape::float1, "sin"}},
        {"smoothstep", {shape::float3, "smoothstep"}}, {"sqrt", {shape::float1, "sqrt"}}, {"step", {shape::float2, "step"}},
        {"tan", {shape::float1, "tan"}}, {"transpose", {shape::transpose, "transpose"}}, {"trunc", {shape::float1, ""}}};
    return t;
}

// WGSL's built-ins outside the subset, and what a GLSL or HLSL programmer wrote for one inside it.
std::string refusal(const std::string& n, const std::string& type_hint) {
    static const std::map<std::string, std::string> hints{
        {"lerp", "WGSL writes mix"}, {"frac", "WGSL writes fract"}, {"rsqrt", "WGSL writes inverseSqrt"},
        {"inversesqrt", "WGSL writes inverseSqrt"}, {"faceforward", "WGSL writes faceForward"}, {"mad", "WGSL writes fma"},
        {"rcp", "WGSL writes 1.0 / x"}, {"mul", "WGSL writes *"}, {"fmod", "WGSL writes %"}, {"texture", "textures are outside the subset normzoo runs"},
        {"texture2D", "textures are outside the subset normzoo runs"}};
    const auto h = hints.find(n);
    if (h != hints.end()) return "'" + n + "' is not declared: " + h->second;
    static const char* const outside[] = {"sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "modf", "frexp", "ldexp",
                                          "quantizeToF16", "countLeadingZeros", "countOneBits", "countTrailingZeros",
                                          "extractBits", "insertBits", "firstLeadingBit", "firstTrailingBit", "reverseBits",
                                          "dot4U8Packed", "dot4I8Packed", "all", "any", "bitcast", "arrayLength",
                                          "workgroupBarrier", "storageBarrier", "textureBarrier", "workgroupUniformLoad"};
    for (const char* o : outside)
        if (n == o) return "the built-in " + n + " is outside the subset normzoo runs (docs/brdf-code.md#wgsl)";
    for (const char* prefix : {"texture", "atomic", "pack", "unpack", "dpd", "fwidth", "subgroup", "quad"})
        if (n.rfind(prefix, 0) == 0) return "the built-in " + n + " is outside the subset normzoo runs (docs/brdf-code.md#wgsl)";
    return "'" + n + "' is not declared" + type_hint;
}

// A component-wise function's value at one component (binary64; rounded to binary32 for f32).
double apply(const std::string& n, double a, double b, double c) {
    if (n == "abs") return std::fabs(a);
    if (n == "acos") return std::acos(a);
    if (n == "asin") return std::asin(a);
    if (n == "atan") return std::atan(a);
    if (n == "atan2") return std::atan2(a, b);
    if (n == "ceil") return std::ceil(a);
    if (n == "clamp") return std::fmin(std::fmax(a, b), c);
    if (n == "cos") return std::cos(a);
    if (n == "degrees") return a * (180 / 3.14159265358979323846);
    if (n == "exp") return std::exp(a);
    if (n == "exp2") return std::exp2(a);
    if (n == "floor") return std::floor(a);
    if (n == "fma") return a * b + c;
    if (n == "fract") return a - std::floor(a);
    if (n == "inverseSqrt") return 1 / std::sqrt(a);
    if (n == "log") return std::log(a);
    if (n == "log2") return std::log2(a);
    if (n == "max") return std::fmax(a, b);
    if (n == "min") return std::fmin(a, b);
    if (n == "mix") return a * (1 - c) + b * c;
    if (n == "pow") return std::pow(a, b);
    if (n == "radians") return a * (3.14159265358979323846 / 180);
    if (n == "round") return std::nearbyint(a);  // ties to even, as WGSL's round
    if (n == "saturate") return std::fmin(std::fmax(a, 0.0), 1.0);
    if (n == "sign") return a > 0 ? 1 : a < 0 ? -1 : 0;
    if (n == "sin") return std::sin(a);
    if (n == "smoothstep") {
        const double t = std::fmin(std::fmax((c - a) / (b - a), 0.0), 1.0);
        return t * t * (3 - 2 * t);
    }
    if (n == "sqrt") return std::sqrt(a);
    if (n == "step") return a <= b ? 1 : 0;
    if (n == "tan") return std::tan(a);
    if (n == "trunc") return std::trunc(a);
    return NAN;
}

// The determinant of an n x n matrix held column by column, by expansion along the first column.
double determinant_of(const std::vector<long double>& m, int n) {
    if (n == 1) return static_cast<double>(m[0]);
    double d = 0;
    for (int row = 0; row < n; ++row) {
        std::vector<long double> minor;
        for (int col = 1; col < n; ++col)
            for (int r = 0; r < n; ++r)
                if (r != row) minor.push_back(m[static_cast<std::size_t>(col * n + r)]);
        d += (row % 2 ? -1 : 1) * static_cast<double>(m[static_cast<std::size_t>(row)]) * determinant_of(minor, n - 1);
    }
    return d;
}

}  // namespace

bool checker::is_builtin(const std::string& name) const { return table().count(name) > 0; }

namespace {
std::size_t arity(shape s) {
    switch (s) {
        case shape::float3: case shape::clamp: case shape::mix: case shape::refract: case shape::face_forward: case shape::select: return 3;
        case shape::float2: case shape::numeric2: case shape::dot: case shape::cross: case shape::distance: case shape::reflect: return 2;
        default: return 1;
    }
}
}  // namespace

// T, the one type the arguments convert to (#overload-resolution-section): their join; an abstract
// T made concrete where an argument is not a const-expression (a runtime call has no abstract
// type). `params` gets each argument's type.
type checker::builtin_type(const expr& x, int shape_index, const std::vector<typed>& args, std::vector<type>& params) {
    const auto s = static_cast<shape>(shape_index);
    const std::string& n = x.text;
    const std::size_t want = arity(s);
    // mix's and refract's scalar third argument, select's condition, share T's element or nothing
    const bool scalar_third = (s == shape::mix && args[2].t.k == type::kind::scalar && args[0].t.k == type::kind::vector) || s == shape::refract;
    const std::size_t shared = scalar_third || s == shape::select ? 2 : want;
    type t = args[0].t;
    for (std::size_t i = 1; i < shared; ++i)
        if (!join(t, args[i].t, t)) {
            const bool mixed = (t.k == type::kind::scalar) != (args[i].t.k == type::kind::scalar);
            fail(x.line, n + " takes arguments of one type, not " + a_type(t) + " and " + a_type(args[i].t) +
                             (mixed ? ": WGSL has no form of it that mixes vectors and scalars (write vec3(x))" : ": WGSL converts neither"));
        }
    if (scalar_third) {
        type e;
        if (!join(scalar_type(t.s), args[2].t, e))
            fail(x.line, n + "'s third argument is " + a_type(scalar_type(t.s)) + ", not " + a_type(args[2].t));
        t = with_element(t, e.s);
    }
    const bool floats = s != shape::numeric1 && s != shape::signed1 && s != shape::numeric2 && s != shape::clamp && s != shape::select;
    if (floats && t.s == scalar::abstract_int) t.s = scalar::abstract_float;
    bool runtime = false;
    for (const auto& a : args) runtime = runtime || !a.constant;
    if (runtime) t = concretized(t);
    const bool vector_only = s == shape::dot || s == shape::cross || s == shape::normalize || s == shape::reflect || s == shape::refract || s == shape::face_forward;
    const bool matrix_only = s == shape::transpose || s == shape::determinant;
    if ((matrix_only && t.k != type::kind::matrix) || (!matrix_only && t.k == type::kind::matrix) ||
        (vector_only && t.k != type::kind::vector) || (s == shape::cross && t.n != 3) ||
        (t.k != type::kind::scalar && t.k != type::kind::vector && t.k != type::kind::matrix) ||
        (floats && !is_float(t.s)) || (s != shape::select && t.s == scalar::boolean) || (s == shape::signed1 && t.s == scalar::u32))
        fail(x.line, n + " is not defined for " + a_type(t) + " (https://www.w3.org/TR/WGSL/#" + n + "-builtin)");
    if (s == shape::select && args[2].t != scalar_type(scalar::boolean))
        fail(x.line, args[2].t.k == type::kind::vector ? "select with a vector of bool is outside the subset normzoo runs"
                                                       : "select's condition is a bool, not " + a_type(args[2].t));
    params.clear();
    for (std::size_t i = 0; i < want; ++i) params.push_back(i < shared ? t : s == shape::select ? args[2].t : scalar_type(t.s));
    return s == shape::dot || s == shape::length || s == shape::distance || s == shape::determinant ? scalar_type(t.s)
           : s == shape::transpose ? matrix_type(t.rows, t.n, t.s) : t;
}

// The value of a call whose arguments are known, each converted to its parameter's type.
void checker::builtin_value(const expr& x, int shape_index, const std::vector<typed>& c, typed& r) {
    const auto s = static_cast<shape>(shape_index);
    const std::string& n = x.text;
    const std::size_t want = arity(s);
    auto v = [&](std::size_t i, std::size_t k) {
        const auto& cs = c[i].v.c;
        return static_cast<double>(cs.size() == 1 ? cs[0] : cs[k]);
    };
    const std::size_t m = static_cast<std::size_t>(components(c[0].t));
    auto dot = [&](std::size_t i, std::size_t j) {
        double d = 0;
        for (std::size_t k = 0; k < m; ++k) d += v(i, k) * v(j, k);
        return d;
    };
    r.v.c.clear();
    if (s == shape::select) {
        for (std::size_t k = 0; k < m; ++k) r.v.c.push_back(v(2, 0) != 0 ? v(1, k) : v(0, k));
    } else if (s == shape::dot || s == shape::length) {
        r.v.c = {s == shape::dot ? dot(0, 1) : std::sqrt(dot(0, 0))};
    } else if (s == shape::distance) {
        double d = 0;
        for (std::size_t k = 0; k < m; ++k) d += (v(0, k) - v(1, k)) * (v(0, k) - v(1, k));
        r.v.c = {std::sqrt(d)};
    } else if (s == shape::cross) {
        r.v.c = {v(0, 1) * v(1, 2) - v(0, 2) * v(1, 1), v(0, 2) * v(1, 0) - v(0, 0) * v(1, 2), v(0, 0) * v(1, 1) - v(0, 1) * v(1, 0)};
    } else if (s == shape::normalize || s == shape::reflect || s == shape::refract || s == shape::face_forward) {
        const double l = std::sqrt(dot(0, 0)), d01 = dot(1, 0), d12 = want > 2 ? dot(1, 2) : 0;
        const double eta = s == shape::refract ? v(2, 0) : 0, k = 1 - eta * eta * (1 - d01 * d01);
        for (std::size_t j = 0; j < m; ++j)
            r.v.c.push_back(s == shape::normalize ? v(0, j) / l
                            : s == shape::reflect ? v(0, j) - 2 * d01 * v(1, j)
                            : s == shape::refract ? (k < 0 ? 0 : eta * v(0, j) - (eta * d01 + std::sqrt(k)) * v(1, j))
                                                  : (d12 < 0 ? v(0, j) : -v(0, j)));
    } else if (s == shape::transpose) {
        const int n = c[0].t.n;  // square: column i of the result is row i
        for (int col = 0; col < n; ++col)
            for (int row = 0; row < n; ++row) r.v.c.push_back(v(0, static_cast<std::size_t>(row * n + col)));
    } else if (s == shape::determinant) {
        r.v.c = {determinant_of(c[0].v.c, c[0].t.n)};
    } else {
        for (std::size_t k = 0; k < m; ++k) {
            const double a = v(0, k), b = want > 1 ? v(1, k) : 0, d = want > 2 ? v(2, k) : 0;
            if (n == "clamp" && c[1].constant && c[2].constant && b > d) fail(x.line, "clamp's low is above its high in a const-expression (WGSL refuses it)");
            if (n == "smoothstep" && c[0].constant && c[1].constant && a == b) fail(x.line, "smoothstep's two edges are equal in a const-expression (WGSL refuses it)");
            r.v.c.push_back(apply(n, a, b, d));
        }
    }
    for (long double& z : r.v.c) {
        if (r.t.s == scalar::f32) z = static_cast<float>(z);
        if (!std::isfinite(z) && (r.constant || is_abstract(r.t))) fail(x.line, n + "(...) is not finite in a const-expression (WGSL refuses it)");
        if (!std::isfinite(z)) r.v.known = false;
    }
}

typed checker::builtin(const expr& x, std::vector<typed>& args) {
    const auto found = table().find(x.text);
    if (found == table().end()) fail(x.line, refusal(x.text, type_hint(x.text)));
    if (x.has_templ) fail(x.line, x.text + " takes no template list");
    const shape s = found->second.s;
    const std::string& n = x.text;
    const std::size_t want = arity(s);
    if (args.size() != want) fail(x.line, n + " takes " + std::to_string(want) + " argument" + (want > 1 ? "s" : "") + ", not " + std::to_string(args.size()));
    std::vector<type> params;
    typed r;
    r.t = builtin_type(x, static_cast<int>(s), args, params);
    r.constant = true;
    r.v.known = true;
    std::vector<typed> c = args;
    for (std::size_t i = 0; i < want; ++i) {
        r.constant = r.constant && args[i].constant;
        std::string why;
        if (!convert_value(c[i].v, args[i].t, params[i], why)) fail(x.line, n + ": " + why);
        c[i].t = params[i];
        r.v.known = r.v.known && c[i].v.known;
    }
    if (r.v.known) builtin_value(x, static_cast<int>(s), c, r);
    if (is_abstract(r.t)) return r;
    std::vector<std::string> a;
    for (std::size_t i = 0; i < want; ++i) a.push_back(as(args[i], params[i], x.line));
    if (n == "saturate") return r.text = "clamp(" + a[0] + ", 0.0, 1.0)", r;
    if (n == "fma") return r.text = "(" + a[0] + " * " + a[1] + " + " + a[2] + ")", r;
    if (n == "select") return r.text = "(" + a[2] + " ? " + a[1] + " : " + a[0] + ")", r;
    std::string glsl = found->second.glsl;
    const bool integer = is_integer(params[0].s);
    if (n == "trunc" || n == "round" || n == "determinant" || (integer && (s == shape::numeric1 || s == shape::signed1 || s == shape::numeric2 || s == shape::clamp))) {
        const std::string h = integer ? "i" + n : n;
        helpers_.insert(h);
        glsl = prefix_ + "h" + h;
    }
    r.text = glsl + "(";
    for (std::size_t i = 0; i < a.size(); ++i) r.text += (i ? ", " : "") + a[i];
    r.text += ")";
    return r;
}

}  // namespace verify::wgsl
