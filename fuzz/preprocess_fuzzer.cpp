// libFuzzer harness of the preprocessing step (docs/brdf-code.md#the-preprocessor): bytes -> a
// shader's code and a file it may include (split at the first NUL byte; the first byte picks GLSL
// or HLSL) -> preprocess_shader, which screens both, resolves the includes and runs mcpp as a
// capped child. It must give code or throw bad_input naming one of the two files (or a cap with
// its file); any other exception, a crash, a leak or a sanitizer report is a finding. Accepted
// code must be plain: no directive, no string, no name holding normzoo_, every line mapped to one
// of the two files, and nothing of the file outside the include folders.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "args.hpp"
#include "brdf_file/preprocess.hpp"

namespace fs = std::filesystem;

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "preprocess_fuzzer: %s\n", what.c_str());
    std::abort();
}

// root/ holds the file, root/inc/ the file it may include (also an include folder); outside.glsl
// beside root/ holds a token that must never reach the code.
struct folders {
    fs::path base, root, main, included;
    folders() {
        base = fs::temp_directory_path() / ("normzoo-preprocess-fuzz-" + std::to_string(::getpid()));
        root = base / "root";
        fs::create_directories(root / "inc");
        main = root / "main.glsl";
        included = root / "inc" / "b.glsl";
        std::ofstream(base / "outside.glsl") << "float LEAKED_OUTSIDE;\n";
        std::error_code ec;
        fs::create_symlink("../../outside.glsl", root / "inc" / "link.glsl", ec);
    }
};

void check_accepted(const verify::shader_source& s, const folders& f) {
    if (!s.preprocessed || s.first_line != 1) finding("a result not marked preprocessed");
    const auto lines = static_cast<std::size_t>(std::count(s.code.begin(), s.code.end(), '\n'));
    if (lines != s.origin.size()) finding("code lines and their origins differ in number");
    for (const auto& o : s.origin)
        if ((o.file != f.main.string() && o.file != f.included.string()) || o.line < 1) finding("a line mapped to " + o.file);
    if (s.code.find("LEAKED_OUTSIDE") != std::string::npos) finding("code from outside the include folders");
    if (s.code.find_first_of("#\"'\\") != std::string::npos) finding("a directive, string or backslash left in the code");
    if (s.code.find("normzoo_") != std::string::npos) finding("a name holding normzoo_ in the code");
    for (unsigned char c : s.code)
        if ((c < 0x20 && c != '\t' && c != '\n') || c >= 0x7f) finding("a byte that is not printable ASCII in the code");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const folders f;
    static const bool caps_set = [] {
        // seconds, not the default 10: libFuzzer's -timeout is 5 s
        ::setenv("NORMZOO_SHADER_SECONDS", "2", 1);
        ::setenv("NORMZOO_SHADER_TEXT_MB", "1", 1);
        ::setenv("NORMZOO_SHADER_MEMORY_MB", "512", 1);
        return true;
    }();
    (void)caps_set;
    if (size == 0) return 0;
    const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
    const std::size_t cut = bytes.find('\0');
    const std::string code = bytes.substr(0, cut), included = cut == std::string::npos ? "" : bytes.substr(cut + 1);
    std::ofstream(f.included, std::ios::binary | std::ios::trunc) << included;
    verify::shader_source raw;
    raw.path = f.main.string();
    raw.lang = data[0] & 1 ? verify::shader_source::language::hlsl : verify::shader_source::language::glsl;
    raw.code = code;
    try {
        check_accepted(verify::preprocess_shader(raw, {{"QUALITY=2"}, {(f.root / "inc").string()}}, verify::shader_caps_from_environment()),
                       f);
    } catch (const verify::bad_input& e) {
        const std::string m = e.what();
        if (m.rfind(f.main.string(), 0) != 0 && m.rfind(f.included.string(), 0) != 0)
            finding("a message that names neither file: " + m);
    } catch (const std::exception& e) {
        finding(std::string("an exception that is not bad_input: ") + e.what());
    }
    return 0;
}
