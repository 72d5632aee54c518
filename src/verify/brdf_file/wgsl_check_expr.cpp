// Expressions (#expressions): literals, names, calls, components and operators, each with its
// WGSL type; the value of a const-expression computed as WGSL computes it (#const-expr), so that
// an abstract one reaches the GLSL as the literal WGSL converts it to.
#include <cmath>
#include <cstdlib>

#include "wgsl_checker.hpp"

namespace verify::wgsl {

bool is_type_name(const std::string& n);
std::string type_hint(const std::string& n);

std::string checker::as(const typed& x, const type& wanted, int line) {
    const type to = concretized(wanted);
    if (!is_abstract(x.t)) {
        if (x.t != to) fail(line, a_type(x.t) + " where " + a_type(to) + " is wanted" + why_not(x.t, to));
        return x.text;
    }
    if (!converts(x.t, to)) fail(line, a_type(x.t) + " where " + a_type(to) + " is wanted" + why_not(x.t, to));
    value v = x.v;
    std::string why;
    if (!v.known || !convert_value(v, x.t, to, why)) fail(line, why.empty() ? "a value WGSL computes at shader creation, which normzoo cannot" : why);
    if (to.s == scalar::u32)
        for (long double c : v.c)
            if (c >= 2147483648.0L) fail(line, "u32 values of 2^31 and more are outside the subset normzoo runs (its u32 is a 32-bit int)");
    return glsl_literal(v, to);
}

typed checker::check(int e) {
    static thread_local int depth = 0;
    struct guard {
        int& d;
        ~guard() { --d; }
    } g{++depth};
    const expr& x = ex(e);
    if (depth > 4 * max_nesting) fail(x.line, "an expression more than " + std::to_string(4 * max_nesting) + " operations deep: outside the subset normzoo reads");
    typed r;
    switch (x.k) {
        case expr::kind::int_literal:
        case expr::kind::float_literal:
        case expr::kind::bool_literal: r = literal(x); break;
        case expr::kind::name: r = name(x); break;
        case expr::kind::call: r = call(x); break;
        case expr::kind::index: r = index(x); break;
        case expr::kind::member: r = member(x); break;
        case expr::kind::unary: r = unary(x); break;
        case expr::kind::binary: r = binary(x); break;
    }
    r.line = x.line;
    return r;
}

typed checker::literal(const expr& x) {
    typed r;
    r.constant = true;
    r.v.known = true;
    if (x.k == expr::kind::bool_literal) {
        r.t = scalar_type(scalar::boolean);
        r.v.c = {x.text == "true" ? 1.0L : 0.0L};
        r.text = x.text;
        return r;
    }
    std::string digits = x.text;
    const char suffix = digits.back();
    const bool hex = digits.size() > 1 && (digits[1] == 'x' || digits[1] == 'X');
    if (x.k == expr::kind::int_literal) {
        if (suffix == 'i' || suffix == 'u') digits.pop_back();
        errno = 0;
        const unsigned long long n = std::strtoull(digits.c_str(), nullptr, hex ? 16 : 10);
        if (errno == ERANGE || n > 9223372036854775807ull) fail(x.line, "the integer literal " + x.text + " is too large (WGSL's integers have at most 64 bits)");
        r.t = scalar_type(suffix == 'i' ? scalar::i32 : suffix == 'u' ? scalar::u32 : scalar::abstract_int);
        r.v.c = {static_cast<long double>(n)};
        if ((suffix == 'i' && n > 2147483647ull) || (suffix == 'u' && n > 4294967295ull))
            fail(x.line, "the literal " + x.text + " does not fit in " + type_name(r.t));
        if (suffix == 'u' && n > 2147483647ull) fail(x.line, "u32 values of 2^31 and more are outside the subset normzoo runs (its u32 is a 32-bit int)");
    } else {
        if (suffix == 'h') fail(x.line, "the f16 literal " + x.text + ": f16 is outside the subset normzoo runs");
        if (suffix == 'f' && !(hex && digits.find_first_of("pP") == std::string::npos)) digits.pop_back();
        const double d = std::strtod(digits.c_str(), nullptr);
        const bool f32 = suffix == 'f' && !(hex && x.text.find_first_of("pP") == std::string::npos);
        r.t = scalar_type(f32 ? scalar::f32 : scalar::abstract_float);
        if (!std::isfinite(d) || (f32 && std::isinf(static_cast<float>(d)))) fail(x.line, "the literal " + x.text + " overflows " + type_name(r.t));
        if (f32 && hex && static_cast<double>(static_cast<float>(d)) != d) fail(x.line, "the hexadecimal literal " + x.text + " is not exactly an f32");
        r.v.c = {d};
    }
    if (!is_abstract(r.t)) r.text = glsl_literal(r.v, r.t);
    return r;
}

typed checker::name(const expr& x) {
    if (x.has_templ) fail(x.line, "'" + x.text + "<...>' is a type: construct a value with " + x.text + "<...>(...)");
    const binding* b = lookup(x.text, x.line);
    if (!b) {
        if (is_type_name(x.text)) fail(x.line, "'" + x.text + "' is a type, not a value");
        if (is_builtin(x.text)) fail(x.line, "'" + x.text + "' is a built-in function: call it");
        fail(x.line, "'" + x.text + "' is not declared" + type_hint(x.text));
    }
    if (b->k == binding::kind::function) fail(x.line, "fn " + x.text + " is a function: call it");
    if (b->k == binding::kind::structure || b->k == binding::kind::alias) fail(x.line, "'" + x.text + "' is a type, not a value");
    if (b->k == binding::kind::uniform_struct)
        fail(x.line, "var<uniform> " + x.text + " is read member by member (" + x.text + ".NAME), each a parameter of the header");
    typed r;
    r.t = b->t;
    r.constant = b->constant;
    r.v = b->v;
    r.text = b->glsl;
    r.reference = b->k == binding::kind::var;
    r.root = x.text;
    return r;
}

typed checker::call(const expr& x) {
    std::vector<typed> args;
    for (int a : x.args) args.push_back(check(a));
    for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s)
        if (s->count(x.text)) fail(x.line, "'" + x.text + "' is a value here, not a function");
    const auto d = module_names_.find(x.text);
    if (d != module_names_.end()) {
        const auto& decl = m_.decls[static_cast<std::size_t>(d->second)];
        if (decl.k == declaration::kind::structure || decl.k == declaration::kind::alias) {
            if (x.has_templ) fail(x.line, "'" + x.text + "' takes no template list");
            return construct(x, module_binding(d->second, x.line).t, args);
        }
        if (decl.k != declaration::kind::function) fail(x.line, "'" + x.text + "' is not a function");
        const binding& f = module_binding(d->second, x.line);
        const auto& sig = signature_[static_cast<std::size_t>(d->second)];
        const std::size_t n = decl.params.size();
        if (args.size() != n) fail(x.line, "fn " + x.text + " takes " + std::to_string(n) + " arguments, not " + std::to_string(args.size()));
        typed r;
        r.t = sig.back();
        r.text = f.glsl + "(";
        for (std::size_t i = 0; i < n; ++i) {
            if (!converts(args[i].t, sig[i]))
                fail(x.line, "fn " + x.text + "'s parameter " + decl.params[i].name + " is " + a_type(sig[i]) + ", not " + a_type(args[i].t));
            r.text += (i ? ", " : "") + as(args[i], sig[i], x.line);
        }
        r.text += ")";
        return r;
    }
    if (parameters_.count(x.text)) fail(x.line, "'" + x.text + "' is a parameter of the header, not a function");
    if (is_type_name(x.text)) {
        if (!x.has_templ && x.text != "f32" && x.text != "i32" && x.text != "u32" && x.text != "bool" && x.text != "f16" &&
            x.text.back() >= '0' && x.text.back() <= '9')
            return construct_inferred(x, args);
        return construct(x, predeclared_type(x), args);
    }
    return builtin(x, args);
}

typed checker::index(const expr& x) {
    const typed base = check(x.args[0]);
    const typed i = check(x.args[1]);
    if (base.t.k != type::kind::vector && base.t.k != type::kind::matrix)
        fail(x.line, "only vectors and matrices are indexed in the subset normzoo runs, not " + a_type(base.t));
    if (i.t.k != type::kind::scalar || !is_integer(i.t.s)) fail(x.line, "an index is an integer (i32 or u32), not " + a_type(i.t));
    if (!i.constant || !i.v.known)
        fail(x.line, "an index known only at run time is outside the subset normzoo runs: write .x, .y, .z or a constant index");
    const long double k = i.v.c.at(0);
    if (k < 0 || k >= base.t.n) fail(x.line, "the index " + std::to_string(static_cast<long long>(k)) + " is out of bounds for " + a_type(base.t));
    const int at = static_cast<int>(k);
    typed r = base;
    r.swizzle = false;
    if (base.t.k == type::kind::vector) {
        r.t = scalar_type(base.t.s);
        r.text = base.text + "." + "xyzw"[at];
        if (r.v.known) r.v.c = {base.v.c[static_cast<std::size_t>(at)]};
    } else {
        r.t = vector_type(base.t.rows, base.t.s);
        r.text = base.text + "[" + std::to_string(at) + "]";
        if (r.v.known) r.v.c.assign(base.v.c.begin() + at * base.t.rows, base.v.c.begin() + (at + 1) * base.t.rows);
    }
    return r;
}

typed checker::uniform_member(const expr& x, const binding& u) {
    const auto& decl = m_.decls[static_cast<std::size_t>(u.t.index)];
    const std::string& uniform = ex(x.args[0]).text;
    for (std::size_t i = 0; i < decl.params.size(); ++i) {
        if (decl.params[i].name != x.text) continue;
        const type t = signature_[static_cast<std::size_t>(u.t.index)][i];
        const auto p = parameters_.find(x.text);
        if (p == parameters_.end())
            fail(x.line, uniform + "." + x.text + " is not a parameter of the header: add [parameters." + x.text + "] to it (docs/brdf-code.md#plain-files)");
        if (t.s == scalar::boolean) fail(x.line, uniform + "." + x.text + ": bool is no uniform's type in WGSL; the header's bool is a module-scope name");
        if (t != p->second.t)
            fail(x.line, uniform + "." + x.text + " is " + a_type(t) + ", but the header's parameter (line " + std::to_string(p->second.line) + ") is " + a_type(p->second.t));
        typed r;
        r.t = t;
        r.text = p->second.glsl;
        return r;
    }
    fail(x.line, "struct " + decl.name + " has no member " + x.text);
}

typed checker::member(const expr& x) {
    const expr& b = ex(x.args[0]);
    if (b.k == expr::kind::name && !b.has_templ) {
        const binding* u = lookup(b.text, b.line);
        if (u && u->k == binding::kind::uniform_struct) return uniform_member(x, *u);
    }
    const typed base = check(x.args[0]);
    typed r = base;
    r.swizzle = false;
    if (base.t.k == type::kind::structure) {
        const auto& decl = m_.decls[static_cast<std::size_t>(base.t.index)];
        for (std::size_t i = 0; i < decl.params.size(); ++i)
            if (decl.params[i].name == x.text) {
                r.t = signature_[static_cast<std::size_t>(base.t.index)][i];
                r.text = base.text + "." + mangled(x.text);
                r.v.known = false;
                return r;
            }
        fail(x.line, "struct " + decl.name + " has no member " + x.text);
    }
    if (base.t.k != type::kind::vector) fail(x.line, a_type(base.t) + " has no member ." + x.text);
    const std::string& w = x.text;
    const std::string sets[] = {"xyzw", "rgba"};
    std::string glsl;
    for (const auto& set : sets) {
        glsl.clear();
        for (char c : w) {
            const auto at = set.find(c);
            if (at == std::string::npos || static_cast<int>(at) >= base.t.n) break;
            glsl += "xyzw"[at];
        }
        if (glsl.size() == w.size()) break;
    }
    if (w.size() > 4 || glsl.size() != w.size()) fail(x.line, "." + w + " is no swizzle of " + a_type(base.t));
    r.t = w.size() == 1 ? scalar_type(base.t.s) : vector_type(static_cast<int>(w.size()), base.t.s);
    r.text = base.text + "." + glsl;
    r.swizzle = w.size() > 1;
    if (base.v.known) {
        r.v.c.clear();
        for (char c : glsl) r.v.c.push_back(base.v.c[static_cast<std::size_t>(std::string("xyzw").find(c))]);
    }
    return r;
}

typed checker::unary(const expr& x) {
    const std::string& op = x.text;
    if (op == "&" || op == "*") fail(x.line, "pointers (unary " + op + ") are outside the subset normzoo runs: pass and return values");
    if (op == "~") fail(x.line, "bitwise operators (~) are outside the subset normzoo runs");
    typed a = check(x.args[0]);
    typed r = a;
    r.reference = false, r.swizzle = false;
    if (op == "!") {
        if (a.t != scalar_type(scalar::boolean)) fail(x.line, "'!' takes a bool, not " + a_type(a.t));
        if (r.v.known) r.v.c[0] = a.v.c[0] == 0 ? 1 : 0;
        r.text = "(!" + a.text + ")";
        return r;
    }
    if (!numeric(a.t) || a.t.k == type::kind::matrix || a.t.s == scalar::u32) fail(x.line, "unary '-' is not defined for " + a_type(a.t));
    if (r.v.known)
        for (long double& c : r.v.c) {
            if (a.t.s == scalar::abstract_int && c == -9223372036854775808.0L) fail(x.line, "the AbstractInt overflows");
            c = a.t.s == scalar::i32 && c == -2147483648.0L ? c : -c;
        }
    if (!is_abstract(a.t)) r.text = "(-" + a.text + ")";
    return r;
}

typed checker::binary(const expr& x) {
    const std::string& op = x.text;
    if (op == "^" || op == "<<" || op == ">>") fail(x.line, "bitwise operators and shifts ('" + op + "') are outside the subset normzoo runs");
    typed a = check(x.args[0]);
    typed b = check(x.args[1]);
    if (op == "+" || op == "-" || op == "*" || op == "/" || op == "%") return arithmetic(op, a, b, x.line);
    if (op == "&&" || op == "||" || op == "&" || op == "|") {
        const type boolean = scalar_type(scalar::boolean);
        if (a.t != boolean || b.t != boolean) {
            if (op.size() == 1 && numeric(a.t)) fail(x.line, "bitwise operators ('" + op + "') are outside the subset normzoo runs");
            fail(x.line, "'" + op + "' takes two bools, not " + a_type(a.t) + " and " + a_type(b.t));
        }
        typed r;
        r.t = boolean;
        r.constant = a.constant && b.constant;
        r.v.known = a.v.known && b.v.known;
        const bool both = op[0] == '&';
        if (r.v.known) r.v.c = {both ? (a.v.c[0] != 0 && b.v.c[0] != 0 ? 1.0L : 0.0L) : (a.v.c[0] != 0 || b.v.c[0] != 0 ? 1.0L : 0.0L)};
        // & and | on bools evaluate both sides; the subset's expressions have no side effects
        r.text = "(" + a.text + (both ? " && " : " || ") + b.text + ")";
        return r;
    }
    return comparison(op, a, b, x.line);
}

}  // namespace verify::wgsl
