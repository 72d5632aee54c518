// A BRDF given as code against the built-in form it writes out (docs/brdf-code.md): the cost of
// one evaluation of the compiled GGX/Smith/Schlick file of examples/brdfs/ in double and in float
// against the built-in composition (run-time parts, and parts fixed at compile time), and of one
// albedo point by the black-box integrator against the built-in integral. Release build; the
// ratios are the figures, each against a peer in the same run.
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include <normzoo/code/code_albedo.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/composition.hpp>

#include "brdf_file/brdf_file.hpp"
#include "brdf_file/compiled_shader.hpp"
#include "brdf_file/preprocess.hpp"

using namespace normzoo;
using clock_type = std::chrono::steady_clock;

namespace {

template <class F>
double seconds_per_call(const F& f, std::size_t calls) {
    const auto t0 = clock_type::now();
    for (std::size_t i = 0; i < calls; ++i) f(i);
    return std::chrono::duration<double>(clock_type::now() - t0).count() / static_cast<double>(calls);
}

volatile double sink = 0;

}  // namespace

int main(int argc, char** argv) {
    const std::string file = argc > 1 ? argv[1] : std::string(NORMZOO_EXAMPLES_DIR) + "/ggx-smith-schlick.brdf";
    const double r = 0.5, alpha = r * r, f0 = 0.04;
    const auto t0 = clock_type::now();
    const verify::compiled_shader shader(verify::read_preprocessed(file));
    const double load = std::chrono::duration<double>(clock_type::now() - t0).count();
    const verify::compiled_shader::instance program(shader, {r, f0});

    // 4096 direction pairs in the upper hemisphere
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<vec3<double>> ls, vs;
    std::vector<vec3<float>> lf, vf;
    for (int i = 0; i < 4096; ++i) {
        ls.push_back(direction(std::acos(u(rng)), 6.283185307179586 * u(rng)));
        vs.push_back(direction(std::acos(u(rng)), 6.283185307179586 * u(rng)));
        lf.push_back(ls.back().cast<float>());
        vf.push_back(vs.back().cast<float>());
    }
    const vec3<double> n(0, 0, 1), x(1, 0, 0), y(0, 1, 0);
    const vec3<float> nf(0, 0, 1), xf(1, 0, 0), yf(0, 1, 0);
    const auto c = microfacet::composition::parse("ggx/smith-height-correlated/schlick");
    const brdf::params<double> p{0, f0, alpha};
    using fixed = microfacet::fixed_composition<microfacet::d_ggx, microfacet::g_smith_height_correlated, microfacet::fresnel_schlick>;
    const std::size_t calls = 4'000'000;
    const double code_double = seconds_per_call([&](std::size_t i) { sink = sink + program(ls[i & 4095], vs[i & 4095], n, x, y)[0]; }, calls);
    const double code_float = seconds_per_call([&](std::size_t i) { sink = sink + program(lf[i & 4095], vf[i & 4095], nf, xf, yf)[0]; }, calls);
    const double built_in = seconds_per_call([&](std::size_t i) { sink = sink + c.f(ls[i & 4095], vs[i & 4095], p); }, calls);
    const double built_in_fixed = seconds_per_call([&](std::size_t i) { sink = sink + fixed::f(ls[i & 4095], vs[i & 4095], alpha, f0); }, calls);
    const double built_in_fixed_float =
        seconds_per_call([&](std::size_t i) { sink = sink + fixed::f(lf[i & 4095], vf[i & 4095], float(alpha), float(f0)); }, calls);

    // One albedo point at 60 degrees: the black box on the compiled file, the black box on the
    // built-in composition as an opaque callable, and the built-in integral.
    const degrees_angle<quad> t(60.0);
    auto opaque = [&](const auto& l, const auto& v, const auto&, const auto&, const auto&) {
        using T = typename std::decay_t<decltype(l)>::Scalar;
        return c.f(l, v, brdf::params<T>{T(0), T(f0), T(alpha)});
    };
    code::code_albedo_result a_code, a_opaque;
    quadrature::estimate<double> a_built_in;
    const int reps = 5;
    const double s_code = seconds_per_call([&](std::size_t) { a_code = code::code_albedo(program, t); }, reps);
    const double s_opaque = seconds_per_call([&](std::size_t) { a_opaque = code::code_albedo(opaque, t); }, reps);
    const double s_built_in = seconds_per_call(
        [&](std::size_t) { a_built_in = microfacet::directional_albedo(c, static_cast<double>(t.cos_t), alpha, f0); }, reps);

    std::printf("# A BRDF given as code against its built-in twin\n\n");
    std::printf("Produced by `bench/run` (`normzoo-bench-brdf-code`), Release build, one process; docs/brdf-code.md.\n\n");
    std::printf("The file: `examples/brdfs/ggx-smith-schlick.brdf` (%s in %.2f s), r = 0.5, F0 = 0.04, against the built-in "
                "composition `ggx/smith-height-correlated/schlick`.\n\n",
                shader.report().cached ? "loaded from the shader cache" : "validated and compiled", load);
    std::printf("| one evaluation, 4096 direction pairs | ns | ratio |\n|---|---|---|\n");
    std::printf("| built-in, parts fixed at compile time, double | %.1f | 1 |\n", built_in_fixed * 1e9);
    std::printf("| built-in, parts chosen at run time, double | %.1f | %.2f |\n", built_in * 1e9, built_in / built_in_fixed);
    std::printf("| compiled file, double | %.1f | %.2f |\n", code_double * 1e9, code_double / built_in_fixed);
    std::printf("| built-in, parts fixed, float | %.1f | %.2f |\n", built_in_fixed_float * 1e9, built_in_fixed_float / built_in_fixed);
    std::printf("| compiled file, float | %.1f | %.2f |\n\n", code_float * 1e9, code_float / built_in_fixed);
    std::printf("| one albedo point, 60 degrees, tolerance 1e-10 | ms | evaluations | albedo | bound | ratio |\n|---|---|---|---|---|---|\n");
    std::printf("| built-in integral | %.2f | %zu | %.15f | %.1e | 1 |\n", s_built_in * 1e3, a_built_in.evaluations,
                a_built_in.value, a_built_in.abs_error);
    std::printf("| black box on the built-in composition | %.2f | %zu | %.15f | %.1e | %.1f |\n", s_opaque * 1e3,
                a_opaque.evaluations, a_opaque.largest().value, a_opaque.largest().abs_error, s_opaque / s_built_in);
    std::printf("| black box on the compiled file | %.2f | %zu | %.15f | %.1e | %.1f |\n", s_code * 1e3, a_code.evaluations,
                a_code.largest().value, a_code.largest().abs_error, s_code / s_built_in);
    return 0;
}
