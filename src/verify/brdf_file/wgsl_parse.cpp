// WGSL's grammar (https://www.w3.org/TR/WGSL/#grammar-recursive-descent), read whole: the
// declarations and statements of the subset and those the checker refuses by name (switch,
// override, pointers), so that a file reads as WGSL or is refused where a WGSL compiler would.
#include <set>

#include "../args.hpp"
#include "wgsl_parser.hpp"

namespace verify::wgsl {

[[noreturn]] void parser::fail(int line, const std::string& what) const {
    throw bad_input(path_ + ":" + std::to_string(line) + ": " + what);
}

std::string parser::shown(const token& t) {
    return t.k == token::kind::end ? "the end of the file" : "'" + t.text + "'";
}

void parser::expect(const std::string& text, const std::string& where) {
    if (peek().text != text || peek().k == token::kind::ident || peek().k == token::kind::end)
        fail(peek().line, "expected '" + text + "' " + where + ", found " + shown(peek()));
    ++at_;
}

bool parser::accept(const std::string& text) {
    if (peek().k != token::kind::punct || peek().text != text) return false;
    ++at_;
    return true;
}

bool parser::word(const std::string& w) const { return peek().k == token::kind::ident && peek().text == w; }

std::string parser::name(const std::string& what) {
    const token& t = peek();
    if (t.k != token::kind::ident) fail(t.line, "expected " + what + ", found " + shown(t));
    if (reserved(t.text)) fail(t.line, "'" + t.text + "' is a WGSL keyword or reserved word, not a name");
    if (t.text.size() > 1 && t.text[0] == '_' && t.text[1] == '_') fail(t.line, "'" + t.text + "': WGSL names may not begin with two underscores");
    ++at_;
    return t.text;
}

void parser::enter(int& depth) {
    if (++depth > max_nesting) fail(peek().line, "nested more than " + std::to_string(max_nesting) + " deep: outside the subset normzoo reads");
}

std::vector<attribute> parser::attributes() {
    std::vector<attribute> out;
    while (accept("@")) {
        attribute a;
        a.line = peek().line;
        if (peek().k != token::kind::ident) fail(a.line, "expected an attribute's name after '@', found " + shown(peek()));
        a.name = peek().text;
        ++at_;
        if (accept("(")) {
            while (!accept(")")) {
                a.args.push_back(expression());
                if (!accept(",")) {
                    expect(")", "to close @" + a.name + "(...)");
                    break;
                }
            }
        }
        out.push_back(a);
    }
    return out;
}

int parser::type_specifier() {
    const int line = peek().line;
    if (peek().k != token::kind::ident) fail(line, "expected a type, found " + shown(peek()));
    expr e;
    e.k = expr::kind::name;
    e.line = line;
    e.text = peek().text;
    ++at_;
    template_list(e);
    return add(e);
}

void parser::template_list(expr& e) {
    if (peek().k != token::kind::template_start) return;
    ++at_;
    e.has_templ = true;
    while (peek().k != token::kind::template_end) {
        e.templ.push_back(expression());
        if (!accept(",")) break;
    }
    if (peek().k != token::kind::template_end) fail(peek().line, "expected '>' to close " + e.text + "<...>, found " + shown(peek()));
    ++at_;
}

// optionally_typed_ident: NAME (':' TYPE)?
void parser::typed_name(std::string& n, int& type, const std::string& what) {
    n = name(what);
    if (accept(":")) type = type_specifier();
}

int parser::parse_function(declaration& d) {
    d.k = declaration::kind::function;
    d.name = name("a function's name after 'fn'");
    expect("(", "after fn " + d.name);
    while (!accept(")")) {
        param p;
        p.attrs = attributes();
        p.line = peek().line;
        p.name = name("a parameter's name");
        expect(":", "after parameter " + p.name + " (WGSL writes name: type)");
        p.type = type_specifier();
        d.params.push_back(p);
        if (!accept(",")) {
            expect(")", "after fn " + d.name + "'s parameters");
            break;
        }
    }
    if (accept("->")) {
        d.return_attrs = attributes();
        d.type = type_specifier();
    }
    if (peek().text != "{" || peek().k != token::kind::punct) fail(peek().line, "expected '{' to begin fn " + d.name + "'s body, found " + shown(peek()));
    int depth = 0;
    d.body = block(depth);
    d.end_line = stmts_[static_cast<std::size_t>(d.body)].end_line;
    return 0;
}

void parser::parse_struct(declaration& d) {
    d.k = declaration::kind::structure;
    d.name = name("a struct's name");
    expect("{", "after struct " + d.name);
    while (!(peek().k == token::kind::punct && peek().text == "}")) {
        param m;
        m.attrs = attributes();
        m.line = peek().line;
        m.name = name("a member's name");
        expect(":", "after member " + m.name + " (WGSL writes name: type)");
        m.type = type_specifier();
        d.params.push_back(m);
        if (!accept(",")) break;
    }
    d.end_line = peek().line;
    expect("}", "to close struct " + d.name + " (members are separated by ',')");
    if (d.params.empty()) fail(d.line, "struct " + d.name + " has no members");
}

declaration parser::global_declaration() {
    declaration d;
    d.attrs = attributes();
    d.line = peek().line;
    const token& t = peek();
    if (t.k != token::kind::ident) fail(t.line, "expected a declaration, found " + shown(t));
    const std::string w = t.text;
    ++at_;
    if (w == "fn") {
        parse_function(d);
        return d;
    }
    if (w == "struct") {
        parse_struct(d);
        return d;
    }
    if (w == "const" || w == "override") {
        d.k = w == "const" ? declaration::kind::const_ : declaration::kind::override_;
        typed_name(d.name, d.type, "a name after '" + w + "'");
        if (w == "const" || peek().text == "=") {
            expect("=", "after const " + d.name + " (a const has a value)");
            d.value = expression();
        }
    } else if (w == "var") {
        d.k = declaration::kind::var;
        expr holder;
        template_list(holder);
        d.templ = holder.templ;
        typed_name(d.name, d.type, "a name after 'var'");
        if (accept("=")) d.value = expression();
    } else if (w == "alias") {
        d.k = declaration::kind::alias;
        d.name = name("a name after 'alias'");
        expect("=", "after alias " + d.name);
        d.type = type_specifier();
    } else if (w == "const_assert") {
        d.k = declaration::kind::const_assert;
        d.value = expression();
    } else {
        fail(t.line, not_a_declaration(w));
    }
    expect(";", "after the declaration of " + (d.name.empty() ? w : d.name));
    return d;
}

// The words of one who wrote GLSL or HLSL in a .wgsl file.
std::string parser::not_a_declaration(const std::string& w) {
    static const std::set<std::string> c_like{"void", "float", "int", "uint", "bool", "vec2", "vec3", "vec4", "float2",
                                              "float3", "float4", "half", "half3", "mat3", "float3x3", "uniform",
                                              "in", "out", "inout", "precision", "layout", "static", "inline",
                                              "cbuffer", "highp", "mediump", "lowp"};
    if (w == "let") return "'let' declares in a function only: a value at module scope is a const";
    std::string m = "'" + w + "' begins no WGSL declaration (fn, struct, const, var, override, alias, const_assert)";
    if (c_like.count(w))
        m += ": this reads as GLSL or HLSL, and a .wgsl file holds WGSL: fn NAME(L: vec3<f32>, ...) -> vec3<f32> "
             "(docs/brdf-code.md#wgsl)";
    return m;
}

module parser::parse_module() {
    module m;
    while (peek().k == token::kind::ident && (word("enable") || word("requires") || (word("diagnostic") && peek(1).text == "("))) {
        directive d;
        d.name = peek().text;
        d.line = peek().line;
        ++at_;
        while (peek().k != token::kind::end && !(peek().k == token::kind::punct && peek().text == ";")) d.words.push_back(peek().text), ++at_;
        expect(";", "after the " + d.name + " directive");
        m.directives.push_back(d);
    }
    while (peek().k != token::kind::end) {
        if (accept(";")) continue;
        m.decls.push_back(global_declaration());
    }
    m.exprs = std::move(exprs_);
    m.stmts = std::move(stmts_);
    return m;
}

module parse(const std::string& path, const std::vector<token>& tokens) { return parser(path, tokens).parse_module(); }

}  // namespace verify::wgsl
