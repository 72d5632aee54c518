#include "brdf_conformance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "args.hpp"

namespace verify {

namespace {

std::string names_of(const std::vector<parameter_values>& grid) {
    std::string s;
    for (const auto& g : grid) s += (s.empty() ? "" : ", ") + g.p->name;
    return s.empty() ? "none" : s;
}

std::string names_of(const reference_material& m) {
    std::string s;
    for (const auto& p : m.parameters) s += (s.empty() ? "" : ", ") + p.name + (p.colour ? " (colour)" : "");
    return s;
}

std::size_t grid_index_of(const std::vector<parameter_values>& grid, const std::string& name) {
    std::size_t k = 0;
    while (k < grid.size() && grid[k].p->name != name) ++k;
    return k;
}

bool colour(const parameter_values& g) { return g.p->type == shader_parameter::kind::color; }

std::string short_number(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return buf;
}

// The directions compared: L at theta 0, 5, ..., 85, 89, 89.9 degrees and every 15 degrees of
// azimuth (the whole circle: a code need not be symmetric about the plane of incidence).
std::vector<double> light_thetas() {
    std::vector<double> t;
    for (int d = 0; d <= 85; d += 5) t.push_back(d);
    t.push_back(89);
    t.push_back(89.9);
    return t;
}

}  // namespace

std::vector<conformance_binding> bind_conformance(const std::vector<parameter_values>& grid, const reference_material& m,
                                                  const std::vector<std::string>& maps) {
    std::vector<conformance_binding> out;
    auto bind = [&](std::size_t g, std::size_t p, const std::string& what) {
        if (colour(grid[g]) != m.parameters[p].colour)
            throw bad_input(what + ": " + grid[g].p->name + " is " + (colour(grid[g]) ? "a colour" : "a number") + " and " +
                            m.id + "'s " + m.parameters[p].name + " is " + (m.parameters[p].colour ? "a colour" : "a number"));
        for (const auto& b : out)
            if (b.material_index == p)
                throw bad_input(what + ": " + m.id + "'s " + m.parameters[p].name + " is mapped twice");
        out.push_back({g, p});
    };
    for (const auto& text : maps) {
        const std::string what = "--map " + text;
        const auto eq = text.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
            throw bad_input(what + ": not SHADER_PARAM=MATERIAL_PARAM");
        const std::string s = text.substr(0, eq), p = text.substr(eq + 1);
        const std::size_t g = grid_index_of(grid, s), k = m.index_of(p);
        if (g == grid.size()) throw bad_input(what + ": the code has no parameter " + s + " (it has: " + names_of(grid) + ")");
        if (k == m.parameters.size())
            throw bad_input(what + ": " + m.id + " has no parameter " + p + " (it has: " + names_of(m) + ")");
        bind(g, k, what);
    }
    // then each code parameter --map left alone to the material's of its name, if it is free
    for (std::size_t g = 0; g < grid.size(); ++g) {
        const std::size_t k = m.index_of(grid[g].p->name);
        bool taken = k == m.parameters.size();
        for (const auto& b : out) taken = taken || b.grid_index == g || b.material_index == k;
        if (!taken) bind(g, k, "--against " + m.id + " (" + grid[g].p->name + " by its name)");
    }
    if (out.empty())
        throw bad_input("--against " + m.id + ": no parameter of the code has a name of the material's; give --map "
                        "SHADER_PARAM=MATERIAL_PARAM (the code's: " + names_of(grid) + "; " + m.id + "'s: " + names_of(m) + ")");
    return out;
}

std::vector<rgb_value> material_values(const parameter_point& at, const reference_material& m,
                                       const std::vector<conformance_binding>& bindings) {
    std::vector<rgb_value> v;
    for (const auto& p : m.parameters) v.push_back(p.default_value);
    for (const auto& b : bindings) {
        const auto& slots = at.grid[b.grid_index].values[at.index[b.grid_index]];
        for (std::size_t c = 0; c < 3; ++c) v[b.material_index][c] = slots[std::min(c, slots.size() - 1)];
    }
    return v;
}

conformance_result compare_to_material(const code_sample& f, const reference_material& m, const std::vector<rgb_value>& values,
                                       const std::vector<conformance_incidence>& incidences, double tolerance) {
    conformance_result r;
    const double degree = boost::math::constants::pi<double>() / 180;
    struct pair_value {
        rgb_value code, material;
        double theta_l, phi_l, theta_v;
    };
    std::vector<pair_value> pairs;
    double largest = 0;
    for (const auto& in : incidences) {
        const normzoo::vec3<double> v(std::sqrt((1 - in.mu) * (1 + in.mu)), 0, in.mu);
        for (double t : light_thetas())
            for (int p = 0; p < 360; p += 15) {
                const normzoo::vec3<double> l(std::sin(t * degree) * std::cos(p * degree), std::sin(t * degree) * std::sin(p * degree),
                                              std::cos(t * degree));
                pairs.push_back({f(l, v), m.f(l, v, values), t, double(p), in.theta_deg});
                for (double x : pairs.back().material) largest = std::max(largest, std::abs(x));
            }
    }
    r.directions = pairs.size();
    for (const auto& q : pairs)
        for (int c = 0; c < 3; ++c) {
            const double a = q.code[c], b = q.material[c];
            if (!std::isfinite(a) || !std::isfinite(b)) {
                r.finite = false;
                continue;
            }
            const double scale = std::max({std::abs(b), 1e-9 * largest, std::numeric_limits<double>::min()});
            const double rel = a == b ? 0 : std::abs(a - b) / scale;
            if (rel > r.max_relative_f)
                r.max_relative_f = rel, r.f_code = a, r.f_material = b, r.theta_l = q.theta_l, r.phi_l = q.phi_l,
                r.theta_v = q.theta_v, r.f_channel = c;
        }
    for (const auto& in : incidences) {
        const auto material = m.albedo(in.mu, values, tolerance);
        for (int c = 0; c < 3; ++c) {
            const auto& code = in.shader_albedo->channel[c];
            const double d = std::abs(code.value - material[c].value);
            if (d >= r.albedo_difference) {
                r.albedo_difference = d, r.albedo_bound = code.abs_error + material[c].abs_error;
                r.albedo_code = code.value, r.albedo_material = material[c].value, r.albedo_theta = in.theta_deg;
                r.albedo_channel = c;
            }
        }
    }
    return r;
}

record conformance_record(const brdf_request& o, const parameter_point& at, const conformance_result& r) {
    record rec = file_record(o, "brdf-conformance");
    set_parameters(rec, at);
    static const char* channels[] = {"r", "g", "b"};
    const bool f_ok = r.finite && r.max_relative_f <= o.against_tolerance;
    const bool albedo_ok = !(r.albedo_difference - r.albedo_bound > o.against_tolerance);
    rec.set("against", o.against)
        .set("max_relative_f", r.max_relative_f)
        .set("f_code", r.f_code)
        .set("f_material", r.f_material)
        .set("where", "theta_l " + short_number(r.theta_l) + ", phi_l " + short_number(r.phi_l) + ", theta_v " +
                          short_number(r.theta_v) + ", channel " + channels[r.f_channel])
        .set("directions", static_cast<std::int64_t>(r.directions))
        .set("albedo_difference", r.albedo_difference)
        .set("albedo_bound", r.albedo_bound)
        .set("albedo_code", r.albedo_code)
        .set("albedo_material", r.albedo_material)
        .set("albedo_where", "theta_v " + short_number(r.albedo_theta) + ", channel " + channels[r.albedo_channel])
        .set("tolerance", o.against_tolerance)
        .set("pass", f_ok && albedo_ok);
    std::string reason;
    if (!r.finite) reason = "NaN or Inf in the code's or the material's f";
    else if (!f_ok)
        reason = "f differs by " + short_number(r.max_relative_f) + " (relative) at " + rec.text("where") + ": code " +
                 short_number(r.f_code) + ", " + o.against + " " + short_number(r.f_material);
    if (!albedo_ok)
        reason += std::string(reason.empty() ? "" : "; ") + "the albedo differs by " + short_number(r.albedo_difference) +
                  " (bound " + short_number(r.albedo_bound) + ") at " + rec.text("albedo_where");
    rec.set("reason", reason);
    return rec;
}

table_info conformance_info(const brdf_request& o, const std::vector<parameter_values>& grid,
                            const std::vector<conformance_binding>& bindings, const reference_material& m) {
    std::string mapped;
    for (const auto& b : bindings)
        mapped += (mapped.empty() ? "" : ", ") + grid[b.grid_index].p->name + " -> " + m.parameters[b.material_index].name;
    std::vector<std::string> md = {"file"}, ids = {"material", "file"};
    for (const auto& g : grid) {
        if (g.swept()) md.push_back("param_" + g.p->name);
        ids.push_back("param_" + g.p->name);
    }
    for (const char* k : {"max_relative_f", "where", "albedo_difference", "albedo_bound", "pass", "reason"}) md.push_back(k);
    table_info t{"brdf-conformance",
                 "A BRDF given as code against the specification's material " + m.id,
                 {"parameters mapped: " + mapped + "; the material's others at their defaults (docs/materials.md)",
                  "f compared per channel at V = each incidence and L at theta_l 0, 5, ..., 85, 89, 89.9 degrees and phi_l every "
                  "15 degrees; relative to |f_material|, or to 1e-9 of the largest where that is smaller",
                  "albedo with V held, the code's by the black-box integrator and the material's by its own, tolerance " +
                      tolerance_text(o.tolerance) + "; albedo_bound: the two bounds added",
                  "pass: max_relative_f <= tolerance and albedo_difference - albedo_bound <= tolerance (--against-tolerance, "
                  "default 1e-6)"},
                 md,
                 {"max_relative_f", "albedo_difference"}};
    t.id_keys = ids;
    return t;
}

}  // namespace verify
