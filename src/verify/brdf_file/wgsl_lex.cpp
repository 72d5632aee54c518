// WGSL's tokens (https://www.w3.org/TR/WGSL/#textual-structure): comments, literals, names and
// punctuation, with template lists found first by the specification's own algorithm
// (#template-list-discovery), so that vec3<f32> and a < b are told apart as WGSL does.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>

#include "../args.hpp"
#include "wgsl_syntax.hpp"

namespace verify::wgsl {

namespace {

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
    throw bad_input(path + ":" + std::to_string(line) + ": " + what);
}

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool hex(char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; }

// The code with its comments blanked (their newlines kept), and the line of each byte. Bytes that
// end a line for WGSL but not for a reader counting '\n' are refused, comments included, since a
// line break ends a // comment (#blankspace-and-line-breaks); so are other control bytes.
std::string blank_comments(const std::string& path, const std::string& c, int first_line, std::vector<int>& line_of) {
    std::string out = c;
    line_of.assign(c.size() + 1, first_line);
    int line = first_line;
    int depth = 0;          // block comments nest in WGSL (#comments)
    bool in_line = false;   // in a // comment
    for (std::size_t i = 0; i < c.size(); ++i) {
        line_of[i] = line;
        const auto ch = static_cast<unsigned char>(c[i]);
        const bool comment = in_line || depth > 0;
        if (ch == '\n') {
            ++line, in_line = false;
            continue;
        }
        if (ch == '\r' && i + 1 < c.size() && c[i + 1] == '\n') {
            out[i] = ' ';
            continue;
        }
        if ((ch < 0x20 && ch != '\t') || ch == 0x7f) {
            char hex_text[8];
            std::snprintf(hex_text, sizeof hex_text, "0x%02x", ch);
            fail(path, line, std::string("control character ") + hex_text + " refused: WGSL may read it as a line break");
        }
        const bool nel = ch == 0xc2 && i + 1 < c.size() && static_cast<unsigned char>(c[i + 1]) == 0x85;
        const bool separator = ch == 0xe2 && i + 2 < c.size() && static_cast<unsigned char>(c[i + 1]) == 0x80 &&
                               (static_cast<unsigned char>(c[i + 2]) == 0xa8 || static_cast<unsigned char>(c[i + 2]) == 0xa9);
        if (nel || separator) fail(path, line, "a Unicode line break (NEL, U+2028, U+2029) refused: WGSL ends a line there");
        if (!comment && ch >= 0x80) fail(path, line, "a byte that is not ASCII outside a comment: names and code are ASCII in the subset normzoo reads");
        if (!comment && ch == '/' && i + 1 < c.size() && c[i + 1] == '/') {
            in_line = true;
        } else if (!in_line && ch == '/' && i + 1 < c.size() && c[i + 1] == '*') {
            ++depth;
            out[i] = out[i + 1] = ' ';
            line_of[++i] = line;
            continue;
        } else if (depth > 0 && ch == '*' && i + 1 < c.size() && c[i + 1] == '/') {
            --depth;
            out[i] = out[i + 1] = ' ';
            line_of[++i] = line;
            continue;
        }
        if (in_line || depth > 0) out[i] = ' ';
    }
    line_of[c.size()] = line;
    if (depth > 0) fail(path, line, "a block comment /* ... */ that does not end");
    return out;
}

// The length of the numeric literal at i (#numeric-literals), and whether it is a float; 0 if
// none starts there.
std::size_t literal_length(const std::string& s, std::size_t i, bool& is_float) {
    std::size_t j = i;
    auto digits = [&](bool (*pred)(char)) {
        const std::size_t from = j;
        while (j < s.size() && pred(s[j])) ++j;
        return j - from;
    };
    auto exponent = [&](char e1, char e2) {
        if (j < s.size() && (s[j] == e1 || s[j] == e2)) {
            std::size_t k = j + 1;
            if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
            if (k < s.size() && digit(s[k])) {
                j = k;
                digits(digit);
                return true;
            }
        }
        return false;
    };
    is_float = false;
    if (s.compare(i, 2, "0x") == 0 || s.compare(i, 2, "0X") == 0) {
        j = i + 2;
        const std::size_t h1 = digits(hex);
        std::size_t h2 = 0;
        const bool dot = j < s.size() && s[j] == '.';
        if (dot) ++j, h2 = digits(hex);
        if (h1 + h2 == 0) return 0;
        const bool exp = exponent('p', 'P');
        is_float = dot || exp;
        if (exp && j < s.size() && (s[j] == 'f' || s[j] == 'h')) ++j;
        if (!is_float && j < s.size() && (s[j] == 'i' || s[j] == 'u')) ++j;
        return j - i;
    }
    const std::size_t d1 = digits(digit);
    std::size_t d2 = 0;
    const bool dot = j < s.size() && s[j] == '.' && (d1 > 0 || (j + 1 < s.size() && digit(s[j + 1])));
    if (dot) ++j, d2 = digits(digit);
    if (d1 + d2 == 0) return 0;
    const bool exp = exponent('e', 'E');
    is_float = dot || exp;
    if (j < s.size() && (s[j] == 'f' || s[j] == 'h')) ++j, is_float = true;
    else if (!is_float && j < s.size() && (s[j] == 'i' || s[j] == 'u')) ++j;
    return j - i;
}

// #template-list-discovery, over the text with comments blanked: the positions of the '<' and
// '>' that delimit template lists.
void discover_templates(const std::string& s, std::set<std::size_t>& starts, std::set<std::size_t>& ends) {
    struct candidate {
        std::size_t position;
        int depth;
    };
    std::vector<candidate> pending;
    int depth = 0;
    std::size_t i = 0;
    auto skip_blank = [&] {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    };
    auto pop_to_depth = [&] {
        while (!pending.empty() && pending.back().depth >= depth) pending.pop_back();
    };
    while (true) {
        skip_blank();
        if (i >= s.size()) return;
        bool is_float = false;
        if (digit(s[i]) || (s[i] == '.' && i + 1 < s.size() && digit(s[i + 1]))) {
            const std::size_t n = literal_length(s, i, is_float);
            i += n > 0 ? n : 1;
            continue;
        }
        if (ident_start(s[i])) {
            while (i < s.size() && ident_char(s[i])) ++i;
            skip_blank();
            if (i < s.size() && s[i] == '<') {
                pending.push_back({i, depth});
                ++i;
                if (i < s.size() && (s[i] == '<' || s[i] == '=')) pending.pop_back(), ++i;
            }
            continue;
        }
        const char c = s[i];
        if (c == '>') {
            if (!pending.empty() && pending.back().depth == depth) {
                starts.insert(pending.back().position);
                ends.insert(i);
                pending.pop_back();
                ++i;
                continue;
            }
            ++i;
            if (i < s.size() && s[i] == '=') ++i;
        } else if (c == '(' || c == '[') {
            ++depth, ++i;
        } else if (c == ')' || c == ']') {
            pop_to_depth();
            depth = std::max(0, depth - 1);
            ++i;
        } else if (c == '!') {
            ++i;
            if (i < s.size() && s[i] == '=') ++i;
        } else if (c == '=') {
            ++i;
            if (i < s.size() && s[i] == '=') {
                ++i;
                continue;
            }
            depth = 0, pending.clear();
        } else if (c == ';' || c == '{' || c == ':') {
            depth = 0, pending.clear(), ++i;
        } else if (s.compare(i, 2, "&&") == 0 || s.compare(i, 2, "||") == 0) {
            pop_to_depth();
            i += 2;
        } else {
            ++i;
        }
    }
}

// What a byte that begins no WGSL token says to someone who wrote it.
std::string stray(char c) {
    if (c == '#') return "'#' is not WGSL: WGSL has no preprocessor (#define, #include, #ifdef; Bevy's #import is naga_oil's)";
    if (c == '"' || c == '\'') return "WGSL has no string or character literals";
    if (c == '\\') return "a backslash is not WGSL";
    if (c == '?') return "'?' is not WGSL: use select(f, t, cond) for a choice";
    return std::string("'") + c + "' begins no WGSL token";
}

}  // namespace

std::vector<token> tokenize(const std::string& path, const std::string& code, int first_line, std::size_t max_tokens,
                            const std::string& cap) {
    std::vector<int> line_of;
    const std::string s = blank_comments(path, code, first_line, line_of);
    std::set<std::size_t> starts, ends;
    discover_templates(s, starts, ends);
    static const char* const operators[] = {"<<=", ">>=", "&&", "||", "->", "<<", ">>", "<=", ">=", "==", "!=", "++", "--",
                                            "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="};
    std::vector<token> out;
    std::size_t i = 0;
    while (i < s.size()) {
        const char c = s[i];
        const int line = line_of[i];
        if (out.size() >= max_tokens)
            fail(path, line, "the code holds more than the " + std::to_string(max_tokens) + " tokens its translation may hold (" + cap + ")");
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        bool is_float = false;
        if (digit(c) || (c == '.' && i + 1 < s.size() && digit(s[i + 1]))) {
            const std::size_t n = literal_length(s, i, is_float);
            const std::string text = s.substr(i, n);
            if (n == 0 || (i + n < s.size() && (ident_char(s[i + n]) || s[i + n] == '.')))
                fail(path, line, "'" + s.substr(i, n + 1) + "' is no WGSL number");
            if (!is_float && text.size() > 1 && text[0] == '0' && digit(text[1]))
                fail(path, line, "'" + text + "': a decimal integer literal has no leading zero in WGSL");
            out.push_back({is_float ? token::kind::float_literal : token::kind::int_literal, text, line});
            i += n;
            continue;
        }
        if (ident_start(c)) {
            std::size_t j = i;
            while (j < s.size() && ident_char(s[j])) ++j;
            const std::string word = s.substr(i, j - i);
            out.push_back({word == "_" ? token::kind::punct : token::kind::ident, word, line});
            i = j;
            continue;
        }
        if (starts.count(i) || ends.count(i)) {
            out.push_back({starts.count(i) ? token::kind::template_start : token::kind::template_end, std::string(1, c), line});
            ++i;
            continue;
        }
        std::string op;
        for (const char* o : operators)
            if (s.compare(i, std::char_traits<char>::length(o), o) == 0) {
                op = o;
                break;
            }
        if (op.empty()) {
            if (std::string("&|^~!@/[]{}():,=<>%-+.;*").find(c) == std::string::npos) fail(path, line, stray(c));
            op = std::string(1, c);
        }
        out.push_back({token::kind::punct, op, line});
        i += op.size();
    }
    out.push_back({token::kind::end, "", line_of[s.size()]});
    return out;
}

bool reserved(const std::string& w) {
    static const std::set<std::string> words{
        // keywords (#keyword-summary)
        "alias", "break", "case", "const", "const_assert", "continue", "continuing", "default", "diagnostic", "discard",
        "else", "enable", "false", "fn", "for", "if", "let", "loop", "override", "requires", "return", "struct", "switch",
        "true", "var", "while",
        // reserved words (#reserved-words)
        "NULL", "Self", "abstract", "active", "alignas", "alignof", "as", "asm", "asm_fragment", "async", "attribute", "auto",
        "await", "become", "cast", "catch", "class", "co_await", "co_return", "co_yield", "coherent", "column_major",
        "common", "compile", "compile_fragment", "concept", "const_cast", "consteval", "constexpr", "constinit", "crate",
        "debugger", "decltype", "delete", "demote", "demote_to_helper", "do", "dynamic_cast", "enum", "explicit", "export",
        "extends", "extern", "external", "fallthrough", "filter", "final", "finally", "friend", "from", "fxgroup", "get",
        "goto", "groupshared", "highp", "impl", "implements", "import", "inline", "instanceof", "interface", "layout",
        "lowp", "macro", "macro_rules", "match", "mediump", "meta", "mod", "module", "move", "mut", "mutable", "namespace",
        "new", "nil", "noexcept", "noinline", "nointerpolation", "non_coherent", "noncoherent", "noperspective", "null",
        "nullptr", "of", "operator", "package", "packoffset", "partition", "pass", "patch", "pixelfragment", "precise",
        "precision", "premerge", "priv", "protected", "pub", "public", "readonly", "ref", "regardless", "register",
        "reinterpret_cast", "require", "resource", "restrict", "self", "set", "shared", "sizeof", "smooth", "snorm",
        "static", "static_assert", "static_cast", "std", "subroutine", "super", "target", "template", "this",
        "thread_local", "throw", "trait", "try", "type", "typedef", "typeid", "typename", "typeof", "union", "unless",
        "unorm", "unsafe", "unsized", "use", "using", "varying", "virtual", "volatile", "wgsl", "where", "with",
        "writeonly", "yield"};
    return words.count(w) > 0;
}

}  // namespace verify::wgsl
