// A BRDF Explorer file (.brdf) or a plain shader file with a TOML header, read into what the
// command compiles (docs/brdf-code.md#files). Bad input throws bad_input naming the file and line.
#pragma once
#include <string>
#include <vector>

namespace verify {

struct shader_parameter {
    enum class kind { real, boolean, color };
    kind type = kind::real;
    std::string name;
    double min = 0, max = 1;             // float parameters; bool: 0 .. 1; color: each channel 0 .. inf
    std::vector<double> default_value;   // one value, or three for a color
    int line = 0;                        // where it is declared
    std::size_t slots() const { return type == kind::color ? 3 : 1; }
};

// Where a line of preprocessed code comes from.
struct code_origin {
    std::string file;  // as messages name it: the path given, or an included file's
    int line = 0;
};

struct shader_source {
    std::string path;                       // as given
    enum class language { glsl, hlsl, wgsl } lang = language::glsl;  // wgsl until translated (wgsl.hpp)
    std::vector<shader_parameter> parameters;
    std::string code;                       // the shader block
    int first_line = 1;                     // the file's line of the code's first line
    std::string function = "BRDF";         // the function that is the BRDF
    // Once preprocessed (preprocess.hpp): the file and line of each line of `code`, the #version
    // ("300 es"; empty: none), the active #extension directives ("NAME : behavior"), and the
    // default float precision its `precision` statements set (they are dropped from `code`).
    std::vector<code_origin> origin;
    std::string version;
    std::vector<std::string> extensions;
    std::string float_precision;
    bool preprocessed = false;              // what compiled_shader takes
    // The textures --texture binds (docs/brdf-code.md#textures): the names of the code's
    // sampler2D or Texture2D uniforms, in the order their tables are bound.
    std::vector<std::string> textures;
    // "FILE:LINE" of the code's line `line`, numbered from first_line as the file's lines are.
    std::string place(int line) const;
};

// Reads a .brdf file (BRDF Explorer's format) or, for .glsl / .hlsl / any other extension, a
// plain shader file that starts with a TOML header in comments (docs/brdf-code.md#plain-files).
shader_source read_shader_file(const std::string& path);

// The same from a file's text (`path` names it in messages and decides its format).
shader_source parse_shader_text(const std::string& path, const std::string& text);

}  // namespace verify
