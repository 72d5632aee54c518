// The tokens of a source file (C, C++, JavaScript, TypeScript, WGSL, GLSL), as much as finding a
// number array needs: names, numbers, strings, punctuation; comments dropped, preprocessor lines
// kept as one token each (C-like files only: in JavaScript '#' starts a private name).
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace verify {

struct source_token {
    enum class kind { name, number, string, punct, directive };
    kind what;
    std::string_view text;  // into the file's text: a string's with its quotes; a directive's line without the '#'
    std::size_t line;       // 1-based
    bool is(const char* p) const { return what == kind::punct && text == p; }
};

// The tokens refer to text, which must outlive them (a token takes 32 bytes, whatever its length).
// Throws bad_input (args.hpp) naming path and the line of an unterminated comment or string.
std::vector<source_token> tokenize_source(const std::string& path, const std::string& text, bool preprocessor);

}  // namespace verify
