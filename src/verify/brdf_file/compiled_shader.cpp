#include "compiled_shader.hpp"

#include <dlfcn.h>
#include <signal.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <cctype>
#include <sstream>

#include "../args.hpp"
#include "shader_analysis.hpp"
#include "shader_messages.hpp"
#include "shader_translate.hpp"

#ifndef NORMZOO_SHADER_PRELUDE
#error "NORMZOO_SHADER_PRELUDE: the path of glsl_prelude.hpp, set by CMake"
#endif
#ifndef NORMZOO_SHADER_CXX
#error "NORMZOO_SHADER_CXX: the C++ compiler, set by CMake"
#endif

namespace verify {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& s) {
    std::string o = "'";
    for (char c : s) o += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return o + "'";
}

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// FNV-1a, 64 bits: the cache key of a translation (stable across runs and machines).
std::string key_of(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

fs::path cache_root() {
    if (const char* x = std::getenv("NORMZOO_CACHE_DIR"); x && *x) return fs::path(x);
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "normzoo" / "shaders";
    if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "normzoo" / "shaders";
    return fs::temp_directory_path() / "normzoo-shaders";
}

// Runs a shell command with a time cap; its output (stdout and stderr) and exit status.
int run_capped(const std::string& command, double seconds, const fs::path& log, std::string& output) {
    const std::string capped = "timeout --kill-after=5 " + std::to_string(static_cast<int>(seconds)) + " " + command + " >" +
                               quoted(log.string()) + " 2>&1";
    const int status = std::system(capped.c_str());
    output = read(log);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

std::string glsl_type(const shader_parameter& p, shader_source::language lang) {
    const bool hlsl = lang == shader_source::language::hlsl;
    if (p.type == shader_parameter::kind::boolean) return "bool";
    if (p.type == shader_parameter::kind::color) return hlsl ? "float3" : "vec3";
    return "float";
}

// The code as glslangValidator checks GLSL: as written, but for its precision qualifiers and
// statements (highp, precision mediump float;), which GLSL 1.20 does not take and which mean
// nothing to desktop GLSL; comments as spaces, lines kept.
std::string without_precision(const token_list& t) {
    std::string code;
    bool statement = false;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const bool word = t[i].type == token::word;
        if (word && t[i].text == "precision") statement = true;
        const bool drop = statement || (word && (t[i].text == "highp" || t[i].text == "mediump" || t[i].text == "lowp"));
        if (statement && t.is(i, ";")) statement = false;
        code += drop && t[i].type != token::space ? " " : t[i].text;
    }
    return code;
}

// The shader as glslangValidator checks it: the header's parameters the code does not declare
// as uniforms, its code with the file's line numbers, and a main that calls the BRDF with five
// vectors (a number it returns made a colour). GLSL is checked as GLSL 1.20 with
// GL_ARB_shading_language_420pack, which gives it scalar swizzles (x.xxx) and initializer lists.
std::string validation_source(const shader_source& s, const shader_analysis& a, const token_list& t) {
    std::ostringstream o;
    const bool hlsl = s.lang == shader_source::language::hlsl;
    if (!hlsl) o << "#version 120\n#extension GL_ARB_shading_language_420pack : enable\n";
    for (const auto& p : s.parameters) {
        const bool declared = std::any_of(a.uniforms.begin(), a.uniforms.end(), [&](const shader_declared& u) { return u.name == p.name; });
        if (!declared) o << (hlsl ? "" : "uniform ") << glsl_type(p, s.lang) << " " << p.name << ";\n";
    }
    // GLSL 1.20's #line N numbers the next line N + 1; HLSL's, like C's, N.
    o << "#line " << (hlsl ? s.first_line : s.first_line - 1) << "\n" << (hlsl ? s.code : without_precision(t)) << "\n";
    if (hlsl)
        o << "float4 main() : SV_Target { float3 c = " << s.function
          << "(float3(0, 0, 1), float3(0, 0, 1), float3(0, 0, 1), float3(1, 0, 0), float3(0, 1, 0)); return float4(c, 1); }\n";
    else
        o << "void main() { gl_FragColor = vec4(vec3(" << s.function
          << "(vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0))), 1.0); }\n";
    return o.str();
}

}  // namespace

compiled_shader::compiled_shader(const shader_source& s, double compile_seconds) {
    const auto start = std::chrono::steady_clock::now();
    const std::string prelude_path = NORMZOO_SHADER_PRELUDE;
    const std::string translation = translate_shader(s, prelude_path);
    const std::string compiler = NORMZOO_SHADER_CXX;
    const std::string key = key_of(translation + read(prelude_path) + compiler);
    const fs::path root = cache_root();
    fs::path library = root / (key + ".so");
    report_.library = library.string();
    std::error_code ec;
    fs::path root_used = root;
    if (!fs::exists(library, ec)) {
        fs::create_directories(root, ec);
        if (ec) {  // a home without a writable cache: the system's temporary folder, per user
            root_used = fs::temp_directory_path() / ("normzoo-shaders-" + std::to_string(::getuid()));
            library = root_used / (key + ".so");
            report_.library = library.string();
            ec.clear();
        }
    }
    if (!fs::exists(library, ec)) {
        fs::create_directories(root_used, ec);
        if (ec) throw bad_input(s.path + ": cannot create the shader cache " + root_used.string() + ": " + ec.message());
        const fs::path work = root_used / (key + ".work." + std::to_string(::getpid()));
        fs::create_directories(work, ec);
        const bool hlsl = s.lang == shader_source::language::hlsl;
        const fs::path checked = work / (hlsl ? "shader.hlsl" : "shader.frag");
        const token_list tokens(tokenize(s.code), s.first_line);
        const shader_analysis analysis = analyze_shader(s, tokens);
        std::ofstream(checked) << validation_source(s, analysis, tokens);
        std::string out;
        // -l links: the GLSL front end finds recursion only there (HLSL's -V links anyway)
        const std::string validator = hlsl ? "glslangValidator -D -V -e main -S frag -o " + quoted((work / "shader.spv").string()) + " "
                                           : "glslangValidator -l -S frag ";
        int status = run_capped(validator + quoted(checked.string()), compile_seconds, work / "validate.log", out);
        if (status != 0) {
            int line = 0;
            const int last = tokens.size() ? tokens.line(tokens.size() - 1) : s.first_line;
            const std::string msg = status == 124 ? "validation took longer than its time cap" : glslang_message(out, s, analysis, last, line);
            fs::remove_all(work, ec);
            if (status == 127) throw bad_input(s.path + ": glslangValidator is not installed (tools/install-deps installs it)");
            throw bad_input(s.path + (line > 0 ? ":" + std::to_string(line) : "") + ": " + (hlsl ? "HLSL" : "GLSL") + " error: " + msg);
        }
        const fs::path source = work / "shader.cpp";
        std::ofstream(source) << translation;
        const fs::path built = work / "shader.so";
        status = run_capped(quoted(compiler) + " -std=c++17 -O2 -fno-finite-loops -fPIC -shared -w -o " + quoted(built.string()) + " " +
                                quoted(source.string()),
                            compile_seconds, work / "compile.log", out);
        if (status != 0) {
            int line = 0;
            const std::string msg = status == 124 ? "compiling took longer than " + std::to_string(static_cast<int>(compile_seconds)) + " s"
                                                  : compiler_message(out, s, line);
            fs::remove_all(work, ec);
            throw bad_input(s.path + (line > 0 ? ":" + std::to_string(line) : "") + ": valid " + (hlsl ? "HLSL" : "GLSL") +
                            ", but outside what normzoo runs on the CPU (docs/brdf-code.md#what-is-supported): " + msg);
        }
        fs::rename(built, library, ec);  // atomic: a concurrent run sees the whole library or none
        fs::remove_all(work, ec);
        report_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } else {
        report_.cached = true;
    }
    handle_ = ::dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) throw bad_input(s.path + ": the compiled shader did not load: " + std::string(::dlerror()));
    auto sym = [&](const char* name) {
        void* p = ::dlsym(handle_, name);
        if (!p) throw bad_input(s.path + ": the compiled shader lacks " + name);
        return p;
    };
    make_double_ = reinterpret_cast<make_fn>(sym("normzoo_make_double"));
    make_float_ = reinterpret_cast<make_fn>(sym("normzoo_make_float"));
    free_double_ = reinterpret_cast<free_fn>(sym("normzoo_free_double"));
    free_float_ = reinterpret_cast<free_fn>(sym("normzoo_free_float"));
    eval_double_ = reinterpret_cast<eval_fn>(sym("normzoo_eval_double"));
    eval_float_ = reinterpret_cast<eval_fn>(sym("normzoo_eval_float"));
}

compiled_shader::~compiled_shader() {
    if (handle_) ::dlclose(handle_);
}

compiled_shader::instance::instance(const compiled_shader& c, const std::vector<double>& slots)
    : c_(c), double_(c.make_double_(slots.data())), float_(c.make_float_(slots.data())) {}

compiled_shader::instance::~instance() {
    c_.free_double_(double_);
    c_.free_float_(float_);
}

namespace {
char timer_message[512];
std::size_t timer_message_size = 0;
extern "C" void on_timer(int) {
    // async-signal-safe: write and _exit only
    if (::write(2, timer_message, timer_message_size) < 0) {}
    ::_exit(2);
}
}  // namespace

void arm_evaluation_timer(const std::string& path, double seconds) {
    const std::string m = "verify: " + path + ": evaluation stopped after " + std::to_string(static_cast<int>(seconds)) +
                          " s (a loop that does not end? docs/brdf-code.md#safety); nothing was written\n";
    timer_message_size = std::min(m.size(), sizeof timer_message);
    std::copy(m.begin(), m.begin() + static_cast<std::ptrdiff_t>(timer_message_size), timer_message);
    struct sigaction sa {};
    sa.sa_handler = on_timer;
    ::sigaction(SIGALRM, &sa, nullptr);
    itimerval t{};
    t.it_value.tv_sec = static_cast<time_t>(seconds);
    t.it_value.tv_usec = static_cast<suseconds_t>((seconds - static_cast<double>(t.it_value.tv_sec)) * 1e6);
    ::setitimer(ITIMER_REAL, &t, nullptr);
}

void disarm_evaluation_timer() {
    itimerval t{};
    ::setitimer(ITIMER_REAL, &t, nullptr);
}

}  // namespace verify
