// libFuzzer harness of the shader files (docs/brdf-code.md): bytes -> a .brdf or a plain file's
// text -> parse_shader_text -> preprocess_shader (mcpp, a capped child) -> translate_shader (the
// analysis and its refusals, the rewrites). The reader must accept the file or throw bad_input
// naming it; any other exception, a crash, a leak, a hang or a sanitizer report is a finding. An
// accepted file must be one the compiler may see: no directive however spelled in the
// preprocessed code, every parameter in its range, and a translation that keeps the code's lines
// and pairs the parentheses it adds.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "args.hpp"
#include <unistd.h>

#include <filesystem>

#include "brdf_file/brdf_file.hpp"
#include "brdf_file/preprocess.hpp"
#include "brdf_file/shader_translate.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "shader_fuzzer: %s\n", what.c_str());
    std::abort();
}

// The oracle of "no directive", written apart from the screening: nothing that can end a line or a
// comment where a reader would not expect it, then the code with its comments blanked (their
// newlines kept), line by line: none starts with # or %:. The same of the translation the
// compiler sees, whose own directives are #line and the preludes' #includes (`translated`; its
// path is the only string in it).
void no_hidden_directive(const std::string& code, bool translated = false) {
    for (std::size_t i = 0; i < code.size(); ++i) {
        const auto ch = static_cast<unsigned char>(code[i]);
        const bool crlf = ch == '\r' && i + 1 < code.size() && code[i + 1] == '\n';
        if ((ch < 0x20 && ch != '\t' && ch != '\n' && !crlf) || ch == 0x7f) finding("accepted a control character");
        if (ch == '\\') finding("accepted a backslash");
        // the code may hold trigraphs (no reader takes them: docs/brdf-code.md#safety); the
        // translation never, since it spaces any a rewrite would make (finding 12)
        if (translated && code.compare(i, 2, "??") == 0) {
            const char t = i + 2 < code.size() ? code[i + 2] : ' ';
            if (std::string("=/'()!<>-").find(t) != std::string::npos) finding("accepted a trigraph");
        }
    }
    std::string blanked = code;
    for (std::size_t i = 0; i + 1 < blanked.size(); ++i) {
        if (blanked[i] != '/' || (blanked[i + 1] != '/' && blanked[i + 1] != '*')) continue;
        const bool line = blanked[i + 1] == '/';
        std::size_t end = line ? blanked.find('\n', i) : blanked.find("*/", i + 2);
        if (end == std::string::npos) {
            if (!line) finding("accepted a comment that does not end");
            end = blanked.size();
        } else if (!line) {
            end += 2;
        }
        for (std::size_t j = i; j < end; ++j)
            if (blanked[j] != '\n') blanked[j] = ' ';
        i = end - 1;
    }
    if (!translated && blanked.find_first_of("\"'") != std::string::npos) finding("accepted a string or character literal");
    std::size_t start = 0;
    while (start < blanked.size()) {
        const std::size_t end = std::min(blanked.find('\n', start), blanked.size());
        const std::size_t at = blanked.find_first_not_of(" \t\r", start);
        if (at < end && (blanked[at] == '#' || blanked.compare(at, 2, "%:") == 0)) {
            const std::size_t name = blanked.find_first_not_of(" \t", at + (blanked[at] == '#' ? 1 : 2));
            auto is = [&](const std::string& word) {
                const std::size_t after = name + word.size();
                return name != std::string::npos && blanked.compare(name, word.size(), word) == 0 &&
                       !(after < blanked.size() && (std::isalnum(static_cast<unsigned char>(blanked[after])) || blanked[after] == '_'));
            };
            const std::string line = blanked.substr(at, end - at);
            const bool generated = translated && (is("line") || line == "#include \"prelude.hpp\"" ||
                                                  line == "#include \"prelude_checks.hpp\"" || line == "#include \"half_prelude.hpp\"");
            if (!generated) finding(translated ? "a translation with a directive of the file's" : "a directive left in the preprocessed code");
        }
        start = end + 1;
    }
}

// The code with its comments as spaces (their newlines kept).
std::string without_comments(std::string c) {
    for (std::size_t i = 0; i + 1 < c.size(); ++i) {
        if (c[i] != '/' || (c[i + 1] != '/' && c[i + 1] != '*')) continue;
        const bool line = c[i + 1] == '/';
        std::size_t end = line ? c.find('\n', i) : c.find("*/", i + 2);
        end = end == std::string::npos ? c.size() : line ? end : end + 2;
        for (std::size_t j = i; j < end; ++j)
            if (c[j] != '\n') c[j] = ' ';
        i = end - 1;
    }
    return c;
}

void check_accepted(const verify::shader_source& s) {
    for (const auto& p : s.parameters) {
        if (p.name.empty()) finding("accepted a parameter without a name");
        for (double d : p.default_value)
            if (p.type != verify::shader_parameter::kind::color && !(d >= p.min && d <= p.max))
                finding("accepted a default outside its range");
    }
    no_hidden_directive(s.code);
    const std::string t = verify::translate_shader(s, "prelude.hpp");
    if (t.find("#include \"prelude.hpp\"") == std::string::npos) finding("a translation without its prelude");
    // the programs: double and float, and binary16 where the code declares reduced precision
    const std::size_t programs = t.find("namespace normzoo_half {") != std::string::npos ? 3 : 2;
    // the file's comments become spaces: the translation's only comments are its own (the head
    // and the programs' namespaces' ends), so a // or /* beyond them is tokens joined into one
    std::size_t slashes = 0;
    for (std::size_t at = t.find("//"); at != std::string::npos; at = t.find("//", at + 2)) ++slashes;
    if (slashes != 1 + programs || t.find("/*") != std::string::npos) finding("a translation with a comment the file did not have");
    no_hidden_directive(t, true);
    // line for line: the body's newlines all reach the translation, once a program
    const auto lines = static_cast<std::size_t>(std::count(s.code.begin(), s.code.end(), '\n'));
    if (static_cast<std::size_t>(std::count(t.begin(), t.end(), '\n')) < programs * lines) finding("a translation that lost lines");
    // the rewrites add and leave out parentheses in pairs ((v ->* normzoo_sw_xy), a prototype):
    // the translation, once a program, opens as many more than it closes as the code without its
    // comments
    const auto excess = [](const std::string& x) { return std::count(x.begin(), x.end(), '(') - std::count(x.begin(), x.end(), ')'); };
    if (excess(t) != static_cast<std::ptrdiff_t>(programs) * excess(without_comments(s.code)))
        finding("a translation whose parentheses do not pair as the code's");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    // the first byte picks the format: a .brdf file, or a plain file
    // in a folder of its own, empty: an #include finds nothing (the preprocess harness fuzzes them)
    static const std::filesystem::path dir = [] {
        const auto d = std::filesystem::temp_directory_path() / ("normzoo-shader-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        ::setenv("NORMZOO_SHADER_SECONDS", "2", 1);  // libFuzzer's -timeout is 5 s
        return d;
    }();
    const std::string path = (dir / (data[0] & 1 ? "fuzz.brdf" : "fuzz.glsl")).string();
    const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        check_accepted(verify::preprocess_shader(verify::parse_shader_text(path, text), {}, verify::shader_caps_from_environment()));
    } catch (const verify::bad_input& e) {
        if (std::string(e.what()).rfind(path, 0) != 0) finding(std::string("a message that does not name the file: ") + e.what());
    } catch (const std::exception& e) {
        finding(std::string("an exception that is not bad_input: ") + e.what());
    }
    return 0;
}
