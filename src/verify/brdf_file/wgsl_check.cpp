// The module: its names (#declaration-and-scope), its declarations checked as the BRDF reaches
// them, the BRDF's signature, and the GLSL put together line for line.
#include <algorithm>
#include <cctype>
#include <functional>
#include <set>

#include "../args.hpp"
#include "wgsl.hpp"
#include "wgsl_checker.hpp"

namespace verify::wgsl {

checker::checker(const shader_source& s, const module& m, std::string prefix)
    : s_(s), m_(m), prefix_(std::move(prefix)), state_(m.decls.size(), 0), decl_binding_(m.decls.size()),
      signature_(m.decls.size()), out_(m.decls.size()) {
    // the header's parameters: module-scope names to the code, as uniforms are to GLSL
    for (const auto& p : s.parameters) {
        binding b;
        b.k = binding::kind::parameter;
        b.t = p.type == shader_parameter::kind::real ? scalar_type(scalar::f32)
              : p.type == shader_parameter::kind::boolean ? scalar_type(scalar::boolean) : vector_type(3, scalar::f32);
        b.glsl = p.name;
        b.line = p.line;
        parameters_.emplace(p.name, b);
    }
}

void checker::fail(int line, const std::string& what) const {
    throw bad_input(s_.path + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what);
}

void checker::check_directives() {
    for (const auto& d : m_.directives) {
        if (d.name != "enable") continue;  // requires and diagnostic change nothing the subset has
        const std::string what = d.words.empty() ? "" : d.words[0];
        fail(d.line, "enable " + what + ": " + (what == "f16" ? "f16 is" : "the extensions WGSL enables are") +
                         " outside the subset normzoo runs (docs/brdf-code.md#wgsl)");
    }
}

void checker::declare_module_names() {
    for (std::size_t i = 0; i < m_.decls.size(); ++i) {
        const auto& d = m_.decls[i];
        if (d.k == declaration::kind::const_assert) continue;
        const auto [at, fresh] = module_names_.emplace(d.name, static_cast<int>(i));
        if (!fresh) fail(d.line, "'" + d.name + "' is declared twice at module scope (first on line " +
                                     std::to_string(m_.decls[static_cast<std::size_t>(at->second)].line) + ")");
        const bool uniform = d.k == declaration::kind::var && !d.templ.empty() && ex(d.templ[0]).text == "uniform";
        for (const auto& p : s_.parameters)
            if (p.name == d.name && !uniform)
                fail(d.line, "'" + d.name + "' is a parameter of the header (line " + std::to_string(p.line) +
                                 "), which the code reads as a module-scope name: it may not be declared again");
    }
}

const binding* checker::lookup(const std::string& name, int line) {
    for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s) {
        const auto f = s->find(name);
        if (f != s->end()) return &f->second;
    }
    const auto d = module_names_.find(name);
    if (d != module_names_.end()) return &module_binding(d->second, line);
    const auto p = parameters_.find(name);
    return p != parameters_.end() ? &p->second : nullptr;
}

const binding& checker::module_binding(int d, int line) {
    const auto& x = m_.decls[static_cast<std::size_t>(d)];
    binding& b = decl_binding_[static_cast<std::size_t>(d)];
    const int state = state_[static_cast<std::size_t>(d)];
    if (state == 2) return b;
    if (state == 1) {
        if (x.k == declaration::kind::function)
            fail(line, "fn " + x.name + " calls itself, directly or through another function: WGSL refuses recursion");
        fail(line, "'" + x.name + "' is defined through itself (line " + std::to_string(x.line) + "): WGSL refuses cycles among declarations");
    }
    if (++module_depth_ > max_nesting) fail(line, "declarations that reach more than " + std::to_string(max_nesting) + " deep: outside the subset normzoo reads");
    switch (x.k) {
        case declaration::kind::function: check_function(d); break;
        case declaration::kind::structure: check_struct(d); break;
        case declaration::kind::const_: check_const(d); break;
        case declaration::kind::var: check_var(d, line); break;
        case declaration::kind::alias: {
            state_[static_cast<std::size_t>(d)] = 1;
            b.k = binding::kind::alias;
            b.t = resolve_type(x.type);
            b.line = x.line;
            state_[static_cast<std::size_t>(d)] = 2;
            break;
        }
        case declaration::kind::override_:
            fail(line, "override " + x.name + " (line " + std::to_string(x.line) + "): pipeline-overridable constants are outside the subset "
                       "normzoo runs: use const, or a parameter of the header");
        case declaration::kind::const_assert: break;
    }
    --module_depth_;
    return b;
}

void checker::check_struct(int d) {
    const auto& x = m_.decls[static_cast<std::size_t>(d)];
    state_[static_cast<std::size_t>(d)] = 1;
    binding& b = decl_binding_[static_cast<std::size_t>(d)];
    b.k = binding::kind::structure;
    b.t.k = type::kind::structure;
    b.t.index = d;
    b.t.spelled = x.name;
    b.glsl = mangled(x.name);
    b.line = x.line;
    std::string text = "struct " + b.glsl + " {";
    std::set<std::string> seen;
    signature_[static_cast<std::size_t>(d)].clear();
    for (const auto& member : x.params) {
        for (const auto& a : member.attrs)
            if (a.name != "align" && a.name != "size" && a.name != "location" && a.name != "builtin" && a.name != "interpolate" &&
                a.name != "invariant" && a.name != "blend_src")
                fail(a.line, "@" + a.name + " is no attribute of a structure's member");
        if (!seen.insert(member.name).second) fail(member.line, "struct " + x.name + " has two members named " + member.name);
        const type t = resolve_type(member.type);
        if (t.k == type::kind::structure && t.index == d) fail(member.line, "struct " + x.name + " contains itself");
        signature_[static_cast<std::size_t>(d)].push_back(t);
        text += " " + glsl_type(t, struct_glsl(t)) + " " + mangled(member.name) + ";";
    }
    out_[static_cast<std::size_t>(d)].push_back({s_.first_line, text + " };"});
    struct_order_.push_back(d);
    state_[static_cast<std::size_t>(d)] = 2;
}

void checker::check_const(int d) {
    const auto& x = m_.decls[static_cast<std::size_t>(d)];
    state_[static_cast<std::size_t>(d)] = 1;
    const auto saved = std::move(scopes_);
    scopes_.clear();
    typed v = check(x.value);
    scopes_ = saved;
    if (!v.constant) fail(x.line, "const " + x.name + "'s value is not a const-expression: it uses a let, a var, a parameter or a function");
    type t = v.t;
    if (x.type >= 0) {
        t = resolve_type(x.type);
        if (!converts(v.t, t)) fail(x.line, "const " + x.name + ": a value of type " + type_name(v.t) + " is not " + a_type(t));
    }
    binding& b = decl_binding_[static_cast<std::size_t>(d)];
    b.k = binding::kind::constant;
    b.t = t;
    b.constant = true;
    b.line = x.line;
    b.v = v.v;
    std::string why;
    if (b.v.known && !convert_value(b.v, v.t, t, why)) fail(x.line, "const " + x.name + ": " + why);
    if (!is_abstract(t)) {
        // a function, so that code above its line reads it as GLSL reads only what is declared before
        b.glsl = mangled(x.name) + "()";
        const std::string head = glsl_type(t, struct_glsl(t)) + " " + b.glsl;
        prototypes_.push_back(head + ";");
        out_[static_cast<std::size_t>(d)].push_back({x.line, head + " { return " + as(v, t, x.line) + "; }"});
    }
    state_[static_cast<std::size_t>(d)] = 2;
}

void checker::check_var(int d, int use) {
    const auto& x = m_.decls[static_cast<std::size_t>(d)];
    const std::string space = x.templ.empty() ? "" : ex(x.templ[0]).text;
    if (space != "uniform") {
        const std::string what = space.empty() ? "var " + x.name + " (a texture or a sampler: a module-scope var without an address space)"
                                                : "var<" + space + "> " + x.name;
        fail(x.line, what + " is outside the subset normzoo runs: a BRDF reads the header's parameters, and const values "
                            "(docs/brdf-code.md#wgsl); read on line " + std::to_string(use));
    }
    state_[static_cast<std::size_t>(d)] = 1;
    if (x.type >= 0) {
        // a structure of parameters, as engines bind a material: read member by member
        const type t = resolve_type(x.type);
        if (t.k == type::kind::structure && !parameters_.count(x.name)) {
            binding& b = decl_binding_[static_cast<std::size_t>(d)];
            b.k = binding::kind::uniform_struct;
            b.t = t;
            b.line = x.line;
            state_[static_cast<std::size_t>(d)] = 2;
            return;
        }
    }
    const shader_parameter* p = nullptr;
    for (const auto& q : s_.parameters)
        if (q.name == x.name) p = &q;
    if (!p) fail(x.line, "var<uniform> " + x.name + " is not a parameter of the header: add [parameters." + x.name + "] to it (docs/brdf-code.md#plain-files)");
    const binding header = parameters_.at(x.name);
    const type t = x.type >= 0 ? resolve_type(x.type) : type{};
    if (p->type == shader_parameter::kind::boolean)
        fail(x.line, "var<uniform> " + x.name + ": the header's bool parameter is a module-scope name (bool is no uniform's type in WGSL); "
                     "do not declare it");
    if (t != header.t)
        fail(x.line, "var<uniform> " + x.name + " is " + a_type(t) + ", but the header's parameter (line " + std::to_string(p->line) +
                         ") is " + a_type(header.t));
    decl_binding_[static_cast<std::size_t>(d)] = header;
    state_[static_cast<std::size_t>(d)] = 2;
}

std::string checker::new_local(const std::string& name) {
    bool taken = module_names_.count(name) > 0;
    for (const auto& s : scopes_) taken = taken || s.count(name) > 0;
    for (const auto& p : s_.parameters) taken = taken || p.name == name;
    return taken ? prefix_ + "s" + std::to_string(++shadow_count_) + "_" + name : mangled(name);
}

void checker::declare(const std::string& name, binding b, int line) {
    auto& scope = scopes_.back();
    const auto at = scope.find(name);
    if (at != scope.end())
        fail(line, "'" + name + "' is declared twice in the same scope (first on line " + std::to_string(at->second.line) + ")");
    b.line = line;
    scope.emplace(name, std::move(b));
}

std::string checker::assemble() {
    std::vector<piece> all;
    for (int d : struct_order_) {
        for (const auto& p : out_[static_cast<std::size_t>(d)]) all.push_back(p);
        all.push_back({s_.first_line, maker(d)});
    }
    std::vector<std::string> order;
    std::function<void(const std::string&)> add = [&](const std::string& h) {
        if (std::find(order.begin(), order.end(), h) != order.end()) return;
        for (const auto& dep : helper_dependencies(h)) add(dep);
        order.push_back(h);
    };
    for (const auto& h : helpers_) add(h);
    for (const auto& h : order) all.push_back({s_.first_line, helper_text(h, prefix_)});
    for (const auto& p : prototypes_) all.push_back({s_.first_line, p});
    for (std::size_t d = 0; d < m_.decls.size(); ++d)
        if (m_.decls[d].k != declaration::kind::structure)
            for (const auto& p : out_[d]) all.push_back(p);
    const int lines = static_cast<int>(std::count(s_.code.begin(), s_.code.end(), '\n'));
    std::string o;
    int at = s_.first_line;
    for (const auto& p : all) {
        if (p.line > at) o.append(static_cast<std::size_t>(p.line - at), '\n'), at = p.line;
        if (!o.empty() && o.back() != '\n') o += ' ';
        o += p.text;
    }
    const int last = s_.first_line + std::max(lines, 1) - 1;
    o.append(static_cast<std::size_t>(std::max(0, last - at + 1)), '\n');
    return o;
}

std::string checker::run() {
    check_directives();
    declare_module_names();
    for (std::size_t d = 0; d < m_.decls.size(); ++d) {
        const auto& x = m_.decls[d];
        if (x.k != declaration::kind::const_assert) continue;
        const typed v = check(x.value);
        if (v.t != scalar_type(scalar::boolean) || !v.constant || !v.v.known)
            fail(x.line, "const_assert takes a bool const-expression");
        if (v.v.c.at(0) == 0) fail(x.line, "const_assert failed");
    }
    check_entry();
    return assemble();
}

}  // namespace verify::wgsl

namespace verify {

namespace {
// A prefix for the translation's names that no name in the file starts with: the file's names
// become PREFIX u NAME, the translation's helpers PREFIX h NAME, so none can meet a GLSL or C++
// name, nor each other.
std::string unused_prefix(const std::vector<wgsl::token>& tokens, const shader_source& s) {
    // a name blocks "wgsl" and "wgsl" followed by each start of the digits after it
    std::set<std::string> blocked;
    auto block = [&](const std::string& name) {
        if (name.compare(0, 4, "wgsl") != 0) return;
        std::size_t end = 4;
        while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
        for (std::size_t k = 4; k <= end; ++k) blocked.insert(name.substr(0, k));
    };
    for (const auto& t : tokens)
        if (t.k == wgsl::token::kind::ident) block(t.text);
    for (const auto& q : s.parameters) block(q.name);
    for (int k = 0;; ++k) {
        const std::string p = "wgsl" + (k ? std::to_string(k) : std::string());
        if (!blocked.count(p)) return p;
    }
}
}  // namespace

namespace {
// The names GLSL 1.20 and C++ keep for themselves, and the built-in functions the translation's
// GLSL calls: a header parameter keeps its name in the GLSL (a uniform) and the C++ (a member), so
// it may not take one of these.
bool glsl_or_cpp_name(const std::string& n) {
    static const std::set<std::string> names{
        // GLSL 1.20's keywords and reserved words, and those glslang reserves for later versions
        "attribute", "const", "uniform", "varying", "centroid", "break", "continue", "do", "for", "while", "if", "else", "in",
        "out", "inout", "float", "int", "void", "bool", "true", "false", "invariant", "discard", "return", "mat2", "mat3",
        "mat4", "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4", "vec2", "vec3",
        "vec4", "ivec2", "ivec3", "ivec4", "bvec2", "bvec3", "bvec4", "uvec2", "uvec3", "uvec4", "dvec2", "dvec3", "dvec4",
        "hvec2", "hvec3", "hvec4", "fvec2", "fvec3", "fvec4", "sampler1D", "sampler2D", "sampler3D", "samplerCube",
        "sampler1DShadow", "sampler2DShadow", "sampler2DRect", "sampler3DRect", "sampler2DRectShadow", "struct", "asm",
        "class", "union", "enum", "typedef", "template", "this", "packed", "goto", "switch", "default", "case", "inline",
        "noinline", "volatile", "public", "static", "extern", "external", "interface", "long", "short", "double", "half",
        "fixed", "unsigned", "uint", "lowp", "mediump", "highp", "precision", "input", "output", "sizeof", "cast",
        "namespace", "using", "flat", "smooth", "noperspective", "patch", "sample", "subroutine", "layout", "superp",
        "filter", "common", "partition", "active", "resource", "buffer", "shared", "coherent", "restrict", "readonly",
        "writeonly", "precise", "main",
        // GLSL 1.20's built-in functions
        "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "pow", "exp", "log", "exp2", "log2", "sqrt",
        "inversesqrt", "abs", "sign", "floor", "ceil", "fract", "mod", "min", "max", "clamp", "mix", "step", "smoothstep",
        "length", "distance", "dot", "cross", "normalize", "ftransform", "faceforward", "reflect", "refract",
        "matrixCompMult", "outerProduct", "transpose", "lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual",
        "equal", "notEqual", "any", "all", "not", "dFdx", "dFdy", "fwidth", "noise1", "noise2", "noise3", "noise4",
        // C++'s keywords the lists above leave out, and the translation's own names
        "alignas", "alignof", "and", "and_eq", "auto", "bitand", "bitor", "catch", "char", "char16_t", "char32_t", "compl",
        "constexpr", "const_cast", "decltype", "delete", "dynamic_cast", "explicit", "export", "friend", "mutable", "new",
        "noexcept", "not_eq", "nullptr", "operator", "or", "or_eq", "private", "protected", "register", "reinterpret_cast",
        "signed", "static_assert", "static_cast", "thread_local", "throw", "try", "typeid", "typename", "virtual",
        "wchar_t", "xor", "xor_eq", "real"};
    return names.count(n) > 0 || n.rfind("gl_", 0) == 0 || n.find("__") != std::string::npos;
}
}  // namespace

void translate_wgsl(shader_source& s, std::size_t memory_bytes) {
    for (const auto& p : s.parameters) {
        if (wgsl::reserved(p.name)) throw bad_input(s.path + ":" + std::to_string(p.line) + ": parameter " + p.name + ": '" + p.name + "' is a WGSL keyword or reserved word, which WGSL code cannot name");
        if (glsl_or_cpp_name(p.name))
            throw bad_input(s.path + ":" + std::to_string(p.line) + ": parameter " + p.name + ": the name is GLSL's or C++'s, which the translation of WGSL runs through: rename it (docs/brdf-code.md#wgsl)");
    }
    const auto tokens = wgsl::tokenize(s.path, s.code, s.first_line, memory_bytes / wgsl_bytes_per_token,
                                       std::to_string(memory_bytes >> 20) + " MB, NORMZOO_SHADER_MEMORY_MB");
    const wgsl::module m = wgsl::parse(s.path, tokens);
    wgsl::checker c(s, m, unused_prefix(tokens, s));
    const std::string glsl = c.run();
    s.function = c.entry_glsl();
    s.code = glsl;
    s.lang = shader_source::language::glsl;
}

}  // namespace verify
