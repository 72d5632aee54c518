#include "shader_screen.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>

#include "../args.hpp"

namespace verify {

namespace {

[[noreturn]] void refuse(const std::string& path, int line, const std::string& what) {
    throw bad_input(path + ":" + std::to_string(line) + ": " + what);
}

std::string hex(unsigned char ch) {
    char h[8];
    std::snprintf(h, sizeof h, "0x%02x", ch);
    return h;
}

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The first phases of the preprocessor's reading: CR LF as LF, then every line splice (a backslash
// at a line's end) joined, the newlines it removes put back after the joined line, so that each
// line keeps its number. Refused: a control character that may end a line for one reader and not
// another (a lone CR, a vertical tab), and a backslash anywhere else (shading code has none).
std::string splice(const std::string& path, const std::string& text) {
    std::string t;
    t.reserve(text.size());
    int line = 1, owed = 0;  // owed: the newlines of the splices since the last line's end
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto ch = static_cast<unsigned char>(text[i]);
        if (ch == '\r' && i + 1 < text.size() && text[i + 1] == '\n') continue;
        if (ch == '\n') {
            t.append(1 + static_cast<std::size_t>(owed), '\n');
            line += 1 + owed, owed = 0;
            continue;
        }
        if ((ch < 0x20 && ch != '\t') || ch == 0x7f)
            refuse(path, line + owed, "control character " + hex(ch) + " refused: a reader may take it for the end of a line");
        if (ch == '\\') {
            std::size_t j = i + 1;
            if (j + 1 < text.size() && text[j] == '\r' && text[j + 1] == '\n') ++j;
            if (j < text.size() && text[j] == '\n') {
                ++owed, i = j;
                continue;
            }
            refuse(path, line + owed, "a backslash that does not end a line (a line continuation) is refused: shading code has none");
        }
        t += static_cast<char>(ch);
    }
    t.append(static_cast<std::size_t>(owed), '\n');
    return t;
}

// What the directive's name allows; the caller keeps, drops or rewrites each.
void check_directive(const std::string& path, const directive& d, bool hlsl) {
    static const std::set<std::string> known{"",      "define", "undef", "if",      "ifdef",     "ifndef", "elif",
                                             "else",  "endif",  "error", "include", "pragma"};
    if (d.name == "version" || d.name == "extension") {
        if (hlsl) refuse(path, d.line, "#" + d.name + " is GLSL's: an HLSL file has none");
        return;
    }
    if (d.name == "line")
        refuse(path, d.line, "#line is refused: normzoo maps every line of the code to its file itself (docs/brdf-code.md#safety)");
    if (!known.count(d.name))
        refuse(path, d.line, "'#" + d.name + "' is not a directive of the shading languages' preprocessor (docs/brdf-code.md#the-preprocessor)");
}

// Reads the header name of an #include at t[i] ('"' or '<') into d.rest, raw: no comment starts in it.
std::size_t header_name(const std::string& path, const std::string& t, std::size_t i, directive& d) {
    const char close = t[i] == '"' ? '"' : '>';
    const std::size_t end = t.find_first_of(std::string(1, close) + "\n", i + 1);
    if (end == std::string::npos || t[end] != close) refuse(path, d.line, "#include: the file's name does not end on its line");
    d.rest += t.substr(i, end - i + 1);
    return end;
}

}  // namespace

// Read as the preprocessor reads: after the splices, comments are spaces; a directive is a line
// whose first token is #. Refused, since the two readings could differ or shading code never
// has them: a comment that does not end, or that spans lines from a directive's line or before a
// #; a # that does not begin a directive outside one; %: (the digraph of #); string and character
// literals but an #include's file name; names holding normzoo_; directives that are not the
// shading languages' (docs/brdf-code.md#safety).
screened_text screen_input(const std::string& path, const std::string& text, bool hlsl) {
    screened_text s{splice(path, text), {}};
    const std::string& t = s.text;
    int line = 1;
    bool line_start = true, after_long_comment = false;
    directive d;
    bool in_directive = false, name_read = false;
    auto finish = [&](std::size_t at) {
        if (!in_directive) return;
        d.end = at;
        while (!d.rest.empty() && (d.rest.back() == ' ' || d.rest.back() == '\t')) d.rest.pop_back();
        check_directive(path, d, hlsl);
        s.directives.push_back(d);
        in_directive = false;
    };
    for (std::size_t i = 0; i < t.size(); ++i) {
        const char c = t[i];
        if (c == '\n') {
            finish(i);
            ++line, line_start = true, after_long_comment = false;
            continue;
        }
        if (c == '/' && i + 1 < t.size() && (t[i + 1] == '/' || t[i + 1] == '*')) {
            std::size_t end = t[i + 1] == '/' ? t.find('\n', i) : t.find("*/", i + 2);
            if (end == std::string::npos && t[i + 1] == '*') refuse(path, line, "a comment that does not end");
            if (end == std::string::npos) end = t.size();
            const auto newlines = static_cast<int>(std::count(t.begin() + static_cast<std::ptrdiff_t>(i), t.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
            if (newlines > 0 && in_directive) refuse(path, line, "a comment that begins on a directive's line must end on it");
            if (newlines > 0) after_long_comment = true;
            line += newlines;
            if (in_directive) d.rest += ' ';
            i = t[i + 1] == '/' ? end - 1 : end + 1;
            continue;
        }
        if (c == ' ' || c == '\t') {
            if (in_directive && name_read) d.rest += c;
            continue;
        }
        if (t.compare(i, 2, "%:") == 0) refuse(path, line, "the digraph %: (another spelling of #) is refused");
        if (t.compare(i, 8, "normzoo_") == 0) refuse(path, line, "names holding normzoo_ are reserved for the translation");
        if (in_directive) {
            if (!name_read) {
                std::size_t k = i;
                while (k < t.size() && word_char(t[k])) ++k;
                d.name = t.substr(i, k - i);
                name_read = true;
                // a name that goes on in $ or a byte that is not ASCII reads otherwise to another preprocessor
                if (k < t.size() && (t[k] == '$' || static_cast<unsigned char>(t[k]) >= 0x80))
                    refuse(path, line, "'#" + d.name + t[k] + "...' is not a directive normzoo reads");
                i = k - 1;
            } else if (d.name == "include" && (c == '"' || c == '<') && d.rest.find_first_not_of(" \t") == std::string::npos) {
                i = header_name(path, t, i, d);
            } else if (c == '"' || c == '\'') {
                refuse(path, line, "string and character literals are refused: shading code has none, and one could hide a comment");
            } else {
                d.rest += c;
            }
            continue;
        }
        if (c == '#') {
            if (after_long_comment) refuse(path, line, "a # after a comment that spans lines is refused: a directive starts its line");
            if (!line_start) refuse(path, line, "a # that does not begin a directive is refused");
            d = directive{line, i, 0, "", ""};
            in_directive = true, name_read = false;
            while (i + 1 < t.size() && (t[i + 1] == ' ' || t[i + 1] == '\t')) ++i;
            if (i + 1 >= t.size() || !word_char(t[i + 1])) name_read = true;  // the null directive, or # followed by punctuation
            continue;
        }
        if (c == '"' || c == '\'') refuse(path, line, "string and character literals are refused: shading code has none, and one could hide a comment");
        line_start = false, after_long_comment = false;
    }
    finish(t.size());
    return s;
}

void screen_output_line(const std::string& line, const std::string& where) {
    auto fail = [&](const std::string& what) { throw bad_input(where + ": " + what); };
    for (std::size_t i = 0; i < line.size(); ++i) {
        const auto ch = static_cast<unsigned char>(line[i]);
        if (ch == '#') fail("a # after preprocessing (a macro made it): the code normzoo compiles has no directive");
        if (ch == '"' || ch == '\'') fail("a string after preprocessing (the # operator, __FILE__ or __DATE__ made it): shading code has none");
        if (ch == '\\') fail("a backslash after preprocessing");
        if ((ch < 0x20 && ch != '\t') || ch >= 0x7f) fail("byte " + hex(ch) + " outside a comment: shading code is ASCII");
        if (line.compare(i, 2, "%:") == 0) fail("the digraph %: (another spelling of #) is refused");
        if (line.compare(i, 8, "normzoo_") == 0) fail("names holding normzoo_ are reserved for the translation (a macro made one)");
    }
}

void check_define(const std::string& definition) {
    const std::size_t eq = definition.find('=');
    const std::string name = definition.substr(0, eq), value = eq == std::string::npos ? "" : definition.substr(eq + 1);
    auto fail = [&](const std::string& what) { throw bad_input("--define " + definition + ": " + what); };
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0])) || !std::all_of(name.begin(), name.end(), word_char))
        fail("'" + name + "' is not a macro name (NAME or NAME=VALUE)");
    if (name == "defined" || name.rfind("__", 0) == 0 || name.rfind("GL_", 0) == 0)
        fail(name + " is reserved (defined, names starting __ or GL_)");
    if (definition.find("normzoo_") != std::string::npos) fail("names holding normzoo_ are reserved for the translation");
    for (unsigned char ch : value)
        if (ch < 0x20 || ch >= 0x7f || ch == '"' || ch == '\'' || ch == '\\' || ch == '#')
            fail(ch == '"' || ch == '\'' ? "a value holds no string" : "a value holds printable ASCII but \" ' \\ and #");
    if (value.find("//") != std::string::npos || value.find("/*") != std::string::npos || value.find("%:") != std::string::npos)
        fail("a value holds no comment and no %:");
}

}  // namespace verify
