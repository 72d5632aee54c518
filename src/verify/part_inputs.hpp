// The parameters of a composition's parts as typed, beside its roughness and incidence: one list
// that the command line, scenes and records read (docs/microfacet.md#part-parameters).
#pragma once
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>
#include <normzoo/microfacet/composition.hpp>

#include "args.hpp"

namespace verify {

// The parameters of a composition's parts as typed (docs/microfacet.md#part-parameters): F0 and,
// each read only by the parts that name it, F90, the index eta and extinction k, the anisotropic
// D's aspect alpha_y / alpha_x, GTR's gamma.
struct part_inputs {
    std::optional<normzoo::decimal> f0, f90, eta, k, aspect, gamma;
};

// The roughness taken, as typed: alpha in [1e-8, 100], r (alpha = r^2) in [1e-4, 10], for the
// options and the scene keys. The floor is the library's smallest_alpha (microfacet/albedo.hpp).
struct roughness_range {
    const char* min;
    const char* max;
};
inline roughness_range roughness_range_of(bool perceptual) {
    return perceptual ? roughness_range{"1e-4", "10"} : roughness_range{"1e-8", "100"};
}

// The parameters beyond F0, one list for the options, the scene keys and the records: each the
// library's declaration (microfacet/part_parameters.hpp: name, meaning, range) and where it goes.
struct part_parameter {
    const char* name;  // the option is --name, the scene and record key name
    std::string min;   // the range as decimals
    std::string max;
    bool min_open;
    const char* meaning;
    std::optional<normzoo::decimal> part_inputs::*input;
    double normzoo::microfacet::composition::*member;
    // The relative rounding of the product the part forms with it in double, as if the parameter
    // itself were rounded that much more (aspect: alpha_y = aspect x alpha); none by a power of two.
    double formed_rounding = 0;

    part_parameter(const normzoo::parameter& declared, std::optional<normzoo::decimal> part_inputs::*in,
                   double normzoo::microfacet::composition::*to, double rounding = 0)
        : name(declared.name.data()),  // the declarations are string literals
          min(normzoo::decimal::shortest(declared.min).text()),
          max(normzoo::decimal::shortest(declared.max).text()),
          min_open(declared.min_open),
          meaning(declared.meaning.data()),
          input(in),
          member(to),
          formed_rounding(rounding) {}
};
inline const std::vector<part_parameter>& part_parameters() {
    namespace mf = normzoo::microfacet;
    using c = mf::composition;
    static const std::vector<part_parameter> list = {
        {mf::f90_parameter, &part_inputs::f90, &c::f90},
        {mf::eta_parameter, &part_inputs::eta, &c::eta},
        {mf::k_parameter, &part_inputs::k, &c::k},
        {mf::aspect_parameter, &part_inputs::aspect, &c::aspect, 0x1p-53},
        {mf::gamma_parameter, &part_inputs::gamma, &c::gamma},
    };
    return list;
}

// The composition `id` with the parameters of p set; bad_input, beginning with `where`, for an id
// that is not a composition.
inline normzoo::microfacet::composition composition_of(const std::string& id, const part_inputs& p, const std::string& where) {
    normzoo::microfacet::composition c;
    try {
        c = normzoo::microfacet::composition::parse(id);
    } catch (const std::invalid_argument& e) {
        throw bad_input(where + e.what());
    }
    for (const auto& q : part_parameters())
        if (p.*q.input && c.reads(q.name)) c.*q.member = (p.*q.input)->to<double>();
    return c;
}

// bad_input for a parameter of p that none of the compositions reads, or eta given beside F0
// where only the exact parts read them; `where` comes before each parameter's name ("--" for
// options). The ids are known to parse. Returns the compositions with p's parameters set.
inline std::vector<normzoo::microfacet::composition> check_part_inputs(const std::vector<std::string>& models, const part_inputs& p,
                                                                       const std::string& where) {
    std::vector<normzoo::microfacet::composition> comps;
    for (const auto& m : models) comps.push_back(composition_of(m, p, "--model: "));
    auto read_by_any = [&](const char* name) {
        return std::any_of(comps.begin(), comps.end(), [&](const normzoo::microfacet::composition& c) { return c.reads(name); });
    };
    auto refuse_unread = [&](const char* name, const std::optional<normzoo::decimal>& x) {
        if (x && !read_by_any(name))
            throw bad_input(where + name + " = " + x->text() + ": no part of " + (models.size() == 1 ? "'" + models[0] + "'" : "these compositions") +
                            " reads it (the parts that do: " + normzoo::microfacet::composition::readers_of(name) + ")");
    };
    for (const auto& q : part_parameters()) refuse_unread(q.name, p.*q.input);
    refuse_unread("f0", p.f0);
    // the other option's name as `where` would begin it: "--eta" on the command line
    const std::string option = where.size() >= 2 && where.compare(where.size() - 2, 2, "--") == 0 ? "--" : "";
    // a conductor's k beside an index from F0 would not be the F0 given
    if (p.k && !p.eta) throw bad_input(where + "k = " + p.k->text() + ": a conductor's k goes with its index, " + option + "eta");
    // F0 beside eta: read only where a Schlick part is (the exact parts take eta)
    if (p.f0 && p.eta &&
        std::none_of(comps.begin(), comps.end(), [](const normzoo::microfacet::composition& c) { return c.reads("f0") && !c.reads("eta"); }))
        throw bad_input(where + "f0 and " + option + "eta: the exact Fresnel parts take their index one way, as eta or from F0");
    return comps;
}

// Whether c's albedo depends on F0: a part reads it (Schlick's, or an exact part's index from F0)
// and no index eta given takes its place.
inline bool uses_f0(const normzoo::microfacet::composition& c, const part_inputs& p) {
    return c.reads("f0") && !(p.eta && c.reads("eta"));
}

// The parameters beyond F0 as options, " --eta 1.5 --k 2", for the command that makes a table again.
inline std::string given_parts(const part_inputs& p) {
    std::string s;
    for (const auto& q : part_parameters())
        if (p.*q.input) s += std::string(" --") + q.name + " " + (p.*q.input)->text();
    return s;
}

}  // namespace verify
