// Types as written (#types), and the constructors of values (#value-constructor-builtin-function,
// #zero-value-builtin-function): which the subset has, and the GLSL each becomes.
#include "wgsl_checker.hpp"

namespace verify::wgsl {

// What a GLSL or HLSL programmer wrote for a WGSL type, and what WGSL calls it.
std::string type_hint(const std::string& n) {
    static const std::map<std::string, std::string> hints{
        {"float", "f32"}, {"int", "i32"}, {"uint", "u32"}, {"half", "f16"}, {"double", "nothing: WGSL has no double"},
        {"float2", "vec2<f32>"}, {"float3", "vec3<f32>"}, {"float4", "vec4<f32>"}, {"mat2", "mat2x2<f32>"},
        {"mat3", "mat3x3<f32>"}, {"mat4", "mat4x4<f32>"}, {"float3x3", "mat3x3<f32>"}, {"float4x4", "mat4x4<f32>"},
        {"void", "nothing: a function without a result has no '->'"}};
    const auto h = hints.find(n);
    return h == hints.end() ? "" : " (WGSL writes " + h->second + ")";
}

namespace {

bool vector_name(const std::string& n, int& size, char& suffix) {
    if (n.size() < 4 || n.compare(0, 3, "vec") != 0 || n[3] < '2' || n[3] > '4' || n.size() > 5) return false;
    size = n[3] - '0';
    suffix = n.size() == 5 ? n[4] : 0;
    return suffix == 0 || suffix == 'f' || suffix == 'h' || suffix == 'i' || suffix == 'u';
}

bool matrix_name(const std::string& n, int& columns, int& rows, char& suffix) {
    if (n.size() < 6 || n.compare(0, 3, "mat") != 0 || n[4] != 'x' || n.size() > 7) return false;
    columns = n[3] - '0', rows = n[5] - '0';
    suffix = n.size() == 7 ? n[6] : 0;
    return columns >= 2 && columns <= 4 && rows >= 2 && rows <= 4 && (suffix == 0 || suffix == 'f' || suffix == 'h');
}

}  // namespace

bool is_type_name(const std::string& n) {
    int a = 0, b = 0;
    char c = 0;
    return n == "f32" || n == "i32" || n == "u32" || n == "bool" || n == "f16" || n == "array" || vector_name(n, a, c) ||
           matrix_name(n, a, b, c);
}

type checker::resolve_type(int e) {
    const expr& x = ex(e);
    if (x.k != expr::kind::name) fail(x.line, "expected a type");
    for (const auto& scope : scopes_)
        if (scope.count(x.text)) fail(x.line, "'" + x.text + "' is a value here, not a type");
    const auto d = module_names_.find(x.text);
    if (d != module_names_.end()) {
        const auto k = m_.decls[static_cast<std::size_t>(d->second)].k;
        if (k != declaration::kind::structure && k != declaration::kind::alias) fail(x.line, "'" + x.text + "' is not a type");
        if (x.has_templ) fail(x.line, "'" + x.text + "' takes no template list");
        return module_binding(d->second, x.line).t;
    }
    if (parameters_.count(x.text)) fail(x.line, "'" + x.text + "' is a parameter of the header, not a type");
    return predeclared_type(x);
}

type checker::predeclared_type(const expr& x) {
    const std::string& n = x.text;
    auto no_template = [&] {
        if (x.has_templ) fail(x.line, "'" + n + "' takes no template list");
    };
    auto element = [&](const char* what) {
        if (x.templ.size() != 1) fail(x.line, std::string(what) + " needs its element type here: " + n + "<f32>");
        return resolve_type(x.templ[0]);
    };
    auto f16 = [&] { fail(x.line, "f16 is outside the subset normzoo runs (docs/brdf-code.md#wgsl)"); };
    int size = 0, rows = 0;
    char suffix = 0;
    if (n == "f32" || n == "i32" || n == "u32" || n == "bool") {
        no_template();
        return scalar_type(n == "f32" ? scalar::f32 : n == "i32" ? scalar::i32 : n == "u32" ? scalar::u32 : scalar::boolean);
    }
    if (n == "f16") f16();
    if (vector_name(n, size, suffix)) {
        type e = scalar_type(scalar::f32);
        if (suffix) no_template();
        else e = element("a vector");
        if (suffix == 'h' || e.s == scalar::f16) f16();
        if (suffix == 'i' || suffix == 'u' || e.k != type::kind::scalar || e.s != scalar::f32)
            fail(x.line, "'" + (suffix ? n : n + "<" + type_name(e) + ">") + "': vectors of i32, u32 and bool are outside the subset normzoo runs (vectors of f32 only)");
        return vector_type(size, scalar::f32);
    }
    if (matrix_name(n, size, rows, suffix)) {
        type e = scalar_type(scalar::f32);
        if (suffix) no_template();
        else e = element("a matrix");
        if (suffix == 'h' || e.s == scalar::f16) f16();
        if (e.k != type::kind::scalar || e.s != scalar::f32) fail(x.line, "a matrix's elements are f32 (or f16), not " + type_name(e));
        if (size != rows) fail(x.line, "'" + n + "': matrices that are not square are outside the subset normzoo runs");
        return matrix_type(size, rows, scalar::f32);
    }
    if (n == "array") fail(x.line, "arrays are outside the subset normzoo runs (docs/brdf-code.md#wgsl)");
    if (n == "ptr") fail(x.line, "pointers are outside the subset normzoo runs: pass and return values");
    if (n == "atomic") fail(x.line, "atomics are outside the subset normzoo runs");
    if (n.compare(0, 8, "texture_") == 0 || n == "sampler" || n == "sampler_comparison" || n == "binding_array")
        fail(x.line, "'" + n + "': textures and samplers are outside the subset normzoo runs");
    fail(x.line, "'" + n + "' is not a type" + type_hint(n));
}

std::string checker::struct_glsl(const type& t) const {
    return t.k == type::kind::structure ? decl_binding_[static_cast<std::size_t>(t.index)].glsl : "";
}

std::string checker::maker(int d) {
    const auto& x = m_.decls[static_cast<std::size_t>(d)];
    const std::string s = decl_binding_[static_cast<std::size_t>(d)].glsl;
    std::string head = s + " " + prefix_ + "hmake_" + x.name + "(", body = " " + s + " r;";
    for (std::size_t i = 0; i < x.params.size(); ++i) {
        const type& t = signature_[static_cast<std::size_t>(d)][i];
        head += (i ? ", " : "") + glsl_type(t, struct_glsl(t)) + " a" + std::to_string(i);
        body += " r." + mangled(x.params[i].name) + " = a" + std::to_string(i) + ";";
    }
    return head + ") {" + body + " return r; }";
}

std::string checker::zero_text(const type& t) {
    if (t.k == type::kind::scalar) return t.s == scalar::boolean ? "false" : is_integer(t.s) ? "0" : "0.0";
    if (t.k == type::kind::vector) return "vec" + std::to_string(t.n) + "(0.0)";
    if (t.k == type::kind::matrix) return "mat" + std::to_string(t.n) + "(0.0)";
    const auto& x = m_.decls[static_cast<std::size_t>(t.index)];
    std::string o = prefix_ + "hmake_" + x.name + "(";
    for (std::size_t i = 0; i < x.params.size(); ++i) o += (i ? ", " : "") + zero_text(signature_[static_cast<std::size_t>(t.index)][i]);
    return o + ")";
}

typed checker::convert_scalar(const expr& call, const type& t, typed& a) {
    if (a.t.k != type::kind::scalar) fail(call.line, type_name(t) + "(...) converts a scalar, not " + a_type(a.t));
    typed r;
    r.t = t;
    r.constant = a.constant;
    r.v = a.v;
    std::string why;
    if (!convert_value(r.v, a.t, t, why)) fail(call.line, type_name(t) + "(...): " + why);
    if (is_abstract(a.t)) {  // a constant: the converted value's literal
        if (t.s == scalar::u32 && r.v.c.at(0) >= 2147483648.0L)
            fail(call.line, "u32 values of 2^31 and more are outside the subset normzoo runs (its u32 is a 32-bit int)");
        r.text = glsl_literal(r.v, t);
        return r;
    }
    const std::string& x = a.text;
    if (a.t.s == t.s || (is_integer(a.t.s) && is_integer(t.s))) r.text = x;  // i32 and u32 share GLSL's int
    else if (t.s == scalar::f32) r.text = "float(" + x + ")";
    else if (t.s == scalar::boolean) r.text = "(" + x + (a.t.s == scalar::f32 ? " != 0.0)" : " != 0)");
    else if (a.t.s == scalar::boolean) r.text = "int(" + x + ")";
    else r.text = (helpers_.insert(t.s == scalar::i32 ? "f2i" : "f2u"), prefix_ + (t.s == scalar::i32 ? "hf2i(" : "hf2u(") + x + ")");
    return r;
}

typed checker::construct(const expr& call, const type& t, std::vector<typed>& args) {
    typed r;
    r.t = t;
    r.constant = true;
    r.v.known = true;
    for (const auto& a : args) r.constant = r.constant && a.constant, r.v.known = r.v.known && a.v.known;
    if (args.empty()) {
        r.v.c.assign(static_cast<std::size_t>(components(t)), 0);
        r.v.known = t.k != type::kind::structure;
        r.text = zero_text(t);
        return r;
    }
    const std::string name = type_name(t);
    if (t.k == type::kind::scalar) {
        if (args.size() != 1) fail(call.line, name + "(...) takes one value");
        return convert_scalar(call, t, args[0]);
    }
    if (t.k == type::kind::structure) {
        const auto& members = signature_[static_cast<std::size_t>(t.index)];
        if (args.size() != members.size()) fail(call.line, name + "(...) takes its " + std::to_string(members.size()) + " members, not " + std::to_string(args.size()));
        r.text = prefix_ + "hmake_" + name + "(";
        for (std::size_t i = 0; i < args.size(); ++i) {
            if (!converts(args[i].t, members[i])) fail(call.line, name + "(...): member " + std::to_string(i + 1) + " is " + a_type(members[i]) + ", not " + a_type(args[i].t));
            r.text += (i ? ", " : "") + as(args[i], members[i], call.line);
        }
        r.v.known = false;
        return r.text += ")", r;
    }
    const scalar e = t.s;
    const type column = vector_type(t.rows, e);
    // one value of the same shape: a conversion (vec3<f32>(v)); one scalar: every component (splat)
    const bool same_shape = args.size() == 1 && args[0].t.k == t.k && args[0].t.n == t.n && args[0].t.rows == t.rows;
    const bool splat = args.size() == 1 && t.k == type::kind::vector && args[0].t.k == type::kind::scalar;
    int count = 0;
    r.v.c.clear();
    std::vector<std::string> parts;
    for (auto& a : args) {
        type want = a.t.k == type::kind::scalar ? scalar_type(e) : t.k == type::kind::matrix ? column : vector_type(a.t.n, e);
        if (same_shape) want = t;
        const bool ok = a.t.k == type::kind::scalar || a.t.k == type::kind::vector || same_shape;
        if (!ok || (t.k == type::kind::matrix && !same_shape && a.t.k == type::kind::vector && a.t.n != t.rows) ||
            (!same_shape && !converts(a.t, want)))
            fail(call.line, name + "(...) cannot take " + a_type(a.t) + (same_shape ? "" : " (WGSL converts no concrete type to another here)"));
        typed c = a;
        std::string why;
        if (!convert_value(c.v, a.t, want, why)) fail(call.line, name + "(...): " + why);
        for (long double v : c.v.c) r.v.c.push_back(v);
        count += components(a.t);
        parts.push_back(is_abstract(a.t) ? glsl_literal(c.v, want) : a.text);
    }
    if (splat) r.v.c.assign(static_cast<std::size_t>(t.n), r.v.c.empty() ? 0 : r.v.c[0]);
    else if (count != components(t))
        fail(call.line, name + "(...) needs " + std::to_string(components(t)) + " components (or one value for all), not " + std::to_string(count));
    r.text = (t.k == type::kind::vector ? "vec" : "mat") + std::to_string(t.n) + "(";
    for (std::size_t i = 0; i < parts.size(); ++i) r.text += (i ? ", " : "") + parts[i];
    r.text += ")";
    return r;
}

typed checker::construct_inferred(const expr& call, std::vector<typed>& args) {
    int size = 0, rows = 0;
    char suffix = 0;
    const bool vector = vector_name(call.text, size, suffix);
    if (!vector) matrix_name(call.text, size, rows, suffix);
    type e = scalar_type(scalar::abstract_int);
    for (std::size_t i = 0; i < args.size(); ++i) {
        const type ai = scalar_type(args[i].t.s);
        if (!numeric(args[i].t) && !(vector && args[i].t.s == scalar::boolean)) fail(call.line, call.text + "(...) cannot take " + a_type(args[i].t));
        if (i == 0) e = ai;
        else if (!join(e, ai, e))
            fail(call.line, call.text + "(...) takes components of one type, not " + type_name(e) + " and " + type_name(ai) + ": WGSL converts neither");
    }
    if (!vector && e.s == scalar::abstract_int) e.s = scalar::abstract_float;
    if (!vector && !is_float(e.s)) fail(call.line, "a matrix's elements are f32, not " + type_name(e));
    if (!is_abstract(e) && e.s != scalar::f32)
        fail(call.line, call.text + "(...) of " + type_name(e) + ": vectors of i32, u32 and bool are outside the subset normzoo runs (vectors of f32 only)");
    if (!vector && size != rows) fail(call.line, "'" + call.text + "': matrices that are not square are outside the subset normzoo runs");
    return construct(call, vector ? vector_type(size, e.s) : matrix_type(size, rows, e.s), args);
}

}  // namespace verify::wgsl
