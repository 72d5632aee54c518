// A shader's code (GLSL, or the HLSL subset of docs/brdf-code.md#plain-files) written as C++ over
// GLM, twice: in double and in float (docs/brdf-code.md#how-the-shader-runs). Token by token, line
// for line, so that the compiler's line numbers are the file's.
#pragma once
#include <string>

#include "brdf_file.hpp"

namespace verify {

// The C++ translation unit: the shader as a struct per number type, with its parameters as
// members, and the C entry points the command loads (compiled_shader.hpp). With binary16, where
// the code declares reduced precision, a third program with its values of those types in binary16
// (half_prelude.hpp) and the entry points normzoo_*_half.
std::string translate_shader(const shader_source& s, const std::string& prelude_path, bool binary16 = true);

}  // namespace verify
