#include "brdf_records.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace verify {

namespace {

using normzoo::code::fixed_direction;

std::string vector_text(const normzoo::vec3<double>& v) {
    std::ostringstream o;
    o.precision(6);
    o << v.x() << "," << v.y() << "," << v.z();
    return o.str();
}

std::string numbers_text(const std::vector<double>& v) {
    std::ostringstream o;
    o.precision(17);
    for (std::size_t i = 0; i < v.size(); ++i) o << (i ? "," : "") << v[i];
    return o.str();
}

std::string short_number(double x, int digits = 4) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    return buf;
}

// Two values that differ by `relative`, to as many digits as show the difference (4 to 17).
std::string pair_text(const char* a_name, double a, const char* b_name, double b, double relative) {
    const int digits =
        relative > 0 && std::isfinite(relative) ? std::clamp(2 - static_cast<int>(std::floor(std::log10(relative))), 4, 17) : 4;
    return std::string(a_name) + " " + short_number(a, digits) + " " + b_name + " " + short_number(b, digits);
}

// The direction the albedo integrates over (V, or L where V is held), as records name it.
std::string integrated(const brdf_request& o) { return o.fixed == fixed_direction::light ? "V" : "L"; }

// Why a brdf record fails, finding by finding, with where and by how much; empty when it passes.
std::string albedo_reason(const brdf_request& o, const albedo_results& a, bool albedo_given, bool conserving) {
    std::vector<std::string> why;
    const auto& found = a.albedo.found;
    const std::string dir = integrated(o);
    if (found.non_finite)
        why.push_back("NaN or Inf at " + dir + "=" + vector_text(*found.non_finite.first) + " (" +
                      std::to_string(found.non_finite.count) + " evaluations)" +
                      (found.non_finite_isolated() ? ", only at isolated directions: the albedo excludes them"
                                                   : ", not only at isolated directions: no albedo"));
    for (std::size_t k = 0; k < gpu_undefined_kinds; ++k) {
        const auto& u = a.undefined[k];
        if (u.count == 0) continue;
        why.push_back(std::string("undefined on a GPU: ") + gpu_undefined_names[k] + " (docs/brdf-code.md#gpu-undefined-operations) at L=" +
                      vector_text({u.l[0], u.l[1], u.l[2]}) + " V=" + vector_text({u.v[0], u.v[1], u.v[2]}) + " (" +
                      std::to_string(u.count) + " evaluations)");
    }
    if (found.negative)
        why.push_back("negative at " + dir + "=" + vector_text(*found.negative.first) + " (" + std::to_string(found.negative.count) +
                      " evaluations)");
    const auto& big = a.albedo.largest();
    if (albedo_given && !conserving && !o.allow_energy_gain)
        why.push_back("gains energy: albedo " + short_number(big.value) + " = 1 + " + short_number(big.value - 1) + " (bound " +
                      short_number(big.abs_error + a.texture_storage_bound.value_or(0)) +
                      (a.texture_storage_bound ? ", the textures' storage included" : "") + ")");
    if (a.precision.breaks_down()) {
        const auto& w = a.precision.worst;
        why.push_back("fp32 breaks down: " + pair_text("float", w.b, "against double", w.a, w.relative) + " at " + dir + "=" +
                      vector_text(w.v) + ", " + short_number(w.relative) + " relative (above " +
                      tolerance_text(a.precision.tolerance) + ")");
    }
    if (a.precision_fp16 && a.precision_fp16->breaks_down()) {
        const auto& w = a.precision_fp16->worst;
        why.push_back("fp16 breaks down (reported, not failed): " + pair_text("binary16", w.b, "against double", w.a, w.relative) + " at " + dir + "=" +
                      vector_text(w.v) + ", " + short_number(w.relative) + " relative (above " +
                      tolerance_text(a.precision_fp16->tolerance) + ")");
    }
    std::string s;
    for (const auto& w : why) s += (s.empty() ? "" : "; ") + w;
    return s;
}

}  // namespace

// The parameters' values at one combination, as fields param_NAME: a float as a number, a bool as
// a boolean, a color as its text r,g,b.
void set_parameters(record& r, const parameter_point& at) {
    for (std::size_t k = 0; k < at.grid.size(); ++k) {
        const parameter_values& g = at.grid[k];
        const std::size_t i = at.index[k];
        field_value v = g.values[i][0];
        if (g.p->type == shader_parameter::kind::boolean) v = g.values[i][0] != 0;
        else if (g.p->type == shader_parameter::kind::color) v = g.texts[i];
        r.set("param_" + g.p->name, v);
    }
}

std::string tolerance_text(double x) {
    std::string s = shortest_text(x);
    // 1e-09 as 1e-9
    const auto e = s.find('e');
    if (e != std::string::npos) {
        std::string sign = s[e + 1] == '-' ? "-" : "";
        std::size_t digits = e + 1 + (s[e + 1] == '-' || s[e + 1] == '+');
        while (digits + 1 < s.size() && s[digits] == '0') ++digits;
        s = s.substr(0, e + 1) + sign + s.substr(digits);
    }
    return s;
}

record file_record(const brdf_request& o, const char* table) {
    record r;
    r.table = table;
    if (!o.material.empty()) r.set("material", o.material);
    r.set("file", o.shown_file.empty() ? o.file : o.shown_file);
    return r;
}

// Where f returned NaN, Inf or a negative value the record says so (values, problem_V); its albedo
// is then null, but where f was not finite only at isolated directions
// (albedo_excludes_non_finite), whose albedo is over the other directions.
record albedo_record(const brdf_request& o, const parameter_point& at, double theta_deg, const albedo_results& a) {
    const auto& e = a.albedo;
    record r = file_record(o, "brdf");
    set_parameters(r, at);
    r.set("theta_deg", theta_deg).set("fixed", normzoo::code::fixed_name(o.fixed));
    const bool finite = e.finite(), non_negative = !e.found.negative, given = e.usable() && non_negative;
    const auto& big = e.largest();
    const double storage = a.texture_storage_bound.value_or(0);
    const bool conserving = big.value <= 1 + big.abs_error + storage;
    if (given) {
        r.set("albedo", big.value);
        r.set("albedo_rgb", numbers_text({e.channel[0].value, e.channel[1].value, e.channel[2].value}));
        r.set("albedo_fp32", a.albedo_fp32.usable() ? field_value(a.albedo_fp32.largest().value) : field_value(nullptr));
        r.set("error_estimate", std::isfinite(storage) ? field_value(big.abs_error + storage) : field_value(nullptr));
    } else {
        r.set("albedo", nullptr).set("albedo_rgb", nullptr).set("albedo_fp32", nullptr).set("error_estimate", nullptr);
    }
    if (a.texture_storage_bound)
        r.set("texture_storage_bound", std::isfinite(storage) ? field_value(storage) : field_value(nullptr));
    r.set("conserving", given ? field_value(conserving) : field_value(nullptr));
    // non-finite first (no albedo, or one over isolated directions), then what a GPU leaves
    // undefined (the CPU's numbers, which a GPU need not give), then negative
    const bool undefined = a.undefined_evaluations > 0;
    r.set("values", !finite ? "non-finite" : undefined ? "gpu-undefined" : !non_negative ? "negative" : "reflectance");
    const auto& where = !finite ? e.found.non_finite : e.found.negative;
    if (finite && undefined) {
        const auto& u = *std::find_if(a.undefined.begin(), a.undefined.end(), [](const gpu_undefined_seen& x) { return x.count > 0; });
        const double* d = o.fixed == fixed_direction::light ? u.v : u.l;
        r.set("problem_V", vector_text({d[0], d[1], d[2]}));
        r.set("problem_count", static_cast<std::int64_t>(a.undefined_evaluations));
    } else {
        r.set("problem_V", where ? field_value(vector_text(*where.first)) : field_value(nullptr));
        r.set("problem_count", static_cast<std::int64_t>(where.count));
    }
    r.set("albedo_excludes_non_finite", given && !finite);
    r.set("fp32_worst_relative", a.precision.worst.relative);
    r.set("fp32_breakdown", a.precision.breaks_down());
    r.set("fp32_where_V", vector_text(a.precision.worst.v));
    const bool fp16_breaks = a.precision_fp16 && a.precision_fp16->breaks_down();
    if (a.albedo_fp16) {  // only where the code declares reduced precision (docs/brdf-code.md#precision)
        r.set("albedo_fp16", given && a.albedo_fp16->usable() ? field_value(a.albedo_fp16->largest().value) : field_value(nullptr));
        r.set("fp16_worst_relative", a.precision_fp16->worst.relative);
        r.set("fp16_breakdown", fp16_breaks);
        r.set("fp16_where_V", vector_text(a.precision_fp16->worst.v));
    }
    r.set("evaluations", static_cast<std::int64_t>(e.evaluations));
    r.set("lobe_width", e.lobe.width);
    // an fp16 breakdown is reported, not failed: the binary16 program is what a mobile GPU may
    // run, and a desktop build of the same file runs mediump in fp32 (docs/brdf-code.md#precision)
    r.set("pass", finite && non_negative && !undefined && (conserving || o.allow_energy_gain) && !a.precision.breaks_down());
    const std::string reason = albedo_reason(o, a, given, conserving);
    r.set("reason", reason.empty() ? field_value(nullptr) : field_value(reason));
    return r;
}

record reciprocity_record(const brdf_request& o, const parameter_point& at, const normzoo::code::reciprocity_result& rec) {
    record r = file_record(o, "brdf-checks");
    r.set("check", "reciprocity");
    set_parameters(r, at);
    r.set("parameter", nullptr).set("theta_deg", nullptr).set("fixed", nullptr).set("worst", rec.worst.relative);
    r.set("tolerance", rec.tolerance);
    const std::string pair = "L=" + vector_text(rec.worst.l) + " V=" + vector_text(rec.worst.v);
    r.set("where", pair).set("pass", rec.reciprocal());
    r.set("reason", rec.reciprocal() ? field_value(nullptr)
                                     : field_value("not reciprocal: " +
                                                   pair_text("f(L, V) =", rec.worst.a, "and f(V, L) =", rec.worst.b, rec.worst.relative) +
                                                   " at " + pair + ", " + short_number(rec.worst.relative) + " relative (above " +
                                                   tolerance_text(rec.tolerance) + ")"));
    return r;
}

// Reported, not failed (no pass): a parameter may be meant to change the albedo (a base color).
record normalization_record(const brdf_request& o, const std::string& name,
                            const std::vector<std::pair<std::string, normzoo::quadrature::estimate<double>>>& points,
                            double theta_deg) {
    std::vector<normzoo::quadrature::estimate<double>> es;
    for (const auto& p : points) es.push_back(p.second);
    const auto n = normzoo::code::check_normalization(es);
    record r = file_record(o, "brdf-checks");
    r.set("check", "normalization").set("parameter", name).set("theta_deg", theta_deg);
    r.set("fixed", normzoo::code::fixed_name(o.fixed)).set("worst", n.spread).set("tolerance", nullptr);
    std::ostringstream where;
    where.precision(12);
    where << name << "=" << points[n.lowest].first << ": " << points[n.lowest].second.value << ", " << name << "="
          << points[n.highest].first << ": " << points[n.highest].second.value << " (bounds " << n.bound << ")";
    r.set("where", where.str()).set("normalized", n.normalized());
    r.set("reason", nullptr);
    return r;
}

}  // namespace verify
