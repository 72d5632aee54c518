// A shader file compiled for the CPU and loaded (docs/brdf-code.md#how-the-shader-runs): validated
// by glslangValidator (a GLSL or HLSL error names the file and line), translated to C++ over GLM
// (shader_translate.hpp), compiled by the system's compiler once per content (cached), loaded,
// and called in double or in float. Bad input throws bad_input naming the file and line.
#pragma once
#include <array>
#include <cfenv>
#include <memory>
#include <string>
#include <vector>

#include <normzoo/geometry.hpp>

#include "brdf_file.hpp"

namespace verify {

struct compile_report {
    bool cached = false;   // the library was already in the cache
    double seconds = 0;    // validation and compilation (0 when cached)
    std::string library;   // its path
    bool binary16 = false;  // it holds the binary16 program (the code declares reduced precision)
};

// An operation a GPU leaves undefined (prelude_checks.hpp; division by zero from FE_DIVBYZERO),
// seen while the double program ran: how many evaluations, and the first one's L and V.
struct gpu_undefined_seen {
    std::size_t count = 0;
    double l[3] = {0, 0, 0}, v[3] = {0, 0, 0};
};
// Their names, bit by bit as prelude_checks.hpp's undefined_op, division by zero last.
constexpr std::size_t gpu_undefined_kinds = 8;
extern const char* const gpu_undefined_names[gpu_undefined_kinds];

class compiled_shader {
public:
    // Validates, translates and compiles (or finds in the cache) the shader; compile_seconds caps
    // the compiler's time.
    explicit compiled_shader(const shader_source& s, double compile_seconds = 120);
    ~compiled_shader();
    compiled_shader(const compiled_shader&) = delete;
    compiled_shader& operator=(const compiled_shader&) = delete;

    const compile_report& report() const { return report_; }

    // The program at given parameter values (one slot per float or bool, three per color, in
    // declaration order), in double and in float.
    class instance {
    public:
        instance(const compiled_shader& c, const std::vector<double>& slots);
        ~instance();
        instance(const instance&) = delete;
        instance& operator=(const instance&) = delete;
        // The k-th texture of the source's `textures`: width x height texels of four channels,
        // row 0 at v = 0 (docs/brdf-code.md#textures).
        void bind(std::size_t k, std::size_t width, std::size_t height, const double* rgba);
        // The callable shape of code/brdf_code.hpp: f(L, V, N, X, Y) -> three channels.
        template <class T>
        std::array<T, 3> operator()(const normzoo::vec3<T>& l, const normzoo::vec3<T>& v, const normzoo::vec3<T>& n,
                                    const normzoo::vec3<T>& x, const normzoo::vec3<T>& y) const {
            double d[15], out[3];
            const normzoo::vec3<T>* w[5] = {&l, &v, &n, &x, &y};
            for (int k = 0; k < 5; ++k)
                for (int c = 0; c < 3; ++c) d[3 * k + c] = static_cast<double>((*w[k])[c]);
            if constexpr (std::is_same_v<T, float>) {
                c_.eval_float_(float_, d, out);
            } else {
                std::feclearexcept(FE_DIVBYZERO);
                c_.eval_double_(double_, d, out);
                note_undefined(d);
            }
            return {static_cast<T>(out[0]), static_cast<T>(out[1]), static_cast<T>(out[2])};
        }
        // What the double program did that a GPU leaves undefined since the last call, by kind
        // (gpu_undefined_names), and how many evaluations did any; then cleared.
        std::array<gpu_undefined_seen, gpu_undefined_kinds> take_undefined(std::size_t& evaluations) const;
        // The binary16 program (docs/brdf-code.md#precision), where report().binary16.
        std::array<double, 3> binary16(const double* d15) const {
            double out[3];
            c_.eval_half_(half_, d15, out);
            return {out[0], out[1], out[2]};
        }

    private:
        void note_undefined(const double* d15) const;
        const compiled_shader& c_;
        mutable std::array<gpu_undefined_seen, gpu_undefined_kinds> undefined_{};
        mutable std::size_t undefined_evaluations_ = 0;
        void* double_ = nullptr;
        void* float_ = nullptr;
        void* half_ = nullptr;
    };

    // The callable shape of code/brdf_code.hpp with the binary16 program in the place of float:
    // f(L, V, N, X, Y) in double as the instance's, in float as binary16's.
    struct binary16_view {
        const instance& f;
        template <class T>
        std::array<T, 3> operator()(const normzoo::vec3<T>& l, const normzoo::vec3<T>& v, const normzoo::vec3<T>& n,
                                    const normzoo::vec3<T>& x, const normzoo::vec3<T>& y) const {
            if constexpr (!std::is_same_v<T, float>) {
                return f(l, v, n, x, y);
            } else {
                double d[15];
                const normzoo::vec3<T>* w[5] = {&l, &v, &n, &x, &y};
                for (int k = 0; k < 5; ++k)
                    for (int c = 0; c < 3; ++c) d[3 * k + c] = static_cast<double>((*w[k])[c]);
                const auto r = f.binary16(d);
                return {static_cast<T>(r[0]), static_cast<T>(r[1]), static_cast<T>(r[2])};
            }
        }
    };

private:
    void load_entry_points(const shader_source& s);
    void* handle_ = nullptr;
    compile_report report_;
    using make_fn = void* (*)(const double*);
    using free_fn = void (*)(void*);
    using eval_fn = void (*)(void*, const double*, double*);
    make_fn make_double_ = nullptr, make_float_ = nullptr, make_half_ = nullptr;
    free_fn free_double_ = nullptr, free_float_ = nullptr, free_half_ = nullptr;
    eval_fn eval_double_ = nullptr, eval_float_ = nullptr, eval_half_ = nullptr;
    unsigned (*undefined_)() = nullptr;
    using bind_fn = void (*)(void*, int, int, int, const double*);
    bind_fn bind_double_ = nullptr, bind_float_ = nullptr, bind_half_ = nullptr;  // with textures only
};

// Stops the process with exit 2 and a message naming the file when `seconds` pass before
// disarm(): a shader that loops forever (docs/brdf-code.md#safety).
void arm_evaluation_timer(const std::string& path, double seconds);
void disarm_evaluation_timer();

}  // namespace verify
