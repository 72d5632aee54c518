#include "brdf_examples.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>

#include <normzoo/albedo.hpp>
#include <normzoo/check.hpp>
#include <normzoo/code/code_albedo.hpp>
#include <normzoo/code/code_checks.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/registry.hpp>

#include "brdf_file/brdf_file.hpp"
#include "brdf_file/compiled_shader.hpp"
#include "brdf_file/preprocess.hpp"
#include "tables/grid_text.hpp"

#ifndef NORMZOO_EXAMPLES_DIR
#error "NORMZOO_EXAMPLES_DIR: examples/brdfs, set by CMake"
#endif

namespace verify {

namespace {

using estimate = normzoo::quadrature::estimate<double>;

// How the file and its built-in twin are compared: the file's parameter slots at a value x of the
// swept parameter, and the built-in albedo there at an incidence.
struct example {
    const char* file;       // in examples/brdfs/
    const char* model;      // the built-in form or composition
    const char* parameter;  // the swept parameter's name in the file ("" for none)
    std::vector<double> values;
    std::function<std::vector<double>(double)> slots;
    std::function<estimate(double x, const normzoo::degrees_angle<normzoo::quad>&)> built_in;
};

template <class Form>
std::function<estimate(double, const normzoo::degrees_angle<normzoo::quad>&)> form_albedo() {
    return [](double x, const normzoo::degrees_angle<normzoo::quad>& t) {
        const auto p = normzoo::brdf::params_at<Form>(x);
        return normzoo::albedo<Form>(t, p.n, p.specular, {}, p.roughness);
    };
}

// E(mu) of GGX/Smith height-correlated/Schlick at alpha = r^2 and F0 = 1.
estimate ggx_smith_schlick(double r, const normzoo::degrees_angle<normzoo::quad>& t) {
    static const auto c = normzoo::microfacet::composition::parse("ggx/smith-height-correlated/schlick");
    return normzoo::microfacet::directional_albedo(c, static_cast<double>(t.cos_t), r * r, 1);
}

std::vector<example> examples() {
    using namespace normzoo::brdf;
    const std::vector<double> exponents{1, 10, 100, 1000, 10000};
    return {
        {"lambert.brdf", "lambert", "", {0}, [](double) { return std::vector<double>{1, 1, 1}; }, form_albedo<lambert>()},
        {"phong.brdf", "phong", "n", exponents, [](double n) { return std::vector<double>{n, 1}; }, form_albedo<phong>()},
        {"phong.brdf", "phong-modified", "n", exponents, [](double n) { return std::vector<double>{n, 0}; },
         form_albedo<phong_modified>()},
        {"blinn-phong.brdf", "blinn-phong", "n", exponents, [](double n) { return std::vector<double>{n}; },
         form_albedo<blinn_phong>()},
        {"blinn-phong-modified.brdf", "blinn-phong-modified", "n", exponents,
         [](double n) { return std::vector<double>{n}; }, form_albedo<blinn_phong_modified>()},
        {"ward.brdf", "ward", "alpha", {0.1, 0.3, 0.5, 1}, [](double a) { return std::vector<double>{a}; },
         form_albedo<ward>()},
        {"ashikhmin-shirley.brdf", "ashikhmin-shirley", "n", {1, 10, 100, 1000},
         [](double n) { return std::vector<double>{n, 1}; }, form_albedo<ashikhmin_shirley>()},
        {"disney-diffuse.brdf", "disney-diffuse", "roughness", {0, 0.5, 1}, [](double r) { return std::vector<double>{r}; },
         form_albedo<disney_diffuse>()},
        {"ggx-smith-schlick.brdf", "ggx/smith-height-correlated/schlick", "roughness", {0.1, 0.3, 0.5, 1},
         [](double r) { return std::vector<double>{r, 1}; }, ggx_smith_schlick},
        {"ggx-smith-schlick.hlsl", "ggx/smith-height-correlated/schlick", "roughness", {0.1, 0.3, 0.5, 1},
         [](double r) { return std::vector<double>{r, 1}; }, ggx_smith_schlick},
    };
}

// The incidences: from their cosine for the compositions (whose albedo takes mu), from degrees
// for the forms.
std::vector<double> example_mus() { return {1.0, 0.8, 0.5, 0.2, 0.05}; }
std::vector<normzoo::degrees_angle<normzoo::quad>> example_angles() {
    std::vector<normzoo::degrees_angle<normzoo::quad>> a;
    for (double mu : example_mus()) a.push_back(normzoo::microfacet::angle_of_cosine(mu));
    return a;
}

double degrees(const normzoo::degrees_angle<normzoo::quad>& t) {
    return static_cast<double>(t.radians * 180 / boost::math::constants::pi<normzoo::quad>());
}

}  // namespace

std::vector<table_output> brdf_example_tables(unsigned jobs) {
    const auto list = examples();
    const auto angles = example_angles();
    struct task {
        std::size_t example;
        double x;
        std::size_t angle;
    };
    std::vector<task> tasks;
    for (std::size_t e = 0; e < list.size(); ++e)
        for (double x : list[e].values)
            for (std::size_t a = 0; a < angles.size(); ++a) tasks.push_back({e, x, a});
    // Compiled once per file (cached across runs), shared by the tasks.
    std::vector<std::unique_ptr<compiled_shader>> shaders;
    for (const auto& e : list)
        shaders.push_back(std::make_unique<compiled_shader>(read_preprocessed(std::string(NORMZOO_EXAMPLES_DIR) + "/" + e.file)));
    struct result {
        normzoo::code::code_albedo_result code;
        estimate built_in;
    };
    std::vector<result> results(tasks.size());
    normzoo::detail::parallel_for(tasks.size(), jobs, [&](std::size_t i) {
        const auto& t = tasks[i];
        const compiled_shader::instance f(*shaders[t.example], list[t.example].slots(t.x));
        results[i].code = normzoo::code::code_albedo(f, angles[t.angle]);
        results[i].built_in = list[t.example].built_in(t.x, angles[t.angle]);
    });
    table_output out;
    out.info = {"brdf-examples",
                "The BRDF Explorer files of examples/brdfs/, compiled and integrated as black boxes, against the "
                "built-in forms they write out",
                {"files compiled for the CPU over GLM and evaluated in double (docs/brdf-code.md)",
                 "black-box integrator, tolerance 1e-10 absolute; built-in albedo integrals, tolerance 1e-10",
                 "pass: |code - built-in| <= 1e-9 and within the sum of the two bounds"},
                {"file", "model", "parameter", "value", "theta_deg", "albedo", "error_estimate", "built_in_albedo", "difference",
                 "pass"},
                {"albedo", "built_in_albedo"}};
    out.parameters = "incidence mu = " + list_text(example_mus()) + "; each form's values as listed";
    out.command = "./verify brdf-code";
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        const auto& t = tasks[i];
        const auto& e = list[t.example];
        const auto& c = results[i].code.largest();
        const auto& b = results[i].built_in;
        const double diff = std::abs(c.value - b.value);
        record r;
        r.table = "brdf-examples";
        r.set("file", std::string("examples/brdfs/") + e.file).set("model", e.model);
        r.set("parameter", *e.parameter ? field_value(e.parameter) : field_value("none"));
        r.set("value", t.x).set("theta_deg", degrees(angles[t.angle]));
        r.set("albedo", c.value).set("error_estimate", c.abs_error);
        r.set("built_in_albedo", b.value).set("built_in_error", b.abs_error);
        r.set("difference", diff);
        r.set("evaluations", static_cast<std::int64_t>(results[i].code.evaluations));
        r.set("pass", results[i].code.finite() && diff <= 1e-9 && diff <= c.abs_error + b.abs_error);
        out.records.push_back(r);
    }
    return {out};
}

std::vector<table_output> code_audit_tables(unsigned jobs) {
    // Every built-in form at every value of its swept parameter and every incidence of the energy
    // table (0, 1, ..., 89, 89.5, 89.9, 89.99 degrees), as an opaque callable: only f(L, V) is
    // visible to the integrator.
    struct task {
        std::size_t form;
        double x;
        double theta;
    };
    const std::vector<double> thetas = normzoo::default_energy_angles();
    std::vector<task> tasks;
    std::vector<std::string> ids;
    std::size_t k = 0;
    normzoo::for_each_brdf([&](auto form) {
        using Form = decltype(form);
        ids.emplace_back(Form::id);
        std::vector<double> values{0};
        if constexpr (normzoo::brdf::has_swept_parameter<Form>()) values.assign(normzoo::brdf::swept_parameter<Form>().sweep.begin(),
                                                                                 normzoo::brdf::swept_parameter<Form>().sweep.end());
        for (double x : values)
            for (double t : thetas) tasks.push_back({k, x, t});
        ++k;
    });
    struct result {
        estimate code, built_in;
        std::size_t evaluations = 0;
        double width = 0;
    };
    std::vector<result> results(tasks.size());
    normzoo::detail::parallel_for(tasks.size(), jobs, [&](std::size_t i) {
        const auto& t = tasks[i];
        std::size_t j = 0;
        normzoo::for_each_brdf([&](auto form) {
            using Form = decltype(form);
            if (j++ != t.form) return;
            const auto p = normzoo::brdf::params_at<Form>(t.x);
            auto opaque = [p](const auto& l, const auto& v, const auto&, const auto&, const auto&) {
                using T = typename std::decay_t<decltype(l)>::Scalar;
                return Form::f(l, v, normzoo::brdf::params<T>{T(p.n), T(p.specular), T(p.roughness)});
            };
            const normzoo::degrees_angle<normzoo::quad> angle(t.theta);
            const auto c = normzoo::code::code_albedo(opaque, angle);
            results[i] = {c.largest(), normzoo::albedo<Form>(angle, p.n, p.specular, {}, p.roughness), c.evaluations, c.lobe.width};
        });
    });
    table_output out;
    out.info = {"code-audit",
                "The black-box integrator against every built-in form passed as an opaque callable: its bound against "
                "the difference from the built-in albedo",
                {"both at tolerance 1e-10 (absolute up to an albedo of 1, relative above)",
                 "pass: |code - built-in| <= the sum of the two bounds"},
                {"model", "value", "theta_deg", "albedo", "error_estimate", "built_in_albedo", "ratio", "evaluations", "pass"},
                {"albedo", "built_in_albedo"}};
    out.parameters = "the energy table's grid: every form, every value of its swept parameter, theta = " + list_text(thetas);
    out.command = "./verify code-audit";
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        const auto& r0 = results[i];
        const double diff = std::abs(r0.code.value - r0.built_in.value);
        const double ratio = diff / (r0.code.abs_error + r0.built_in.abs_error);
        record r;
        r.table = "code-audit";
        r.set("model", ids[tasks[i].form]).set("value", tasks[i].x).set("theta_deg", tasks[i].theta);
        r.set("albedo", r0.code.value).set("error_estimate", r0.code.abs_error);
        r.set("built_in_albedo", r0.built_in.value).set("built_in_error", r0.built_in.abs_error);
        r.set("difference", diff).set("ratio", ratio);
        r.set("evaluations", static_cast<std::int64_t>(r0.evaluations)).set("lobe_width", r0.width);
        r.set("pass", ratio <= 1);
        out.records.push_back(r);
    }
    return {out};
}

}  // namespace verify
