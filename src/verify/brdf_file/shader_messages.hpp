// What the two compilers a shader goes through said, in a shader programmer's words
// (docs/brdf-code.md#what-is-supported): glslangValidator's first error at the file's line, and
// the C++ compiler's first error about the translation mapped back to the file's line and the
// construct it could not run, never its own text.
#pragma once
#include <string>

#include "shader_analysis.hpp"

namespace verify {

// glslangValidator's output (ERROR: 0:12: message, or a link error such as its recursion check):
// the message, with `line` the file's line (0 where none), for a file whose last line is `last`.
std::string glslang_message(const std::string& out, const shader_source& s, const shader_analysis& a, int last, int& line);

// The C++ compiler's output on the translation: what the file's line `line` holds that normzoo
// does not run, said in shading terms, with that line's code.
std::string compiler_message(const std::string& out, const shader_source& s, int& line);

}  // namespace verify
