// What a shader's code declares, read from its tokens before anything is compiled
// (docs/brdf-code.md#what-is-supported): its functions with their parameters and the calls they
// make, its structs, the uniforms it declares (GLSL's uniform, HLSL's cbuffer members and plain
// globals), the statements the translation leaves out, and where reduced precision is declared.
// The checks on it refuse, naming the file and line in a shader programmer's words, what a GPU
// compiler refuses (recursion) and what would not bind to the file's header (a uniform it does
// not declare, or of another type).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "brdf_file.hpp"
#include "shader_tokens.hpp"

namespace verify {

// A declared name: a function's parameter, a struct's field, a uniform.
struct shader_declared {
    enum class direction { in, out, inout };
    std::string type;             // as written, without qualifiers or array brackets: float, vec3, float3, S
    std::string element;          // HLSL's Texture2D<float2>: its element type, float2; empty without one
    std::string name;             // empty for an unnamed parameter
    bool array = false;
    bool reduced_precision = false;  // mediump, lowp, half, min16float, ...
    direction dir = direction::in;
    int line = 0;
    std::size_t end = token_list::none;  // its declarator's last token
};

struct shader_call {
    std::string name;
    std::size_t arity = 0;
    int line = 0;
};

struct shader_function {
    std::string name;
    std::string return_type;  // as written, without qualifiers: float, vec3, float[3]
    int line = 0;
    std::vector<shader_declared> params;
    std::size_t first = 0, open = 0, close = 0;  // its first token, the braces of its body
    std::vector<shader_call> calls;               // to the file's own functions
    bool reduced_precision = false;               // declared in it, or the file's default precision where it starts
};

struct shader_struct {
    std::string name;
    int line = 0;
    std::size_t open = 0, close = 0;  // its braces
    bool local = false;               // declared in a function
    std::vector<shader_declared> fields;
};

struct shader_analysis {
    std::vector<shader_function> functions;  // definitions, in the file's order
    std::vector<std::string> declared;       // every function name, prototypes included
    std::vector<shader_struct> structs;
    std::vector<shader_declared> uniforms;   // what the code declares as uniforms
    // Token ranges [first, last] the translation leaves out: uniform declarations, cbuffers,
    // precision statements, prototypes, HLSL's attributes ([unroll]).
    std::vector<std::pair<std::size_t, std::size_t>> removed;
    // The `const` of a global constant of an integer or bool type: a C++ constant expression, as
    // an array's size needs.
    std::vector<std::size_t> constant_integers;
    bool reduced_precision = false;  // anywhere in the file
    int reduced_precision_line = 0;  // its first line; 0 where only a precision statement declares it
};

// The type names of each language (GLSL's and HLSL's built-in types, without the file's structs).
bool is_builtin_type(const std::string& w, shader_source::language lang);
// mediump, lowp, half, min16float, float16_t and their vectors.
bool is_reduced_precision(const std::string& w);

// Reads the code's tokens. Throws bad_input naming the file and line where brackets do not
// balance and for a uniform block, which normzoo does not read.
shader_analysis analyze_shader(const shader_source& s, const token_list& t);

// The refusals: a uniform the header does not declare (with the header's lines to add) or of
// another type; a function named by the header that is missing or does not take five vec3 and
// return a float or a vec3; recursion, direct or through other functions.
void check_shader(const shader_source& s, const shader_analysis& a, const token_list& t);

}  // namespace verify
