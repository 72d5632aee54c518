#include "shader_analysis.hpp"

#include <algorithm>
#include <set>

#include "../args.hpp"

namespace verify {

namespace {

constexpr std::size_t none = token_list::none;

[[noreturn]] void refuse(const shader_source& s, int line, const std::string& what) { throw bad_input(s.place(line) + ": " + what); }

// "", "3" or "3x3" from `from` on: the dimensions a type name ends in.
bool dimensions(const std::string& w, std::size_t from) {
    const std::string d = w.substr(from);
    auto digit = [](char c) { return c >= '1' && c <= '4'; };
    return d.empty() || (d.size() == 1 && digit(d[0])) || (d.size() == 3 && digit(d[0]) && d[1] == 'x' && digit(d[2]));
}

bool starts(const std::string& w, const std::string& prefix) { return w.size() >= prefix.size() && w.compare(0, prefix.size(), prefix) == 0; }

const std::set<std::string>& qualifiers() {
    static const std::set<std::string> q{"const", "static", "inline", "precise", "highp", "mediump", "lowp", "uniform", "in", "out",
                                         "inout", "extern", "volatile", "invariant", "flat", "smooth", "noperspective", "centroid",
                                         "nointerpolation", "groupshared", "row_major", "column_major", "linear", "snorm", "unorm"};
    return q;
}

// The first token at or after i that is not a space.
std::size_t significant(const token_list& t, std::size_t i) {
    if (i >= t.size()) return none;
    return t[i].type == token::space ? t.next(i) : i;
}

// After layout(...) and qualifiers: the declaration's type token (i's direction and precision in d).
std::size_t skip_qualifiers(const token_list& t, std::size_t i, std::size_t e, shader_declared& d) {
    while (i < e && t.is_word(i)) {
        const std::string& w = t[i].text;
        if (w == "layout" && t.is(t.next(i), "(")) {
            i = t.next(t.match(t.next(i)));
            continue;
        }
        if (!qualifiers().count(w)) break;
        if (w == "out") d.dir = shader_declared::direction::out;
        if (w == "inout") d.dir = shader_declared::direction::inout;
        if (is_reduced_precision(w)) d.reduced_precision = true;
        i = t.next(i);
    }
    return i;
}

// A declaration's tokens [b, e): qualifiers, a type, then its declarators, each NAME [dims]
// [: semantic] [= initializer], separated by commas. A parameter may have no name.
std::vector<shader_declared> declarators(const token_list& t, std::size_t b, std::size_t e, bool unnamed = false) {
    std::vector<shader_declared> out;
    shader_declared base;
    std::size_t i = skip_qualifiers(t, significant(t, b), e, base);
    if (i >= e || !t.is_word(i)) return out;
    base.type = t[i].text;
    base.line = t.line(i);
    base.end = i;
    base.reduced_precision = base.reduced_precision || is_reduced_precision(base.type);
    i = t.next(i);
    if (i < e && t.is(i, "<")) {  // Texture2D<float2>
        for (i = t.next(i); i < e && !t.is(i, ">"); i = t.next(i)) base.element += t[i].text;
        base.end = i, i = t.next(i);
    }
    while (i < e && t.is(i, "[")) base.array = true, base.end = t.match(i), i = t.next(t.match(i));
    while (i < e) {
        shader_declared d = base;
        if (t.is_word(i)) {
            d.name = t[i].text, d.end = i, d.line = t.line(i);
            i = t.next(i);
        } else if (!unnamed) {
            break;
        }
        while (i < e && t.is(i, "[")) d.array = true, d.end = t.match(i), i = t.next(t.match(i));
        out.push_back(d);
        while (i < e && !t.is(i, ",")) i = t.next(t.is(i, "(") || t.is(i, "[") || t.is(i, "{") ? t.match(i) : i);
        if (i >= e) break;
        i = t.next(i);
    }
    return out;
}

// The end of the top-level statement that starts at i: its ';', or the '}' of a function's body
// (`body`) or of a cbuffer, which needs no ';'.
std::size_t statement_end(const token_list& t, std::size_t i, bool& body) {
    body = false;
    const bool buffer = t.is(i, "cbuffer") || t.is(i, "tbuffer");
    bool paren = false;
    std::size_t last = i;
    for (std::size_t j = i; j < t.size(); j = t.next(j)) {
        last = j;
        if (t[j].type != token::punct) continue;
        const char c = t[j].text[0];
        if (c == ';') return j;
        if (c == '(' || c == '[') {
            paren = paren || c == '(';
            j = t.match(j);
        } else if (c == '{') {
            const std::size_t close = t.match(j);
            if (buffer) return t.is(t.next(close), ";") ? t.next(close) : close;
            if (paren) {
                body = true;
                return close;
            }
            j = close;  // struct S { ... } s; : on to its ;
        }
        last = j;
    }
    return last;
}

// The calls each function makes to the file's own functions, with their number of arguments.
void find_calls(const token_list& t, shader_analysis& a) {
    const std::set<std::string> names(a.declared.begin(), a.declared.end());
    for (auto& f : a.functions)
        for (std::size_t j = f.open; j < f.close; ++j) {
            if (!t.is_word(j) || !names.count(t[j].text) || t.is(t.prev(j), ".")) continue;
            const std::size_t open = t.next(j);
            if (!t.is(open, "(")) continue;
            const std::size_t close = t.match(open);
            std::size_t arity = t.next(open) == close ? 0 : 1;
            for (std::size_t k = open + 1; k < close; ++k) arity += t.is(k, ",") && t.parent(k) == open;
            f.calls.push_back({t[j].text, arity, t.line(j)});
        }
}

void read_function(const token_list& t, std::size_t i, std::size_t close, bool reduced_default, shader_analysis& a) {
    shader_function f;
    f.first = i;
    f.close = close;
    f.open = t.match(close);
    std::size_t paren = i;
    while (paren < f.open && !t.is(paren, "(")) paren = t.next(paren);
    const std::size_t name = t.prev(paren);
    if (!t.is_word(name)) return;
    f.name = t[name].text;
    f.line = t.line(name);
    shader_declared ignored;
    for (std::size_t k = skip_qualifiers(t, i, name, ignored); k < name; k = t.next(k)) f.return_type += t[k].text;
    const std::size_t end = t.match(paren);
    for (std::size_t b = paren + 1; b < end;) {
        std::size_t e = b;
        while (e < end && !(t.is(e, ",") && t.parent(e) == paren)) ++e;
        const auto d = declarators(t, b, e, true);
        if (!d.empty() && !(d[0].type == "void" && d[0].name.empty())) f.params.push_back(d[0]);
        b = e + 1;
    }
    f.reduced_precision = reduced_default;
    for (std::size_t k = i; k <= close; ++k) f.reduced_precision = f.reduced_precision || (t.is_word(k) && is_reduced_precision(t[k].text));
    a.functions.push_back(f);
    a.declared.push_back(f.name);
}

void read_structs(const token_list& t, shader_analysis& a) {
    for (std::size_t j = 0; j < t.size(); ++j) {
        if (!t.is(j, "struct")) continue;
        const std::size_t name = t.next(j), open = t.next(name);
        if (!t.is_word(name) || !t.is(open, "{")) continue;
        shader_struct s{t[name].text, t.line(name), open, t.match(open), t.parent(j) != none, {}};
        for (std::size_t b = open + 1; b < s.close;) {
            std::size_t e = b;
            while (e < s.close && !(t.is(e, ";") && t.parent(e) == open)) ++e;
            for (const auto& d : declarators(t, b, e)) s.fields.push_back(d);
            b = e + 1;
        }
        a.structs.push_back(s);
    }
}

// HLSL's attributes before a statement ([unroll], [branch], [loop(4)]): C++ has none of them.
void remove_attributes(const token_list& t, shader_analysis& a) {
    for (std::size_t j = 0; j < t.size(); ++j) {
        if (!t.is(j, "[") || !t.is_word(t.next(j)) || t.parent(j) == none) continue;
        const std::size_t p = t.prev(j);
        if (t.is(p, ";") || t.is(p, "{") || t.is(p, "}")) a.removed.push_back({j, t.match(j)});
    }
}

// = followed by what C++ computes at compile time as the code does: integer literals, true and
// false, operators, and the integer constants before it (const int N = 2 * M + 1).
bool constant_expression(const token_list& t, std::size_t equals, std::size_t end, const shader_analysis& a) {
    if (!t.is(equals, "=")) return false;
    for (std::size_t k = t.next(equals); k < end; k = t.next(k)) {
        const token& x = t[k];
        const bool hex = x.text.size() > 1 && x.text[0] == '0' && (x.text[1] == 'x' || x.text[1] == 'X');
        if (x.type == token::number && !hex && x.text.find_first_of(".eEfF") != std::string::npos) return false;
        if (x.type == token::punct && std::string("()+-*/%<>=!&|^~?:").find(x.text) == std::string::npos) return false;
        if (x.type == token::word && x.text != "true" && x.text != "false" &&
            std::none_of(a.constant_integers.begin(), a.constant_integers.end(), [&](std::size_t c) {
                std::size_t n = t.next(t.next(c));  // const TYPE NAME
                while (t.is_word(n) && t.is_word(t.next(n))) n = t.next(n);
                return t.is_word(n) && t[n].text == x.text;
            }))
            return false;
        if (x.type == token::directive) return false;
    }
    return true;
}

void note_reduced(shader_analysis& a, int line) {
    if (!a.reduced_precision) a.reduced_precision = true, a.reduced_precision_line = line;
}

// A statement at the file's top level, from i to end.
void read_top(const shader_source& s, const token_list& t, std::size_t i, std::size_t end, bool body, bool& reduced_default,
              shader_analysis& a) {
    const bool hlsl = s.lang == shader_source::language::hlsl;
    const std::string& first = t[i].text;
    if (first == "precision") {
        bool reduced = false, for_float = false;
        for (std::size_t k = i; k < end; k = t.next(k)) reduced = reduced || is_reduced_precision(t[k].text), for_float = for_float || t.is(k, "float");
        if (for_float) reduced_default = reduced;
        if (reduced) note_reduced(a, t.line(i));
        a.removed.push_back({i, end});
        return;
    }
    if (first == "cbuffer" || first == "tbuffer") {
        std::size_t open = i;
        while (open < end && !t.is(open, "{")) open = t.next(open);
        const std::size_t close = t.is(open, "{") ? t.match(open) : 0;  // no braces: no members
        for (std::size_t b = open + 1; b < close;) {
            std::size_t e = b;
            while (e < close && !(t.is(e, ";") && t.parent(e) == open)) ++e;
            for (auto d : declarators(t, b, e)) a.uniforms.push_back(d);
            b = e + 1;
        }
        a.removed.push_back({i, end});
        return;
    }
    std::size_t k = i;
    bool is_static = false, is_const = false, uniform = false, has_equal = false, paren = false;
    std::size_t const_token = none, brace = none;
    for (std::size_t j = i; j < end; j = t.next(j)) {
        if (t.is(j, "=")) has_equal = true;
        // a call's or a function's parentheses, not layout(...) nor HLSL's : register(t0)
        const bool binding = t.is(t.prev(j), "layout") || t.is(t.prev(j), "register") || t.is(t.prev(j), "packoffset");
        if (t.is(j, "(") && !has_equal && !binding) paren = true;
        if (t.is(j, "{") && brace == none) brace = j;
        if (t.is(j, "(") || t.is(j, "[") || t.is(j, "{")) j = t.match(j);
    }
    for (; k < end && t.is_word(k) && (qualifiers().count(t[k].text) || t.is(k, "layout")); k = t.next(k)) {
        if (t.is(k, "layout")) k = t.match(t.next(k));
        is_static = is_static || t.is(k, "static");
        uniform = uniform || t.is(k, "uniform");
        if (t.is(k, "const")) is_const = true, const_token = k;
        if (t.is(k, "in") || t.is(k, "out") || t.is(k, "varying") || t.is(k, "attribute"))
            refuse(s, t.line(k), "a shader input or output (" + t[k].text + " " + (k + 1 < end ? t[t.next(k)].text : "") +
                                     " ...) is outside what normzoo runs: the BRDF takes its vectors as parameters");
    }
    if (t.is(k, "varying") || t.is(k, "attribute"))
        refuse(s, t.line(k), "a shader input (" + t[k].text + ") is outside what normzoo runs: the BRDF takes its vectors as parameters");
    if (uniform && brace != none)
        refuse(s, t.line(brace), "a uniform block (uniform NAME { ... }) is outside what normzoo reads: declare each parameter as its own "
                                 "uniform (uniform float roughness;), bound to the header's parameter of that name");
    if (first == "struct" && !paren) return;
    if (body) {
        read_function(t, i, end, reduced_default, a);
        return;
    }
    if (paren && !uniform) {  // a prototype: C++ needs none in a class
        std::size_t p = i;
        while (p < end && !t.is(p, "(")) p = t.next(p);
        if (t.is_word(t.prev(p))) a.declared.push_back(t[t.prev(p)].text);
        a.removed.push_back({i, end});
        return;
    }
    const auto decls = declarators(t, i, end);
    for (const auto& d : decls)
        if (d.reduced_precision) note_reduced(a, d.line);
    // HLSL's globals are uniforms unless static or const (docs/brdf-code.md#uniforms-and-cbuffers)
    if (uniform || (hlsl && !is_static && !is_const && !has_equal && !decls.empty())) {
        for (const auto& d : decls) a.uniforms.push_back(d);
        a.removed.push_back({i, end});
        return;
    }
    if (is_const && decls.size() == 1 && !decls[0].array &&
        (decls[0].type == "int" || decls[0].type == "uint" || decls[0].type == "bool" || decls[0].type == "dword") &&
        constant_expression(t, t.next(decls[0].end), end, a))
        a.constant_integers.push_back(const_token);
}

}  // namespace

bool is_builtin_type(const std::string& w, shader_source::language lang) {
    if (w == "void" || w == "bool" || w == "int" || w == "uint" || w == "float" || w == "double") return true;
    for (const char* v : {"vec", "ivec", "uvec", "bvec", "dvec"})
        if (starts(w, v) && w.size() == std::string(v).size() + 1 && w.back() >= '2' && w.back() <= '4') return true;
    for (const char* m : {"mat", "dmat"})
        if (starts(w, m) && w.size() > std::string(m).size() && dimensions(w, std::string(m).size()) && w[std::string(m).size()] != '1')
            return true;
    if (lang != shader_source::language::hlsl) return false;
    for (const char* b : {"float", "half", "int", "uint", "bool", "double", "dword", "min16float", "min10float", "min16int", "min12int",
                          "min16uint"})
        if (starts(w, b) && dimensions(w, std::string(b).size())) return true;
    return false;
}

bool is_reduced_precision(const std::string& w) {
    if (w == "mediump" || w == "lowp" || w == "float16_t") return true;
    if (starts(w, "half")) return dimensions(w, 4);
    if (starts(w, "min16float") || starts(w, "min10float")) return dimensions(w, 10);
    return starts(w, "f16vec") && w.size() == 7;
}

shader_analysis analyze_shader(const shader_source& s, const token_list& t) {
    if (t.unbalanced() != none) {
        const std::size_t u = t.unbalanced();
        const std::string b = t[u].text;
        refuse(s, t.line(u), b == "(" || b == "[" || b == "{" ? "this " + b + " is never closed" : "this " + b + " closes nothing");
    }
    shader_analysis a;
    read_structs(t, a);
    if (s.lang == shader_source::language::hlsl) remove_attributes(t, a);
    // the default precision of float the file's precision statements set, which the preprocessor
    // drops (preprocess.hpp): for every function, as it is declared at the file's start
    bool reduced_default = s.float_precision == "mediump" || s.float_precision == "lowp";
    if (reduced_default) a.reduced_precision = true;
    for (std::size_t i = significant(t, 0); i < t.size();) {
        if (t[i].type == token::directive) {
            i = t.next(i);
            continue;
        }
        bool body = false;
        const std::size_t end = statement_end(t, i, body);
        if (!t.is(i, ";")) read_top(s, t, i, end, body, reduced_default, a);
        i = t.next(end);
    }
    for (std::size_t j = 0; j < t.size(); ++j)
        if (t.is_word(j) && is_reduced_precision(t[j].text) && (!a.reduced_precision || (a.reduced_precision_line && t.line(j) < a.reduced_precision_line)))
            a.reduced_precision = true, a.reduced_precision_line = t.line(j);
    find_calls(t, a);
    return a;
}

}  // namespace verify
