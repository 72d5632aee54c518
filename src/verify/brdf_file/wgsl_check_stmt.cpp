// Functions and statements (#functions, #statements): scopes as WGSL draws them (a function's
// parameters and its body's outer statements share one, as a for's initializer and its body do),
// the behaviours of #behaviors (a function with a result returns one on every path; a loop ends),
// and the GLSL of each statement on the statement's own line.
#include "wgsl_checker.hpp"

namespace verify::wgsl {

void checker::check_signature(int d) {
    const auto& x = m_.decls[static_cast<std::size_t>(d)];
    for (const auto& a : x.attrs) {
        if (a.name == "vertex" || a.name == "fragment" || a.name == "compute")
            fail(a.line, "fn " + x.name + " is an entry point (@" + a.name + "), which no function calls in WGSL: the BRDF and its helpers are plain fns");
        if (a.name != "must_use" && a.name != "diagnostic") fail(a.line, "@" + a.name + " is outside the subset normzoo runs on a function");
    }
    if (!x.return_attrs.empty()) fail(x.line, "fn " + x.name + ": attributes on a result (@" + x.return_attrs[0].name + ") belong to entry points");
    auto& sig = signature_[static_cast<std::size_t>(d)];
    sig.clear();
    for (const auto& p : x.params) {
        if (!p.attrs.empty()) fail(p.line, "parameter " + p.name + ": attributes (@" + p.attrs[0].name + ") belong to entry points");
        sig.push_back(resolve_type(p.type));
        if (!supported_type(sig.back())) fail(p.line, "parameter " + p.name + " is " + a_type(sig.back()) + ": outside the subset normzoo runs");
    }
    sig.push_back(x.type >= 0 ? resolve_type(x.type) : type{});
    binding& b = decl_binding_[static_cast<std::size_t>(d)];
    b.k = binding::kind::function;
    b.glsl = mangled(x.name);
    b.line = x.line;
}

void checker::check_function(int d) {
    const auto& x = m_.decls[static_cast<std::size_t>(d)];
    state_[static_cast<std::size_t>(d)] = 1;
    check_signature(d);
    const auto& sig = signature_[static_cast<std::size_t>(d)];
    // the caller's state: a function is checked when first called
    auto scopes = std::move(scopes_);
    const type return_type = return_type_;
    const bool has_return = has_return_type_, continuing = in_continuing_, splat = splat_return_;
    const int loops = loop_depth_;
    auto continued = std::move(loop_continued_);
    auto* pieces = pieces_;
    scopes_.assign(1, {});
    return_type_ = sig.back();
    has_return_type_ = x.type >= 0;
    // a BRDF of one channel returns its three equal channels: what the pipeline takes of any BRDF
    splat_return_ = x.name == s_.function && return_type_ == scalar_type(scalar::f32);
    in_continuing_ = false;
    loop_depth_ = 0;
    loop_continued_.clear();
    pieces_ = &out_[static_cast<std::size_t>(d)];
    if (has_return_type_ && !supported_type(return_type_)) fail(x.line, "fn " + x.name + " returns " + a_type(return_type_) + ": outside the subset normzoo runs");
    std::string head = (splat_return_ ? "vec3" : has_return_type_ ? glsl_type(return_type_, struct_glsl(return_type_)) : "void") + " " +
                       mangled(x.name) + "(";
    for (std::size_t i = 0; i < x.params.size(); ++i) {
        binding b;
        b.k = binding::kind::let;
        b.t = sig[i];
        b.glsl = new_local(x.params[i].name);
        head += (i ? ", " : "") + glsl_type(sig[i], struct_glsl(sig[i])) + " " + b.glsl;
        declare(x.params[i].name, b, x.params[i].line);
    }
    head += ")";
    emit(x.line, head + " {");
    const unsigned b = statements(st(x.body).body);
    if (has_return_type_ && b != returns)
        fail(x.end_line, "fn " + x.name + " returns " + a_type(return_type_) + ", but the end of its body is reachable: return a value on every path");
    emit(x.end_line, "}");
    prototypes_.push_back(head + ";");
    scopes_ = std::move(scopes);
    return_type_ = return_type;
    has_return_type_ = has_return;
    splat_return_ = splat;
    in_continuing_ = continuing;
    loop_depth_ = loops;
    loop_continued_ = std::move(continued);
    pieces_ = pieces;
    state_[static_cast<std::size_t>(d)] = 2;
}

void checker::check_entry() {
    const auto f = module_names_.find(s_.function);
    const std::string shape = "fn " + s_.function + "(L: vec3<f32>, V: vec3<f32>, N: vec3<f32>, X: vec3<f32>, Y: vec3<f32>) -> vec3<f32> (or -> f32)";
    if (f == module_names_.end() || m_.decls[static_cast<std::size_t>(f->second)].k != declaration::kind::function)
        fail(0, "no " + shape + " (docs/brdf-code.md#wgsl)");
    const int d = f->second;
    const auto& x = m_.decls[static_cast<std::size_t>(d)];
    check_signature(d);
    const auto& sig = signature_[static_cast<std::size_t>(d)];
    bool ok = sig.size() == 6;
    for (std::size_t i = 0; ok && i < 5; ++i) ok = sig[i] == vector_type(3, scalar::f32);
    ok = ok && (sig.back() == vector_type(3, scalar::f32) || sig.back() == scalar_type(scalar::f32));
    if (!ok) fail(x.line, "the BRDF must be " + shape);
    module_binding(d, x.line);
}

unsigned checker::statements(const std::vector<int>& list) {
    unsigned b = next;
    for (int s : list) {
        const unsigned one = statement(s);
        if (b & next) b = (b & ~static_cast<unsigned>(next)) | one;
    }
    return b;
}

unsigned checker::block(int s, bool new_scope) {
    const stmt& x = st(s);
    emit(x.line, "{");
    if (new_scope) scopes_.emplace_back();
    const unsigned b = statements(x.body);
    if (new_scope) scopes_.pop_back();
    emit(x.end_line, "}");
    return b;
}

typed checker::condition(int e, const char* what) {
    const typed c = check(e);
    if (c.t != scalar_type(scalar::boolean)) fail(ex(e).line, std::string(what) + "'s condition is a bool, not " + a_type(c.t));
    return c;
}

unsigned checker::statement(int s) {
    const stmt& x = st(s);
    switch (x.k) {
        case stmt::kind::empty: return next;
        case stmt::kind::block: return block(s);
        case stmt::kind::if_: return if_statement(s);
        case stmt::kind::loop: return loop_statement(s);
        case stmt::kind::for_: return for_statement(s);
        case stmt::kind::while_: return while_statement(s);
        case stmt::kind::return_: {
            if (in_continuing_) fail(x.line, "return is not allowed in a continuing block");
            if (x.value < 0) {
                if (has_return_type_) fail(x.line, "return needs a value: the function returns " + a_type(return_type_));
                emit(x.line, "return;");
                return returns;
            }
            const typed v = check(x.value);
            if (!has_return_type_) fail(x.line, "this function has no result ('->'): return takes no value here");
            if (!converts(v.t, return_type_)) fail(x.line, "returns " + a_type(v.t) + ", but the function's result is " + a_type(return_type_) + why_not(v.t, return_type_));
            const std::string value = as(v, return_type_, x.line);
            emit(x.line, "return " + (splat_return_ ? "vec3(" + value + ")" : value) + ";");
            return returns;
        }
        case stmt::kind::break_:
        case stmt::kind::continue_: {
            const bool brk = x.k == stmt::kind::break_;
            if (loop_depth_ == 0) fail(x.line, std::string(brk ? "break" : "continue") + " outside a loop");
            if (in_continuing_) fail(x.line, brk ? "a continuing block ends with 'break if', never 'break'" : "continue is not allowed in a continuing block");
            if (!brk && !loop_continued_.empty() && !loop_continued_.back()) loop_continued_.back() = x.line != 0;
            emit(x.line, brk ? "break;" : "continue;");
            return brk ? breaks : continues;
        }
        case stmt::kind::break_if: fail(x.line, "'break if' may only end a loop's continuing block");
        case stmt::kind::discard: fail(x.line, "discard is outside the subset normzoo runs: a BRDF is a function of directions");
        case stmt::kind::switch_: fail(x.line, "switch is outside the subset normzoo runs: write it as if / else");
        case stmt::kind::const_assert: {
            const typed c = check(x.value);
            if (c.t != scalar_type(scalar::boolean) || !c.constant || !c.v.known) fail(x.line, "const_assert takes a bool const-expression");
            if (c.v.c.at(0) == 0) fail(x.line, "const_assert failed");
            return next;
        }
        default: {
            const std::string text = simple(s);
            if (!text.empty()) emit(x.line, text + ";");
            return next;
        }
    }
}

unsigned checker::if_statement(int s) {
    const stmt& x = st(s);
    const typed c = condition(x.value, "if");
    emit(x.line, "if (" + c.text + ")");
    unsigned b = block(x.body[0]);
    if (x.else_ < 0) return b | next;
    const stmt& e = st(x.else_);
    emit(e.line, "else");
    return b | (e.k == stmt::kind::if_ ? if_statement(x.else_) : block(x.else_));
}

unsigned checker::loop_statement(int s) {
    const stmt& x = st(s);
    ++loop_depth_;
    loop_continued_.push_back(false);
    emit(x.line, "for (;;) {");
    scopes_.emplace_back();
    const unsigned body = statements(x.body);
    unsigned cont = next;
    if (x.has_continuing) {
        if (loop_continued_.back())
            fail(x.continuing_line, "continue in a loop with a continuing block is outside the subset normzoo runs: move the continuing "
                                    "statements before each continue, or write a for loop");
        in_continuing_ = true;
        scopes_.emplace_back();
        std::vector<int> list = x.continuing;
        int tail = -1;
        if (!list.empty() && st(list.back()).k == stmt::kind::break_if) tail = list.back(), list.pop_back();
        cont = statements(list);
        if (tail >= 0) {
            const typed c = condition(st(tail).value, "break if");
            emit(st(tail).line, "if (" + c.text + ") break;");
            cont |= breaks | next;
        }
        scopes_.pop_back();
        in_continuing_ = false;
    }
    scopes_.pop_back();
    emit(x.end_line, "}");
    loop_continued_.pop_back();
    --loop_depth_;
    if (cont & (continues | returns)) fail(x.continuing_line, "a continuing block may not continue or return");
    if (body == returns) return returns;
    const unsigned all = body | cont;
    if (!(all & breaks)) {
        const unsigned b = all & ~static_cast<unsigned>(continues | next);
        if (b == 0) fail(x.line, "this loop never ends: it has no break and no return (WGSL refuses it)");
        return b;
    }
    return (all | next) & ~static_cast<unsigned>(breaks | continues);
}

unsigned checker::for_statement(int s) {
    const stmt& x = st(s);
    scopes_.emplace_back();  // the initializer's, which the body shares
    const std::string init = x.init >= 0 ? simple(x.init) : "";
    const std::string cond = x.value >= 0 ? condition(x.value, "for").text : "";
    ++loop_depth_;
    loop_continued_.push_back(false);
    const std::string update = x.update >= 0 ? simple(x.update) : "";
    if (x.update >= 0 && (st(x.update).k == stmt::kind::var || st(x.update).k == stmt::kind::let || st(x.update).k == stmt::kind::const_))
        fail(x.line, "a for loop's update may not declare");
    emit(x.line, "for (" + init + "; " + cond + "; " + update + ")");
    const stmt& body = st(x.body[0]);
    emit(body.line, "{");
    unsigned b = statements(body.body);
    emit(body.end_line, "}");
    scopes_.pop_back();
    loop_continued_.pop_back();
    --loop_depth_;
    if (x.value >= 0) b |= breaks;
    if (!(b & breaks)) {
        const unsigned r = b & ~static_cast<unsigned>(continues | next);
        if (r == 0) fail(x.line, "this loop never ends: it has no condition, no break and no return (WGSL refuses it)");
        return r;
    }
    return (b | next) & ~static_cast<unsigned>(breaks | continues);
}

unsigned checker::while_statement(int s) {
    const stmt& x = st(s);
    const typed c = condition(x.value, "while");
    ++loop_depth_;
    loop_continued_.push_back(false);
    emit(x.line, "while (" + c.text + ")");
    const unsigned b = block(x.body[0]);
    loop_continued_.pop_back();
    --loop_depth_;
    return (b | next) & ~static_cast<unsigned>(breaks | continues);
}

}  // namespace verify::wgsl
