#include "shader_translate.hpp"

#include "../args.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace verify {

namespace {

struct token {
    enum kind { space, word, number, punct, directive } type;
    std::string text;
};

// Comments become spaces (their newlines kept); a # line is one directive token (the translation
// reads preprocessed code, which has none).
std::vector<token> tokenize(const std::string& s) {
    std::vector<token> out;
    std::size_t i = 0;
    bool line_start = true;
    while (i < s.size()) {
        const char c = s[i];
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            std::string kept = " ";
            i += 2;
            while (i + 1 < s.size() && !(s[i] == '*' && s[i + 1] == '/')) kept += s[i] == '\n' ? "\n" : "", ++i;
            i += 2;
            out.push_back({token::space, kept});
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(c))) {
            out.push_back({token::space, std::string(1, c)});
            if (c == '\n') line_start = true;
            ++i;
            continue;
        }
        if (c == '#' && line_start) {
            std::size_t j = s.find('\n', i);
            if (j == std::string::npos) j = s.size();
            out.push_back({token::directive, s.substr(i, j - i)});
            i = j;
            continue;
        }
        line_start = false;
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            std::size_t j = i;
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
            out.push_back({token::word, s.substr(i, j - i)});
            i = j;
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            std::size_t j = i;
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '.' ||
                                    ((s[j] == '+' || s[j] == '-') && (s[j - 1] == 'e' || s[j - 1] == 'E'))))
                ++j;
            out.push_back({token::number, s.substr(i, j - i)});
            i = j;
            continue;
        }
        out.push_back({token::punct, std::string(1, c)});
        ++i;
    }
    return out;
}

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

bool swizzle(const std::string& w) {
    if (w.size() < 2 || w.size() > 4) return false;
    const std::string sets[] = {"xyzw", "rgba", "stpq"};
    for (const auto& set : sets) {
        bool all = true;
        for (char ch : w) all = all && set.find(ch) != std::string::npos;
        if (all) return true;
    }
    return false;
}

// The word each shading language's type or name becomes.
std::string mapped(const std::string& w, shader_source::language lang) {
    static const std::map<std::string, std::string> common{
        {"float", "real"}, {"vec2", "vec2"}, {"vec3", "vec3"}, {"vec4", "vec4"}, {"mat2", "mat2"}, {"mat3", "mat3"},
        {"mat4", "mat4"}, {"in", ""}, {"highp", ""}, {"mediump", ""}, {"lowp", ""}, {"precise", ""}};
    static const std::map<std::string, std::string> hlsl{
        {"float2", "vec2"}, {"float3", "vec3"}, {"float4", "vec4"}, {"half", "real"}, {"half2", "vec2"},
        {"half3", "vec3"}, {"half4", "vec4"}, {"float2x2", "mat2"}, {"float3x3", "mat3"}, {"float4x4", "mat4"},
        {"static", ""}, {"inline", ""}, {"min16float", "real"}, {"min16float3", "vec3"}};
    if (lang == shader_source::language::hlsl) {
        auto h = hlsl.find(w);
        if (h != hlsl.end()) return h->second;
    }
    auto c = common.find(w);
    return c != common.end() ? c->second : w;
}

// The body, translated: float literals as real(...), swizzles as calls, out/inout parameters as
// references, prototypes (a top-level declaration that ends in ");") dropped.
std::string translate_body(const shader_source& s) {
    const shader_source::language lang = s.lang;
    auto t = tokenize(s.code);
    std::ostringstream out;
    int depth = 0;      // braces
    bool reference_next = false;  // after out / inout: the parameter's type is followed by &
    std::vector<std::string> pending;  // tokens of the current top-level statement
    auto flush = [&](bool keep) {
        if (keep)
            for (auto& p : pending) out << p;
        else
            for (auto& p : pending)
                for (char ch : p)
                    if (ch == '\n') out << '\n';
        pending.clear();
    };
    // the file's line of token i
    auto line_of = [&](std::size_t i) {
        int line = s.first_line;
        for (std::size_t j = 0; j < i; ++j) line += static_cast<int>(std::count(t[j].text.begin(), t[j].text.end(), '\n'));
        return line;
    };
    for (std::size_t i = 0; i < t.size(); ++i) {
        const token& k = t[i];
        std::string text = k.text;
        // the preprocessor leaves none (preprocess.hpp): the code around the file's never meets its macros
        if (k.type == token::directive) throw bad_input(s.place(line_of(i)) + ": a directive reached the translation unpreprocessed");
        if (k.type == token::number) text = is_float_literal(k.text) ? float_literal(k.text) : k.text;
        if (k.type == token::word) {
            const bool after_dot = i > 0 && t[i - 1].type == token::punct && t[i - 1].text == ".";
            if (after_dot) {
                text = swizzle(k.text) ? k.text + "()" : k.text;
                // GLM's swizzles are values: v.xy = ... would compile and change nothing
                if (swizzle(k.text)) {
                    std::string after;
                    for (std::size_t j = i + 1; j < t.size() && after.size() < 2; ++j)
                        if (t[j].type == token::punct) after += t[j].text;
                        else if (t[j].type != token::space) break;
                    const bool assigns = (after.size() >= 1 && after[0] == '=' && after != "==") ||
                                         (after.size() == 2 && after[1] == '=' && std::string("+-*/").find(after[0]) != std::string::npos) ||
                                         after == "++" || after == "--";
                    if (assigns) {
                        throw bad_input(s.place(line_of(i)) + ": assigning to a swizzle (." + k.text +
                                        " = ...) is outside what normzoo runs on the CPU (docs/brdf-code.md#what-is-supported)");
                    }
                }
            } else if (k.text == "out" || k.text == "inout") {
                reference_next = true;
                text = " ";  // not "": the tokens beside it must not join (/inout* would make /*)
            } else {
                text = mapped(k.text, lang);
                if (text.empty()) text = " ";  // a dropped qualifier, as out above (/in* would make /*)
                if (reference_next && text != "const" && text != " ") {  // out highp float x: the & goes to the type
                    text += "&";
                    reference_next = false;
                }
            }
        }
        if (k.type == token::punct) {
            if (text == "{") ++depth;
            if (text == "}") --depth;
        }
        pending.push_back(text);
        if (depth == 0 && k.type == token::punct && (text == ";" || text == "}")) {
            // a prototype: ... ( ... ) ;  with no '=' and no '{'
            bool prototype = false;
            if (text == ";") {
                std::string joined;
                for (auto& p : pending) joined += p;
                const auto close = joined.find_last_of(')');
                prototype = close != std::string::npos && joined.find('{') == std::string::npos &&
                            joined.find('=') == std::string::npos &&
                            joined.find_first_not_of(" \t\n", close + 1) == joined.size() - 1;
            }
            flush(!prototype);
        }
    }
    flush(true);
    return out.str();
}

std::string cpp_string(const std::string& s) {
    std::string o = "\"";
    for (char c : s) {
        if (static_cast<unsigned char>(c) < 0x20) {  // a newline would end the literal and start a line
            char octal[8];
            std::snprintf(octal, sizeof octal, "\\%03o", static_cast<unsigned>(static_cast<unsigned char>(c)));
            o += octal;
            continue;
        }
        if (c == '"' || c == '\\') o += '\\';
        o += c;
    }
    return o + "\"";
}

}  // namespace

std::string translate_shader(const shader_source& s, const std::string& prelude_path) {
    const std::string body = translate_body(s);
    std::string shown_path = s.path;  // in a comment: nothing that could end its line
    for (char& ch : shown_path)
        if (static_cast<unsigned char>(ch) < 0x20 || ch == '\\') ch = '?';
    std::ostringstream o;
    o << "// Generated by normzoo from " << shown_path << " (docs/brdf-code.md#how-the-shader-runs).\n";
    o << "#include " << cpp_string(prelude_path) << "\n\n";
    for (const char* real : {"double", "float"}) {
        o << "namespace normzoo_" << real << " {\nusing real = " << real << ";\n";
        if (s.lang == shader_source::language::hlsl)
            o << "using vec2 = normzoo_glsl::hlsl_vec<2, real>;\nusing vec3 = normzoo_glsl::hlsl_vec<3, real>;\n"
                 "using vec4 = normzoo_glsl::hlsl_vec<4, real>;\n";
        else
            o << "using vec2 = glm::vec<2, real>;\nusing vec3 = glm::vec<3, real>;\nusing vec4 = glm::vec<4, real>;\n";
        o << "using mat2 = glm::mat<2, 2, real>;\nusing mat3 = glm::mat<3, 3, real>;\nusing mat4 = glm::mat<4, 4, real>;\n";
        o << "NORMZOO_GLSL_MIXED_OPERATORS(real)\n";
        o << "struct normzoo_program : normzoo_glsl::library<real> {\n";
        for (const auto& p : s.parameters)
            o << "    " << (p.type == shader_parameter::kind::real ? "real" : p.type == shader_parameter::kind::boolean ? "bool" : "vec3")
              << " " << p.name << "{};\n";
        o << "#line " << s.first_line << " " << cpp_string(s.path) << "\n" << body << "\n};\n";
        o << "}  // namespace normzoo_" << real << "\n\n";
    }
    o << "extern \"C\" {\n";
    for (const char* real : {"double", "float"}) {
        const std::string ns = std::string("normzoo_") + real;
        o << "void* normzoo_make_" << real << "(const double* p) {\n    auto* s = new " << ns << "::normzoo_program();\n";
        std::size_t slot = 0;
        for (const auto& p : s.parameters) {
            if (p.type == shader_parameter::kind::color)
                o << "    s->" << p.name << " = " << ns << "::vec3(" << ns << "::real(p[" << slot << "]), " << ns << "::real(p["
                  << slot + 1 << "]), " << ns << "::real(p[" << slot + 2 << "]));\n";
            else if (p.type == shader_parameter::kind::boolean)
                o << "    s->" << p.name << " = p[" << slot << "] != 0;\n";
            else
                o << "    s->" << p.name << " = " << ns << "::real(p[" << slot << "]);\n";
            slot += p.slots();
        }
        o << "    return s;\n}\n";
        o << "void normzoo_free_" << real << "(void* s) { delete static_cast<" << ns << "::normzoo_program*>(s); }\n";
        o << "void normzoo_eval_" << real << "(void* s, const double* d, double* out) {\n";
        o << "    using v = " << ns << "::vec3;\n    using r = " << ns << "::real;\n";
        o << "    const auto f = static_cast<" << ns << "::normzoo_program*>(s)->" << s.function
          << "(v(r(d[0]), r(d[1]), r(d[2])), v(r(d[3]), r(d[4]), r(d[5])), v(r(d[6]), r(d[7]), r(d[8])), "
             "v(r(d[9]), r(d[10]), r(d[11])), v(r(d[12]), r(d[13]), r(d[14])));\n";
        o << "    normzoo_glsl::store(out, f);\n}\n";
    }
    o << "}\n";
    return o.str();
}

}  // namespace verify
