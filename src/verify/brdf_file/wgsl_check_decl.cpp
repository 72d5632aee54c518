// The simple statements (#var-and-value, #assignment, #increment-decrement, #function-call-statement):
// let, var and const in a function, assignments to what a var holds, and calls, each as one line
// of GLSL without its ';'.
#include "wgsl_checker.hpp"

namespace verify::wgsl {

std::string checker::declaration(const stmt& x) {
    const char* what = x.k == stmt::kind::let ? "let" : x.k == stmt::kind::var ? "var" : "const";
    if (x.k == stmt::kind::var && !x.templ.empty() && ex(x.templ[0]).text != "function")
        fail(x.line, "var<" + ex(x.templ[0]).text + "> in a function: a function's var is var<function> (or plain var)");
    typed v;
    const bool has_value = x.value >= 0;
    if (has_value) v = check(x.value);
    if (has_value && v.t.k == type::kind::none) fail(x.line, std::string(what) + " " + x.name + ": the function called returns no value");
    type t = has_value ? v.t : type{};
    if (x.type >= 0) {
        t = resolve_type(x.type);
        if (has_value && !converts(v.t, t)) fail(x.line, std::string(what) + " " + x.name + ": " + type_name(t) + " cannot hold " + a_type(v.t) + why_not(v.t, t));
    }
    binding b;
    b.k = x.k == stmt::kind::var ? binding::kind::var : binding::kind::let;
    if (x.k == stmt::kind::const_) {
        if (!v.constant) fail(x.line, "const " + x.name + "'s value is not a const-expression: it uses a let, a var, a parameter or a function");
        b.k = binding::kind::constant;
        b.constant = true;
        b.v = v.v;
        std::string why;
        if (b.v.known && !convert_value(b.v, v.t, t, why)) fail(x.line, "const " + x.name + ": " + why);
        if (is_abstract(t)) {  // the uses of an abstract constant are literals
            b.t = t;
            declare(x.name, b, x.line);
            return "";
        }
    } else {
        t = concretized(t);
    }
    if (!supported_type(t)) fail(x.line, std::string(what) + " " + x.name + " is " + a_type(t) + ": outside the subset normzoo runs");
    b.t = t;
    b.glsl = new_local(x.name);
    const std::string init = has_value ? as(v, t, x.line) : zero_text(t);
    declare(x.name, b, x.line);
    return glsl_type(t, struct_glsl(t)) + " " + b.glsl + " = " + init;
}

std::string checker::assignment(const stmt& x) {
    if (x.name == "_") {
        const typed v = check(x.value);
        if (v.t.k == type::kind::none) fail(x.line, "_ = ...: the function called returns no value");
        return is_abstract(v.t) ? "" : v.text;
    }
    const typed target = check(x.target);
    if (!target.reference || target.swizzle) {
        const binding* b = target.root.empty() ? nullptr : lookup(target.root, x.line);
        std::string why = "this is no variable";
        if (target.swizzle) why = "a swizzle of several components is no reference in WGSL: assign the components one by one";
        else if (b && b->k == binding::kind::let) why = "'" + target.root + "' is a let or a parameter, which is immutable: declare it with var";
        else if (b && b->k == binding::kind::constant) why = "'" + target.root + "' is a const";
        else if (b && b->k == binding::kind::parameter) why = "'" + target.root + "' is a parameter of the header, which the code only reads";
        fail(x.line, "cannot assign: " + why);
    }
    const typed v = check(x.value);
    if (x.name == "=") {
        if (!converts(v.t, target.t)) fail(x.line, "cannot assign " + a_type(v.t) + " to " + a_type(target.t) + why_not(v.t, target.t));
        return target.text + " = " + as(v, target.t, x.line);
    }
    const std::string op = x.name.substr(0, x.name.size() - 1);
    if (op != "+" && op != "-" && op != "*" && op != "/" && op != "%") fail(x.line, "bitwise operators and shifts ('" + x.name + "') are outside the subset normzoo runs");
    typed current = target;
    current.constant = false, current.v.known = false;
    const typed r = arithmetic(op, current, v, x.line);
    if (r.t != target.t) fail(x.line, "'" + x.name + "' would make the " + type_name(target.t) + " " + a_type(r.t));
    return target.text + " = " + r.text;
}

std::string checker::simple(int s) {
    const stmt& x = st(s);
    switch (x.k) {
        case stmt::kind::var:
        case stmt::kind::let:
        case stmt::kind::const_: return declaration(x);
        case stmt::kind::assign: return assignment(x);
        case stmt::kind::increment:
        case stmt::kind::decrement: {
            const typed t = check(x.target);
            const char* op = x.k == stmt::kind::increment ? "++" : "--";
            if (t.t != scalar_type(scalar::i32) && t.t != scalar_type(scalar::u32))
                fail(x.line, std::string("'") + op + "' takes an i32 or u32, not " + a_type(t.t));
            if (!t.reference) fail(x.line, std::string("'") + op + "' takes a variable (var)");
            return t.text + op;
        }
        case stmt::kind::call: {
            const expr& c = ex(x.value);
            bool user = false;
            for (const auto& scope : scopes_) user = user || scope.count(c.text) > 0;
            const auto d = module_names_.find(c.text);
            user = !user && d != module_names_.end() && m_.decls[static_cast<std::size_t>(d->second)].k == declaration::kind::function;
            bool must_use = !user;
            if (user)
                for (const auto& a : m_.decls[static_cast<std::size_t>(d->second)].attrs) must_use = must_use || a.name == "must_use";
            const typed r = check(x.value);
            if (must_use) fail(x.line, "the value of " + c.text + "(...) is unused: WGSL refuses that (write _ = " + c.text + "(...) to drop it)");
            return r.text;
        }
        default: fail(x.line, "expected a statement");
    }
}

}  // namespace verify::wgsl
