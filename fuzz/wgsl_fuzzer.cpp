// libFuzzer harness of the WGSL translator (docs/brdf-code.md#wgsl): bytes -> a .wgsl file ->
// parse_shader_text -> preprocess_shader, where the translator takes the preprocessor's place (it
// checks the WGSL and writes GLSL; no child process runs) -> translate_shader (the GLSL to C++). The first byte picks the file: odd, a fixed header (three parameters, one of each kind)
// before the rest, so that the bytes reach the translator; even, the bytes alone. The reader must
// accept the file or throw bad_input naming it; any other exception, a crash, a leak or a
// sanitizer report is a finding. An accepted file must have become GLSL that keeps its lines, in
// which every name of the file is the translation's (its prefix), a parameter's, or GLSL's own.
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "args.hpp"
#include "brdf_file/brdf_file.hpp"
#include "brdf_file/preprocess.hpp"
#include "brdf_file/shader_translate.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "wgsl_fuzzer: %s\n", what.c_str());
    std::abort();
}

const char* header = "// [brdf]\n// function = \"BRDF\"\n// [parameters.k]\n// type = \"float\"\n// range = [0, 1]\n// default = 0.5\n"
                     "// [parameters.flag]\n// type = \"bool\"\n// default = true\n// [parameters.tint]\n// type = \"color\"\n"
                     "// default = [1, 0.5, 0.25]\n//\n";

// The words the translation's GLSL may hold besides its own names and the parameters'.
bool glsl_word(const std::string& w) {
    static const std::set<std::string> words{
        "float", "int", "bool", "void", "vec2", "vec3", "vec4", "mat2", "mat3", "mat4", "struct", "return", "if", "else",
        "for", "while", "break", "continue", "true", "false", "abs", "acos", "asin", "atan", "ceil", "clamp", "cos", "cross",
        "degrees", "distance", "dot", "exp", "exp2", "faceforward", "floor", "fract", "inversesqrt", "length", "log",
        "log2", "max", "min", "mix", "normalize", "pow", "radians", "reflect", "refract", "sign", "sin", "smoothstep",
        "sqrt", "step", "tan", "transpose",
        // the helpers' own locals (wgsl_helpers.cpp) and the exponent of a float literal
        "x", "r", "a", "b", "c", "d", "e", "f", "m", "s", "lo", "hi", "minor"};
    return words.count(w) > 0;
}

void check_accepted(const std::string& input, const verify::shader_source& s) {
    if (s.lang != verify::shader_source::language::glsl || !s.preprocessed) finding("a WGSL file not translated");
    std::size_t lines = 0;
    for (std::size_t at = 0; at < input.size(); at = input.find('\n', at) == std::string::npos ? input.size() : input.find('\n', at) + 1) ++lines;
    std::size_t newlines = 0;
    for (char c : s.code) newlines += c == '\n';
    if (newlines != lines) finding("a translation that does not keep the file's lines");
    const std::string prefix = s.function.substr(0, s.function.find('u', 4));
    if (prefix.compare(0, 4, "wgsl") != 0) finding("the BRDF's GLSL name is not the translation's: " + s.function);
    std::set<std::string> parameters;
    for (const auto& p : s.parameters) parameters.insert(p.name);
    for (std::size_t i = 0; i < s.code.size();) {
        const char c = s.code[i];
        const bool printable = c == '\n' || (c >= 0x20 && c < 0x7f);
        if (!printable || c == '#' || c == '"' || c == '\\' || c == '\'' || c == '@' || c == '`' || c == '$')
            finding(std::string("the GLSL holds a byte the translation never writes: ") + c);
        if (s.code.compare(i, 2, "//") == 0 || s.code.compare(i, 2, "/*") == 0) finding("the GLSL holds a comment");
        if (s.code.compare(i, 2, "??") == 0) finding("the GLSL holds a trigraph's start");
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            std::size_t j = i;
            while (j < s.code.size() && (std::isalnum(static_cast<unsigned char>(s.code[j])) || s.code[j] == '_')) ++j;
            const std::string w = s.code.substr(i, j - i);
            const bool swizzle = i > 0 && s.code[i - 1] == '.' && w.size() <= 4 && w.find_first_not_of("xyzw") == std::string::npos;
            const bool argument = w.size() > 1 && w[0] == 'a' && w.find_first_not_of("0123456789", 1) == std::string::npos;  // a maker's
            if (w.compare(0, prefix.size(), prefix) != 0 && !parameters.count(w) && !glsl_word(w) && !swizzle && !argument)
                finding("a name of the file reached the GLSL as it is: " + w);
            i = j;
            continue;
        }
        ++i;
    }
    (void)verify::translate_shader(s, "prelude.hpp");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string path = "fuzz.wgsl";
    const std::string text = std::string(data[0] & 1 ? header : "") + std::string(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        check_accepted(text, verify::preprocess_shader(verify::parse_shader_text(path, text), {}, verify::shader_caps{}));
    } catch (const verify::bad_input& e) {
        if (std::string(e.what()).rfind(path, 0) != 0) finding(std::string("a message that does not name the file: ") + e.what());
    } catch (const std::exception& e) {
        finding(std::string("an exception that is not bad_input: ") + e.what());
    }
    return 0;
}
