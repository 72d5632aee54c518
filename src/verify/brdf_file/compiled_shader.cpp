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
#include "child_process.hpp"
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

std::string glsl_type(const shader_parameter& p, shader_source::language lang) {
    const bool hlsl = lang == shader_source::language::hlsl;
    if (p.type == shader_parameter::kind::boolean) return "bool";
    if (p.type == shader_parameter::kind::color) return hlsl ? "float3" : "vec3";
    return "float";
}

// The code as glslangValidator checks GLSL of a version that has no precision qualifiers
// (desktop GLSL before 1.30): its highp, mediump and lowp blanked, which mean nothing on the
// desktop (the preprocessor has dropped the precision statements); lines kept.
std::string without_precision(const token_list& t) {
    std::string code;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const bool drop = t[i].type == token::word && (t[i].text == "highp" || t[i].text == "mediump" || t[i].text == "lowp");
        code += drop ? " " : t[i].text;
    }
    return code;
}

// The shader as glslangValidator checks it: the header's parameters the code does not declare
// as uniforms, its code with the file's line numbers, and a main that calls the BRDF with five
// vectors (a number it returns made a colour). GLSL at the file's #version with its active
// extensions; without one, GLSL 1.20 with GL_ARB_shading_language_420pack, which gives it scalar
// swizzles (x.xxx) and initializer lists. The ES profiles with a default precision, since the
// file's precision statements are dropped (preprocess.hpp).
std::string validation_source(const shader_source& s, const shader_analysis& a, const token_list& t) {
    std::ostringstream o;
    const bool hlsl = s.lang == shader_source::language::hlsl;
    const std::string version = s.version.empty() ? "120" : s.version;
    const int number = std::atoi(version.c_str());
    const bool es = number == 100 || version.find(" es") != std::string::npos;
    const bool frag_color = es ? number < 300 : number < 130;  // gl_FragColor, or an out variable
    if (!hlsl) {
        o << "#version " << version << "\n";
        if (s.version.empty()) o << "#extension GL_ARB_shading_language_420pack : enable\n";
        for (const auto& e : s.extensions)
            if (e.rfind("GL_GOOGLE_", 0) != 0 && e.rfind("GL_ARB_shading_language_include", 0) != 0) o << "#extension " << e << "\n";
        if (es) o << "precision highp float;\n";
        if (!frag_color) o << "out vec4 normzoo_color;\n";
    }
    for (const auto& p : s.parameters) {
        const bool declared = std::any_of(a.uniforms.begin(), a.uniforms.end(), [&](const shader_declared& u) { return u.name == p.name; });
        if (!declared) o << (hlsl ? "" : "uniform ") << glsl_type(p, s.lang) << " " << p.name << ";\n";
    }
    // #line N numbers the next line N + 1 in GLSL before 3.30 and ES; after, as in HLSL and C, N.
    o << "#line " << (hlsl || es || number >= 330 ? s.first_line : s.first_line - 1) << "\n"
      << (hlsl || es || number >= 130 ? s.code : without_precision(t)) << "\n";
    if (hlsl)
        o << "float4 main() : SV_Target { float3 c = " << s.function
          << "(float3(0, 0, 1), float3(0, 0, 1), float3(0, 0, 1), float3(1, 0, 0), float3(0, 1, 0)); return float4(c, 1); }\n";
    else
        o << "void main() { " << (frag_color ? "gl_FragColor" : "normzoo_color") << " = vec4(vec3(" << s.function
          << "(vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0))), 1.0); }\n";
    return o.str();
}

}  // namespace

compiled_shader::compiled_shader(const shader_source& s, double compile_seconds) {
    if (!s.preprocessed) throw std::logic_error("compiled_shader: " + s.path + " was not preprocessed (preprocess.hpp)");
    const auto start = std::chrono::steady_clock::now();
    const std::string prelude_path = NORMZOO_SHADER_PRELUDE;
    const std::string translation = translate_shader(s, prelude_path);
    const std::string compiler = NORMZOO_SHADER_CXX;
    const fs::path folder = fs::path(prelude_path).parent_path();
    const std::string textures_path = (folder / "glsl_textures.hpp").string();  // the prelude includes it
    const std::string key = key_of(translation + read(prelude_path) + read(textures_path) + read(folder / "half_prelude.hpp") +
                                  read(folder / "prelude_checks.hpp") + compiler);
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
        const shader_caps caps = shader_caps_from_environment();
        const child_limits validation{caps.seconds, caps.memory_mb << 20, caps.text_bytes()};
        // -l links: the GLSL front end finds recursion only there (HLSL's -V links anyway)
        std::vector<std::string> validator{"glslangValidator", "-l", "-S", "frag", checked.string()};
        if (hlsl) validator = {"glslangValidator", "-D", "-V", "-e", "main", "-S", "frag", "-o", (work / "shader.spv").string(), checked.string()};
        child_result r = run_child(validator, validation);
        if (!r.ok()) {
            fs::remove_all(work, ec);
            if (r.how == child_result::ending::not_started || (r.how == child_result::ending::exited && r.status == 127))
                throw bad_input(s.path + ": glslangValidator did not start (tools/install-deps installs it)");
            const std::string cap = cap_tripped(r, validation, "NORMZOO_SHADER_SECONDS");
            if (!cap.empty()) throw bad_input(s.path + ": validation by glslangValidator stopped: it " + cap);
            int line = 0;
            const int last = tokens.size() ? tokens.line(tokens.size() - 1) : s.first_line;
            const std::string msg = glslang_message(r.out + r.err, s, analysis, last, line);
            throw bad_input(s.place(line) + ": " + (hlsl ? "HLSL" : "GLSL") + " error: " + msg);
        }
        const fs::path source = work / "shader.cpp";
        std::ofstream(source) << translation;
        const fs::path built = work / "shader.so";
        const child_limits compiling{compile_seconds, caps.memory_mb << 20, caps.text_bytes()};
        const std::vector<std::string> command{compiler, "-std=c++17", "-O2", "-fno-finite-loops", "-fPIC", "-shared", "-w", "-o", built.string(), source.string()};
        r = run_child(command, compiling);
        if (!r.ok() && cap_tripped(r, compiling, nullptr).empty() && analysis.reduced_precision) {
            // the double and float programs alone: a construct the binary16 types do not take
            // (docs/brdf-code.md#precision) leaves the file checked as before, without albedo_fp16
            std::ofstream(source) << translate_shader(s, prelude_path, false);
            r = run_child(command, compiling);
        }
        if (!r.ok()) {
            int line = 0;
            const std::string cap = cap_tripped(r, compiling, nullptr);
            const std::string msg = !cap.empty() ? "compiling stopped: it " + cap : compiler_message(r.out + r.err, s, line);
            fs::remove_all(work, ec);
            if (!cap.empty()) throw bad_input(s.path + ": " + msg);
            throw bad_input(s.place(line) + ": valid " + (hlsl ? "HLSL" : "GLSL") +
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
    load_entry_points(s);
}

// The programs' C entry points (shader_translate.hpp): double and float, the binary16 program's
// where the library has it, the textures' bindings where the file binds any.
void compiled_shader::load_entry_points(const shader_source& s) {
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
    undefined_ = reinterpret_cast<unsigned (*)()>(sym("normzoo_undefined_double"));
    if (::dlsym(handle_, "normzoo_eval_half")) {
        make_half_ = reinterpret_cast<make_fn>(sym("normzoo_make_half"));
        free_half_ = reinterpret_cast<free_fn>(sym("normzoo_free_half"));
        eval_half_ = reinterpret_cast<eval_fn>(sym("normzoo_eval_half"));
        report_.binary16 = true;
    }
    if (!s.textures.empty()) {
        bind_double_ = reinterpret_cast<bind_fn>(sym("normzoo_bind_double"));
        bind_float_ = reinterpret_cast<bind_fn>(sym("normzoo_bind_float"));
        if (report_.binary16) bind_half_ = reinterpret_cast<bind_fn>(sym("normzoo_bind_half"));
    }
}

compiled_shader::~compiled_shader() {
    if (handle_) ::dlclose(handle_);
}

compiled_shader::instance::instance(const compiled_shader& c, const std::vector<double>& slots)
    : c_(c), double_(c.make_double_(slots.data())), float_(c.make_float_(slots.data())),
      half_(c.make_half_ ? c.make_half_(slots.data()) : nullptr) {}

void compiled_shader::instance::bind(std::size_t k, std::size_t width, std::size_t height, const double* rgba) {
    if (!c_.bind_double_) throw std::logic_error("compiled_shader: a texture bound to a shader compiled without textures");
    c_.bind_double_(double_, static_cast<int>(k), static_cast<int>(width), static_cast<int>(height), rgba);
    c_.bind_float_(float_, static_cast<int>(k), static_cast<int>(width), static_cast<int>(height), rgba);
    if (half_ && c_.bind_half_) c_.bind_half_(half_, static_cast<int>(k), static_cast<int>(width), static_cast<int>(height), rgba);
}

compiled_shader::instance::~instance() {
    c_.free_double_(double_);
    c_.free_float_(float_);
    if (half_) c_.free_half_(half_);
}

const char* const gpu_undefined_names[gpu_undefined_kinds] = {
    "pow of a negative base, or of 0 to a power <= 0", "sqrt of a negative", "inversesqrt of a value <= 0",
    "log of a value <= 0", "asin or acos outside [-1, 1]", "atan(y, x) with x = y = 0", "normalize of a zero vector",
    "division by zero"};

void compiled_shader::instance::note_undefined(const double* d) const {
    unsigned seen = c_.undefined_();
    // FE_DIVBYZERO: a quotient by 0, or a pole of log or pow already noted as such
    if (seen == 0 && std::fetestexcept(FE_DIVBYZERO)) seen = 1u << (gpu_undefined_kinds - 1);
    if (seen == 0) return;
    ++undefined_evaluations_;
    for (std::size_t k = 0; k < gpu_undefined_kinds; ++k) {
        if (!(seen & (1u << k)) || undefined_[k].count++ > 0) continue;
        std::copy(d, d + 3, undefined_[k].l);
        std::copy(d + 3, d + 6, undefined_[k].v);
    }
}

std::array<gpu_undefined_seen, gpu_undefined_kinds> compiled_shader::instance::take_undefined(std::size_t& evaluations) const {
    const auto r = undefined_;
    evaluations = undefined_evaluations_;
    undefined_ = {};
    undefined_evaluations_ = 0;
    return r;
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
