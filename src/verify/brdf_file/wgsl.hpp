// A .wgsl file's BRDF (docs/brdf-code.md#wgsl), translated into the GLSL the rest of the pipeline
// takes: checked first as WGSL, with WGSL's types and strictness (no implicit conversion between
// f32 and i32, abstract literals and constants, no recursion, every path of a function with a
// value returning one), so that what WGSL refuses, and what lies outside the subset normzoo runs,
// is refused with the file, the line and a WGSL programmer's words, never as the GLSL or C++ it
// becomes. The GLSL keeps the file's lines: every statement on its own line.
#pragma once
#include <cstddef>

#include "brdf_file.hpp"

namespace verify {

// Replaces a WGSL shader_source's code with its GLSL translation (language glsl, the function the
// GLSL name of the BRDF). Bad input throws bad_input "PATH:LINE: ...". What the translation holds
// grows with the code's tokens, at most bytes_per_token each: `memory_bytes` caps it (a file of
// more tokens is refused, naming NORMZOO_SHADER_MEMORY_MB).
constexpr std::size_t wgsl_bytes_per_token = 512;
void translate_wgsl(shader_source& s, std::size_t memory_bytes = std::size_t(2048) << 20);

}  // namespace verify
