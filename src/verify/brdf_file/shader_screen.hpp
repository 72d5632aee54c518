// The screening of shader text on its way into the preprocessor and out of it
// (docs/brdf-code.md#safety). Going in, each file is read as the preprocessor's first phases read
// it (line splices, comments, where a directive starts), its directives listed for the caller to
// keep, drop or rewrite, and whatever could make that reading differ from the preprocessor's, or
// that shading code never holds, is refused. Coming out, the text must be plain code: a macro
// cannot have made a directive, a string, or a name reserved for the translation. Refusals throw
// bad_input naming the file and line.
#pragma once
#include <string>
#include <vector>

namespace verify {

struct directive {
    int line = 0;              // the file's line of its #
    std::size_t begin = 0;     // its span in the screened text: from the # ...
    std::size_t end = 0;       // ... to its line's end (the newline, or the text's end)
    std::string name;          // define, include, ...; empty for a # alone
    std::string rest;          // after the name, comments as spaces, trimmed
};

struct screened_text {
    std::string text;          // line splices joined, each joined line's newlines kept after it: the file's line numbers
    std::vector<directive> directives;
};

// `path` names the file in messages; `text` starts at the file's line 1. GLSL files may hold
// #version and #extension; HLSL files neither.
screened_text screen_input(const std::string& path, const std::string& text, bool hlsl);

// One line of the preprocessed code, at `where` ("FILE:LINE"): no #, no string or character
// literal, no backslash, no %:, no name starting with normzoo_, nothing but printable ASCII and tabs.
void screen_output_line(const std::string& line, const std::string& where);

// "NAME" or "NAME=VALUE" of --define: NAME an identifier, VALUE text that would pass both screens.
void check_define(const std::string& definition);

}  // namespace verify
