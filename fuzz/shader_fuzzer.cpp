// libFuzzer harness of the shader files (docs/brdf-code.md): bytes -> a .brdf or a plain file's
// text -> parse_shader_text -> translate_shader. The reader must accept the file or throw
// bad_input naming it; any other exception, a crash, a leak or a sanitizer report is a finding.
// An accepted file must be one the compiler may see: no directive but #define, every parameter
// in its range, and a translation that keeps the file's lines.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "args.hpp"
#include "brdf_file/brdf_file.hpp"
#include "brdf_file/shader_translate.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "shader_fuzzer: %s\n", what.c_str());
    std::abort();
}

void check_accepted(const verify::shader_source& s) {
    for (const auto& p : s.parameters) {
        if (p.name.empty()) finding("accepted a parameter without a name");
        for (double d : p.default_value)
            if (p.type != verify::shader_parameter::kind::color && !(d >= p.min && d <= p.max))
                finding("accepted a default outside its range");
    }
    std::size_t at = 0;
    while ((at = s.code.find('#', at)) != std::string::npos) {
        const std::size_t line = s.code.rfind('\n', at);
        const std::size_t start = line == std::string::npos ? 0 : line + 1;
        if (s.code.find_first_not_of(" \t", start) == at && s.code.compare(at, 7, "#define") != 0)
            finding("accepted a directive other than #define");
        ++at;
    }
    const std::string t = verify::translate_shader(s, "prelude.hpp");
    if (t.find("#include \"prelude.hpp\"") == std::string::npos) finding("a translation without its prelude");
    // line for line: the body's newlines all reach the translation, twice
    const auto lines = static_cast<std::size_t>(std::count(s.code.begin(), s.code.end(), '\n'));
    if (static_cast<std::size_t>(std::count(t.begin(), t.end(), '\n')) < 2 * lines) finding("a translation that lost lines");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    // the first byte picks the format: a .brdf file, or a plain file
    const std::string path = data[0] & 1 ? "fuzz.brdf" : "fuzz.glsl";
    const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        check_accepted(verify::parse_shader_text(path, text));
    } catch (const verify::bad_input& e) {
        if (std::string(e.what()).rfind(path, 0) != 0) finding(std::string("a message that does not name the file: ") + e.what());
    } catch (const std::exception& e) {
        finding(std::string("an exception that is not bad_input: ") + e.what());
    }
    return 0;
}
