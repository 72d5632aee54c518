// The translation's rewrites of expressions and declarations (shader_rewrite.hpp): arrays as
// normzoo_glsl::array, swizzles as ->* with a tag (docs/brdf-code.md#how-the-shader-runs).
#include <algorithm>

#include "shader_rewrite.hpp"

namespace verify {

namespace {

constexpr std::size_t none = token_list::none;

bool operand_end(const token_list& t, std::size_t i) {
    return i != none && (t[i].type == token::word || t[i].type == token::number || t.is(i, ")") || t.is(i, "]"));
}

bool qualifier(const std::string& w) {
    return w == "const" || w == "static" || w == "in" || w == "out" || w == "inout" || w == "highp" || w == "mediump" || w == "lowp" ||
           w == "precise" || w == "uniform";
}

// The elements of the brackets that open at `open`: ( a, b ) or { a, b, } -> 2.
std::size_t elements(const token_list& t, std::size_t open) {
    const std::size_t close = t.match(open);
    if (close == none) return none;
    if (t.next(open) == close) return 0;
    std::size_t n = 1;
    for (std::size_t k = open + 1; k < close; ++k) n += t.is(k, ",") && t.parent(k) == open;
    return t.is(t.prev(close), ",") ? n - 1 : n;
}

std::string wrap(std::string type, const std::vector<std::string>& d) {
    for (std::size_t k = d.size(); k-- > 0;) type = "normzoo_glsl::array<" + type + ", " + d[k] + ">";
    return type;
}

}  // namespace

// Each [N] from `open` on: its C++ (on one line), its brackets left as spaces; after: the token
// that follows them.
std::vector<std::string> shader_rewriter::dims(std::size_t open, std::size_t& after) {
    std::vector<std::string> d;
    std::size_t k = open;
    while (t.is(k, "[") && t.match(k) != none) {
        const std::size_t close = t.match(k);
        std::string text;
        for (std::size_t m = k + 1; m < close; ++m) text += t[m].type == token::space ? " " : out[m];
        for (std::size_t m = k; m <= close; ++m)
            if (t[m].type != token::space) out[m] = " ";
        const std::size_t b = text.find_first_not_of(' '), e = text.find_last_not_of(' ');
        d.push_back(b == std::string::npos ? "" : text.substr(b, e - b + 1));
        k = t.next(close);
    }
    after = k;
    return d;
}

// The number of elements an initializer gives (= T[](a, b), = { a, b }), or none.
std::size_t shader_rewriter::count_initializer(std::size_t equals) const {
    if (!t.is(equals, "=")) return none;
    std::size_t k = t.next(equals);
    if (t.is(k, "{")) return elements(t, k);
    if (!is_type(k)) return none;
    k = t.next(k);
    while (t.is(k, "[") && t.match(k) != none) k = t.next(t.match(k));
    return t.is(k, "(") ? elements(t, k) : none;
}

// An array declared without its size (float a[] = float[](...)) takes its initializer's.
void shader_rewriter::sized(std::vector<std::string>& d, std::size_t name, std::size_t after) const {
    if (d.empty() || !d[0].empty()) return;
    const std::size_t n = count_initializer(after);
    if (n == none || n == 0)
        refuse(name, "the array " + t[name].text + " is declared without its size, and normzoo cannot count it from an initializer: write its size");
    d[0] = std::to_string(n);
}

void shader_rewriter::arrays() {
    for (std::size_t i = 0; i < t.size(); ++i)
        if (is_type(i) && !t.is(t.prev(i), ".")) declaration(i);
}

// After a type: T[N](...) (a constructor), T[N] NAME, or NAME [N], NAME [N] ... (declarators,
// each of which becomes normzoo_glsl::array<T, N>; a statement of several is split into one
// declaration each).
void shader_rewriter::declaration(std::size_t type) {
    const std::size_t j = t.next(type);
    if (t.is(j, "[")) {
        std::size_t after = j;
        auto d = dims(j, after);
        if (t.is(after, "(")) {
            if (d.size() > 1) refuse(type, "an array of arrays built by a constructor is outside what normzoo runs: build each array apart");
            out[type] = "normzoo_glsl::make_array<" + out[type] + ">";
        } else if (t.is_word(after)) {
            std::size_t next = t.next(after);
            while (t.is(next, "[") && t.match(next) != none) next = t.next(t.match(next));
            sized(d, after, next);
            out[type] = wrap(out[type], d);
        }
        return;
    }
    if (!t.is_word(j) || is_type(j) || qualifier(t[j].text)) return;
    const std::string base = out[type];
    std::string quals;
    for (std::size_t p = t.prev(type); t.is_word(p) && qualifier(t[p].text); p = t.prev(p)) quals = out[p] + " " + quals;
    const bool statement = t.parent(type) == none || t.is(t.parent(type), "{");
    bool arrays_seen = false;
    for (std::size_t name = j, comma = none;;) {
        std::size_t after = t.next(name);
        std::vector<std::string> d;
        if (t.is(after, "[")) d = dims(after, after);
        sized(d, name, after);
        arrays_seen = arrays_seen || !d.empty();
        if (comma == none && !d.empty()) out[type] = wrap(base, d);
        if (comma != none && arrays_seen) out[comma] = "; " + quals + wrap(base, d);
        // on past its initializer; a function's body ends the search (its { follows no =)
        std::size_t k = after;
        bool initializer = false;
        while (k < t.size() && !t.is(k, ",") && !t.is(k, ";") && !t.is(k, ")") && !t.is(k, "}") && !(t.is(k, "{") && !initializer)) {
            initializer = initializer || t.is(k, "=");
            k = t.next(t.is(k, "(") || t.is(k, "[") || t.is(k, "{") ? t.match(k) : k);
        }
        if (!statement || !t.is(k, ",") || !t.is_word(t.next(k)) || is_type(t.next(k))) return;
        comma = k;
        name = t.next(k);
    }
}

// The first token of the operand a swizzle's dot follows: v, a[i], f(x), (a + b), s.n.
std::size_t shader_rewriter::operand_start(std::size_t j) const {
    static const std::set<std::string> keywords{"return", "if", "while", "for", "switch", "case", "else", "do"};
    while (true) {
        if (t.is(j, ")") || t.is(j, "]")) {
            const std::size_t open = t.match(j);
            if (open == none) return j;
            const std::size_t p = t.prev(open);
            if (t.is(j, "]") && operand_end(t, p)) {
                j = p;
                continue;
            }
            if (t.is(j, ")") && p != none && ((t.is_word(p) && !keywords.count(t[p].text)) || t.is(p, "]"))) {
                j = p;
                continue;
            }
            return open;
        }
        const std::size_t p = t.prev(j);
        if (t.is(p, ".") && operand_end(t, t.prev(p))) {
            j = t.prev(p);
            continue;
        }
        return j;
    }
}

// The swizzle, whole, is an argument of an out or inout parameter: sincos(x, v.x, v.y).
bool shader_rewriter::out_argument(std::size_t start, std::size_t last) const {
    const std::size_t p = t.prev(start), n = t.next(last);
    if (!(t.is(p, "(") || t.is(p, ",")) || !(t.is(n, ",") || t.is(n, ")"))) return false;
    const std::size_t paren = t.is(p, "(") ? p : t.parent(p);
    if (!t.is(paren, "(") || !t.is_word(t.prev(paren))) return false;
    std::size_t index = 0;
    for (std::size_t k = paren + 1; k < start; ++k) index += t.is(k, ",") && t.parent(k) == paren;
    const std::string& callee = t[t.prev(paren)].text;
    if (callee == "sincos") return index >= 1;
    if (callee == "modf" || callee == "frexp") return index == 1;
    for (const auto& f : a.functions)
        if (f.name == callee && index < f.params.size() && f.params[index].dir != shader_declared::direction::in) return true;
    return false;
}

// The swizzle at `dot word` is written: an assignment follows it (or its [i]), ++ or -- goes
// before it, or it is an out argument.
bool shader_rewriter::written(std::size_t dot, std::size_t word, std::size_t start) const {
    (void)dot;
    auto at = [&](std::size_t k, const char* c) { return k < t.size() && t[k].text == c; };
    std::size_t k = t.next(word);
    if (t.is(k, "[") && t.match(k) != none) k = t.next(t.match(k));
    if (k != none && t[k].type == token::punct) {
        const std::string& x = t[k].text;
        if (x == "=" && !at(k + 1, "=")) return true;
        if (std::string("+-*/%&|^").find(x) != std::string::npos && at(k + 1, "=")) return true;
        if ((x == "+" || x == "-") && at(k + 1, x.c_str())) return true;
        if ((x == "<" || x == ">") && at(k + 1, x.c_str()) && at(k + 2, "=")) return true;
    }
    const std::size_t p = t.prev(start);
    if (p != none && p > 0 && (t.is(p, "+") || t.is(p, "-")) && t[p - 1].text == t[p].text) return true;
    return out_argument(start, word);
}

// v.xy becomes (v ->* normzoo_sw_xy): a value, or with normzoo_swr_xy a reference where it is
// written; a written swizzle of a swizzle (v.xy.x = ...) writes both.
void shader_rewriter::swizzle_pass() {
    struct use {
        std::size_t dot, word, start;
        bool write;
    };
    std::vector<use> uses;
    for (std::size_t d = 0; d < t.size(); ++d) {
        if (!t.is(d, ".")) continue;
        const std::size_t w = t.next(d), p = t.prev(d);
        if (!t.is_word(w) || swizzle_set(t[w].text) < 0 || !operand_end(t, p)) continue;
        const std::size_t start = operand_start(p);
        // a reference to several components binds to no vec2& (glsl_prelude.hpp, swizzle_ref)
        if (t[w].text.size() > 1 && out_argument(start, w))
            refuse(w, "a swizzle of several components as an out or inout argument (." + t[w].text +
                          ") is outside what normzoo runs: pass a variable, and assign it to the swizzle after the call");
        uses.push_back({d, w, start, written(d, w, start)});
    }
    for (auto u = uses.rbegin(); u != uses.rend(); ++u) {
        if (!u->write) continue;
        const std::size_t inner = t.prev(u->dot);
        for (auto& v : uses)
            if (v.word == inner) v.write = true;
    }
    for (const auto& u : uses) {
        out[u.start] = "(" + out[u.start];
        out[u.dot] = "->*";
        out[u.word] = std::string(u.write ? "normzoo_swr_" : "normzoo_sw_") + t[u.word].text + ")";
        swizzles.insert(t[u.word].text);
    }
}

}  // namespace verify
