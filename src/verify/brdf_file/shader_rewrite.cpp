#include "shader_rewrite.hpp"

#include <cctype>
#include <map>

#include "../args.hpp"

namespace verify {

namespace {

constexpr std::size_t none = token_list::none;

bool is_float_literal(const std::string& t) {
    if (t.size() > 1 && (t[0] == '0') && (t[1] == 'x' || t[1] == 'X')) return false;
    return t.find_first_of(".eE") != std::string::npos || t.back() == 'f' || t.back() == 'F';
}

std::string float_literal(std::string t) {
    while (!t.empty() && (t.back() == 'f' || t.back() == 'F' || t.back() == 'l' || t.back() == 'L' || t.back() == 'h' || t.back() == 'H')) t.pop_back();
    if (t.back() == '.') t += "0";
    if (t.front() == '.') t = "0" + t;
    return "real(" + t + ")";
}

// The word each shading language's type or name becomes. HLSL's matrices floatRxC are GLM's
// mat<R, C> (their rows as GLM's columns: glsl_prelude.hpp, mul).
std::string mapped(const std::string& w, shader_source::language lang) {
    static const std::map<std::string, std::string> common{{"float", "real"}, {"in", ""},      {"highp", ""},
                                                           {"mediump", ""},   {"lowp", ""},   {"precise", ""}};
    static const std::map<std::string, std::string> hlsl{{"half", "real"}, {"min16float", "real"}, {"min10float", "real"},
                                                         {"static", ""},   {"inline", ""},        {"dword", "uint"},
                                                         {"min16int", "int"}, {"min16uint", "uint"}};
    if (lang == shader_source::language::hlsl) {
        const auto h = hlsl.find(w);
        if (h != hlsl.end()) return h->second;
        // float3 -> vec3, int2 -> ivec2, half3x3 -> mat3x3, float1 -> real
        for (const auto& [base, glsl] : std::map<std::string, std::string>{{"float", "vec"}, {"half", "vec"}, {"min16float", "vec"},
                                                                           {"min10float", "vec"}, {"int", "ivec"}, {"uint", "uvec"},
                                                                           {"bool", "bvec"}, {"min16int", "ivec"}, {"min16uint", "uvec"}}) {
            if (w.compare(0, base.size(), base) != 0 || w.size() <= base.size()) continue;
            const std::string d = w.substr(base.size());
            auto digit = [](char c) { return c >= '1' && c <= '4'; };
            if (d.size() == 1 && d[0] == '1') return glsl == "vec" ? "real" : glsl == "ivec" ? "int" : glsl == "uvec" ? "uint" : "bool";
            if (d.size() == 1 && digit(d[0])) return glsl + d;
            if (d.size() == 3 && digit(d[0]) && d[1] == 'x' && digit(d[2]) && glsl == "vec") return "mat" + d;
        }
    }
    const auto c = common.find(w);
    return c != common.end() ? c->second : w;
}

// Names a shader may use that C++ reserves, or that the translation itself defines (real).
const std::set<std::string>& cpp_reserved() {
    static const std::set<std::string> r{
        "new", "delete", "and", "or", "xor", "bitand", "bitor", "compl", "and_eq", "or_eq", "xor_eq", "not_eq", "auto", "register",
        "mutable", "explicit", "friend", "operator", "protected", "virtual", "try", "catch", "throw", "typeid", "typename", "wchar_t",
        "char", "signed", "alignas", "alignof", "constexpr", "decltype", "noexcept", "nullptr", "static_assert", "thread_local",
        "char8_t", "char16_t", "char32_t", "const_cast", "dynamic_cast", "reinterpret_cast", "static_cast", "export", "concept",
        "requires", "co_await", "co_return", "co_yield", "consteval", "constinit", "real", "library", "std", "glm"};
    return r;
}

}  // namespace

std::string cpp_name(const std::string& w) {
    if (w == "not") return "normzoo_not";
    return cpp_reserved().count(w) ? "normzoo_id_" + w : w;
}

int swizzle_set(const std::string& w) {
    if (w.empty() || w.size() > 4) return -1;
    const char* sets[] = {"xyzw", "rgba", "stpq"};
    for (int k = 0; k < 3; ++k)
        if (w.find_first_not_of(sets[k]) == std::string::npos) return k;
    return -1;
}

std::vector<int> swizzle_components(const std::string& w) {
    const std::string sets[] = {"xyzw", "rgba", "stpq"};
    std::vector<int> c;
    for (char ch : w) c.push_back(static_cast<int>(sets[swizzle_set(w)].find(ch)));
    return c;
}

shader_rewriter::shader_rewriter(const shader_source& src, const token_list& tokens, const shader_analysis& an, std::set<std::string>& sw)
    : s(src), t(tokens), a(an), swizzles(sw), out(tokens.size()), reference(tokens.size(), false) {}

void shader_rewriter::refuse(std::size_t i, const std::string& what) const {
    throw bad_input(s.place(t.line(i)) + ": " + what + " (docs/brdf-code.md#what-is-supported)");
}

bool shader_rewriter::is_type(std::size_t i) const {
    if (!t.is_word(i)) return false;
    if (is_builtin_type(t[i].text, s.lang)) return true;
    for (const auto& st : a.structs)
        if (st.name == t[i].text) return true;
    return false;
}

// Each token's own C++: types and names mapped, float literals in the number type, out and inout
// as references.
void shader_rewriter::words() {
    bool reference_next = false;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const token& k = t[i];
        out[i] = k.text;
        if (k.type == token::number && is_float_literal(k.text)) out[i] = float_literal(k.text);
        // the preprocessor leaves none (preprocess.hpp): the code around the file's never meets its macros
        if (k.type == token::directive) throw bad_input(s.place(t.line(i)) + ": a directive reached the translation unpreprocessed");
        if (k.type != token::word) continue;
        if (t.is(t.prev(i), ".")) {  // a member: its name as its declaration's
            out[i] = cpp_name(k.text);
            continue;
        }
        if (k.text == "out" || k.text == "inout") {
            reference_next = true;
            out[i] = " ";  // not "": the tokens beside it must not join (/inout* would make /*)
            continue;
        }
        out[i] = cpp_reserved().count(k.text) || k.text == "not" ? cpp_name(k.text) : mapped(k.text, s.lang);
        if (out[i].empty()) out[i] = " ";  // a dropped qualifier, as out above (/in* would make /*)
        if (reference_next && out[i] != "const" && out[i] != " ") reference[i] = true, reference_next = false;
    }
}

// What the analysis leaves out (uniform declarations, cbuffers, precision statements,
// prototypes, HLSL's attributes) as spaces with their newlines; global integer constants as
// constant expressions.
void shader_rewriter::remove() {
    for (std::size_t c : a.constant_integers) out[c] = "static constexpr";
    for (const auto& [first, last] : a.removed)
        for (std::size_t k = first; k <= last && k < t.size(); ++k) {
            if (t[k].type == token::space || t[k].type == token::directive) continue;
            out[k] = " ";
            reference[k] = false;
        }
}

std::string shader_rewriter::run() {
    words();
    precision();
    arrays();
    swizzle_pass();
    structs();
    if (hlsl()) casts();
    remove();
    std::string joined;
    for (std::size_t i = 0; i < t.size(); ++i) joined += out[i] + (reference[i] ? "&" : "");
    // The code has no trigraph (docs/brdf-code.md#safety), but two ? it holds, and a ( or > a
    // rewrite puts after them, would make one: a space between
    std::string spaced;
    for (std::size_t i = 0; i < joined.size(); ++i) {
        spaced += joined[i];
        if (i >= 1 && joined[i] == '?' && joined[i - 1] == '?' && i + 1 < joined.size() &&
            std::string("=/'()!<>-").find(joined[i + 1]) != std::string::npos)
            spaced += ' ';
    }
    return spaced;
}

// A struct: a constructor from its fields in order (GLSL's S(a, b)), fields that start at zero,
// and for a field named like a swizzle (s.x, s.rgb), the ->* that reads and writes it.
void shader_rewriter::structs() {
    for (const auto& st : a.structs) {
        std::string made = " " + st.name + "() = default;";
        std::string params, init;
        for (std::size_t k = 0; k < st.fields.size(); ++k) {
            const auto& f = st.fields[k];
            if (f.end == none || f.name.empty()) continue;
            const std::string name = cpp_name(f.name), arg = "normzoo_" + std::to_string(k);
            out[f.end] += "{}";
            params += (params.empty() ? "" : ", ") + std::string("const decltype(") + name + ")& " + arg;
            init += (init.empty() ? "" : ", ") + name + "(" + arg + ")";
            if (swizzle_set(f.name) < 0) continue;
            swizzles.insert(f.name);
            made += " auto& operator->*(decltype(normzoo_swr_" + f.name + ")) { return " + name + "; } const auto& operator->*(decltype(normzoo_sw_" +
                    f.name + ")) const { return " + name + "; }";
        }
        if (!params.empty()) made += " " + st.name + "(" + params + ") : " + init + " {}";
        out[st.close] = made + " " + out[st.close];
    }
}

// HLSL: (S)0, a struct of zeros, as S(); the semantics after a parameter, a field or a function
// (: NORMAL, : SV_Target) left out.
void shader_rewriter::casts() {
    for (std::size_t k = 0; k < t.size(); ++k) {
        if (t.is(k, "(")) {
            const std::size_t name = t.next(k), close = t.next(name), zero = t.next(close);
            if (is_type(name) && !is_builtin_type(t[name].text, s.lang) && t.is(close, ")") && t.is(zero, "0"))
                out[k] = " ", out[close] = "(", out[zero] = ")";
        }
        if (!t.is(k, ":") || !t.is_word(t.next(k))) continue;
        const std::size_t p = t.parent(k);
        // after a function's ) or before register(...); a top level ternary's : stays
        bool semantic = p == none && (t.is(t.prev(k), ")") || t.is(t.next(k), "register") || t.is(t.next(k), "packoffset"));
        for (const auto& st : a.structs) semantic = semantic || p == st.open;
        for (const auto& f : a.functions) semantic = semantic || (p != none && t.is(p, "(") && p > f.first && p < f.open && t.parent(p) == none);
        if (!semantic) continue;
        const std::size_t w = t.next(k);
        out[k] = " ", out[w] = " ";
        const std::size_t open = t.next(w);
        if (t.is(open, "(") && t.match(open) != none)
            for (std::size_t j = open; j <= t.match(open); ++j)
                if (t[j].type != token::space) out[j] = " ";
    }
}

}  // namespace verify
