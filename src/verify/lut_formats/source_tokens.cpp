// A source file's tokens (source_tokens.hpp).
#include "source_tokens.hpp"

#include <cstring>

#include "../args.hpp"

namespace verify {
namespace {

bool name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '$'; }
bool digit(char c) { return c >= '0' && c <= '9'; }
bool name_char(char c) { return name_start(c) || digit(c); }

struct lexer {
    const std::string& path;
    const std::string& s;
    bool preprocessor;
    std::size_t i = 0, line = 1;
    bool line_start = true;
    std::vector<source_token> out;

    bad_input bad(std::size_t at_line, const std::string& what) const {
        return bad_input(path + ":" + std::to_string(at_line) + ": " + what);
    }
    void push(source_token::kind k, std::size_t from, std::size_t to, std::size_t at_line) {
        out.push_back({k, std::string_view(s).substr(from, to - from), at_line});
    }
    // returns whether a comment was skipped
    bool comment() {
        if (s[i] != '/' || i + 1 >= s.size()) return false;
        if (s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n') ++i;
            return true;
        }
        if (s[i + 1] != '*') return false;
        const std::size_t end = s.find("*/", i + 2);
        if (end == std::string::npos) throw bad(line, "a comment that never ends");
        for (std::size_t k = i; k < end; ++k) line += s[k] == '\n';
        i = end + 2;
        return true;
    }
    // A preprocessor line, continued over backslash-newlines, its // comment dropped.
    void directive() {
        const std::size_t from = ++i, at_line = line;
        while (i < s.size() && s[i] != '\n') {
            if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == '\n') ++line, ++i;
            ++i;
        }
        const std::string_view text = std::string_view(s).substr(from, i - from);
        out.push_back({source_token::kind::directive, text.substr(0, text.find("//")), at_line});
    }
    void number() {
        const std::size_t from = i;
        const bool hex = s[i] == '0' && i + 1 < s.size() && (s[i + 1] == 'x' || s[i + 1] == 'X');
        while (i < s.size() && (name_char(s[i]) || s[i] == '.' ||
                                (!hex && (s[i] == '+' || s[i] == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E'))))
            ++i;
        push(source_token::kind::number, from, i, line);
    }
    void string() {
        const char quote = s[i];
        const std::size_t from = i++, at_line = line;
        while (true) {
            if (i >= s.size() || (quote != '`' && s[i] == '\n')) throw bad(at_line, std::string("a string that never ends (") + quote + ")");
            if (s[i] == '\\') {
                line += i + 1 < s.size() && s[i + 1] == '\n';
                i += 2;
                continue;
            }
            line += s[i] == '\n';
            if (s[i++] == quote) break;
        }
        push(source_token::kind::string, from, i, at_line);
    }
    void punct() {
        const std::size_t from = i;
        const char c = s[i++], next = i < s.size() ? s[i] : '\0';
        if ((std::strchr("=!<>+-*/%&|^", c) && next == '=') || (c == '=' && next == '>') || (c == ':' && next == ':')) ++i;
        if ((c == '=' || c == '!') && next == '=' && i < s.size() && s[i] == '=') ++i;  // === and !==
        push(source_token::kind::punct, from, i, line);
    }
    void run() {
        while (i < s.size()) {
            const char c = s[i];
            if (c == '\n') {
                ++line, ++i, line_start = true;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || comment()) {
                if (c != '/') ++i;
            } else if (preprocessor && line_start && c == '#') {
                directive();
            } else {
                line_start = false;
                if (name_start(c) || (c == '#' && !preprocessor)) {
                    const std::size_t from = i++;
                    while (i < s.size() && name_char(s[i])) ++i;
                    push(source_token::kind::name, from, i, line);
                } else if (digit(c) || (c == '.' && i + 1 < s.size() && digit(s[i + 1]))) {
                    number();
                } else if (c == '"' || c == '\'' || c == '`') {
                    string();
                } else {
                    punct();
                }
            }
        }
    }
};

}  // namespace

std::vector<source_token> tokenize_source(const std::string& path, const std::string& text, bool preprocessor) {
    lexer l{path, text, preprocessor, 0, 1, true, {}};
    l.run();
    return std::move(l.out);
}

}  // namespace verify
