#include "microfacet_tables.hpp"

#include <normzoo/albedo_input.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/geometry.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>
#include <normzoo/microfacet/split_sum.hpp>
#include <normzoo/real.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "args.hpp"
#include "microfacet_shortcuts.hpp"
#include "plots.hpp"
#include "tables/energy_keys.hpp"
#include "tables/grid.hpp"

namespace verify {

namespace mf = normzoo::microfacet;
using normzoo::decimal;
using estimate = normzoo::quadrature::estimate<double>;

// The message below and --mu's help (command_line.cpp) write the floor out
static_assert(mf::smallest_mu == 1e-8, "the incidence floor is written as 1e-8 in messages");
// and the roughness floor as 1e-8 (r: 1e-4), there and in roughness_range_of (part_inputs.hpp)
static_assert(mf::smallest_alpha == 1e-8, "the roughness floor is written as 1e-8 in messages");

void set_part_keys(record& r, const mf::composition& c, const part_inputs& p, std::optional<double> f0) {
    if (f0 && uses_f0(c, p)) {
        r.set("f0", *f0);
        if (p.f0) r.set("f0_input", p.f0->text());
    }
    for (const auto& q : part_parameters())
        if (p.*q.input && c.reads(q.name)) r.set(q.name, c.*q.member).set(std::string(q.name) + "_input", (p.*q.input)->text());
}

mu_value mu_of(const incidence_input& in) {
    auto refuse_below = [&](double mu) {
        if (!(mu >= mf::smallest_mu))
            throw bad_input(std::string(in.degrees ? "theta = " : "mu = ") + in.value.text() + (in.degrees ? " degrees" : "") +
                            ": the incidence cosine is below 1e-8 (90 - 5.7e-7 degrees), the smallest the microfacet "
                            "albedo takes (docs/microfacet.md)");
    };
    if (in.degrees) {
        const auto angle = normzoo::degrees_of<normzoo::quad>(in.value);
        const double mu = static_cast<double>(angle.cos_t);
        refuse_below(mu);
        const double delta = static_cast<double>(abs(angle.cos_t - normzoo::quad(mu))) + 1e-33;
        return {mu, delta, in.value.to<double>()};
    }
    const double mu = in.value.to<double>();
    refuse_below(mu);
    return {mu, in.value.rounding<double>() * mu, std::acos(mu) * 57.295779513082320876798};
}

bool squares_exactly(const normzoo::decimal& r) {
    const double x = r.to<double>();
    return r.rounding<double>() == 0 && std::fma(x, x, -(x * x)) == 0;
}

alpha_value alpha_of(const roughness_input& in) {
    const double x = in.value.to<double>();
    const double alpha = in.perceptual ? x * x : x;  // alpha = r^2: r's rounding twice, and the product's
    if (!(alpha >= mf::smallest_alpha))
        throw bad_input(std::string(in.perceptual ? "r = " : "alpha = ") + in.value.text() +
                        ": the roughness is below alpha = 1e-8 (r = 1e-4), the smallest the microfacet albedo takes "
                        "(docs/microfacet.md)");
    if (!in.perceptual) return {x, in.value.rounding<double>() * x};
    if (squares_exactly(in.value)) return {alpha, 0.0};
    return {alpha, alpha * (2 * in.value.rounding<double>() + 1.2e-16)};
}

void refuse_outside_fit(const mf::composition& c, const roughness_input& in) {
    // charlie-sheen's Lambda is KHR_materials_sheen's fit over alpha in [0, 1] (microfacet/albedo.hpp)
    if (c.g_part == mf::detail::index_of<mf::masking_parts>("charlie-sheen") && alpha_of(in).alpha > 1)
        throw bad_input(std::string(in.perceptual ? "r = " : "alpha = ") + in.value.text() + ": " + c.id +
                        ": charlie-sheen's fitted Lambda is defined for alpha in [0, 1] (KHR_materials_sheen)");
    if (c.transmission && alpha_of(in).alpha > 1)
        throw bad_input(std::string(in.perceptual ? "r = " : "alpha = ") + in.value.text() + ": " + c.id +
                        ": the interface's albedo is integrated for alpha in (0, 1] (docs/microfacet.md)");
}

void refuse_outside_interface(const mf::composition& c, double f0, double alpha, const std::string& where) {
    if (c.eta == 0 && f0 == 1)
        throw bad_input(where + c.id + " needs the interface's index, --eta (or --f0 below 1): at the default F0 = 1 it is a "
                        "mirror that refracts nothing");
    if (alpha > 1)
        throw bad_input(where + c.id + ": alpha = " + std::to_string(alpha) +
                        ": the interface's albedo is integrated for alpha in (0, 1] (docs/microfacet.md)");
}

std::vector<mf::kulla_conty_terms> kulla_conty_row(const mf::composition& c, double alpha, double alpha_delta, double f0,
                                                   double f0_delta, const part_inputs& p) {
    if (c.compensation != mf::composition::compensation_kind::kulla_conty) return {};
    std::vector<mf::kulla_conty_terms> row{mf::kulla_conty_at(c, alpha, f0)};
    if (alpha_delta > 0) row.push_back(mf::kulla_conty_at(c, normzoo::input_rounding_step(alpha), f0));
    if (f0_delta > 0) row.push_back(mf::kulla_conty_at(c, alpha, normzoo::input_rounding_step(f0, 1.0)));
    for (const auto& q : part_parameters()) {
        const auto& x = p.*q.input;
        if (!x || !c.reads(q.name) || !(parameter_delta(q, *x) > 0)) continue;
        auto moved = c;
        moved.*q.member = normzoo::input_rounding_step(c.*q.member, rounding_upper(q));
        row.push_back(mf::kulla_conty_at(moved, alpha, f0));
    }
    return row;
}

table_info composition_energy_info() {
    table_info info{
        "energy",
        "Directional albedo E(mu, alpha) of microfacet compositions D/G/F (docs/microfacet.md)",
        {"E(mu) = integral of f(L, V) N.L over L, f = D G F / (4 N.L N.V), V at cos t = mu; with F = one (GGX or Beckmann) "
         "or Schlick's (GGX, by complete elliptic integrals) and a G of N.L and N.V, one integral over N.L of G times D F's "
         "integral over L's azimuth in closed form, adaptive Gauss-Kronrod 15 (microfacet/azimuthal_albedo.hpp); otherwise in the half vector, in the variable psi in "
         "which D(h) N.h is flat (the inverse CDF of the distribution), the horizon cut in closed form, nested "
         "adaptive Gauss-Kronrod 15 (microfacet/albedo.hpp); generic lobe integral for gtr and the anisotropic D",
         "pass: false where the albedo or its bound is not finite (an integral that broke)",
         "error_estimate: absolute bound (relative above 1): sum of |Kronrod - Gauss| + node rounding bounds + the "
         "inputs' rounding to double (mu, alpha or r, f0 and the parts' parameters as typed: slope over a relative step "
         "of 1e-6, doubled)",
         "alpha: the roughness of Walter et al. 2007; r: perceptual roughness, alpha = r^2; f0: the F part's F0, where "
         "the albedo depends on it (the exact parts' eta = (1 + sqrt F0)/(1 - sqrt F0) unless eta is given); default 1; "
         "f90, eta, k, aspect, gamma: the parts' own parameters, where given (docs/microfacet.md#part-parameters); "
         "NAME_input: an input as typed",
         "kulla-conty, turquin: the compensated albedo by quadrature (microfacet/multiple_scattering.hpp); with F "
         "= one, pass: |E - 1| <= max(error, 1e-10) (the white furnace); the bound, a sum of several integrals' bounds, "
         "can exceed 1e-10: most where 1 - E_avg is small (alpha <= 0.01; Kulla-Conty's lobe divides by it) and above "
         "alpha = 1 (docs/microfacet.md)",
         "D/G/F/transmission: E is the interface's reflection plus refraction, Walter et al. 2007's BTDF beside f, in "
         "the half vector over every h that faces V (microfacet/rough_dielectric.hpp)",
         "conserving: false where albedo - error_estimate > 1"},
        {"model", "alpha", "mu", "albedo", "error_estimate", "conserving"},
        {"albedo"}};
    info.id_keys = energy_id_keys();
    info.check = energy_check_rule();
    return info;
}

table_info microfacet_energy_info() {
    auto info = composition_energy_info();
    info.name = "microfacet-energy";
    info.id_keys = {"material", "model", "alpha_input", "r_input", "mu_input", "theta_input", "f0", "f90", "eta", "k",
                    "aspect", "gamma"};
    info.check = {};  // every field compared exactly
    return info;
}

table_output composition_energy_table(const std::vector<std::string>& models, const std::vector<roughness_input>& roughness,
                                      const std::vector<incidence_input>& incidence, const part_inputs& parts, unsigned jobs) {
    for (const auto& in : incidence) mu_of(in);  // bad input refused before any computing
    const std::vector<mf::composition> comps = check_part_inputs(models, parts, "--");
    for (const auto& c : comps)
        for (const auto& r : roughness) refuse_outside_fit(c, r);
    const f0_value typed_f0 = f0_of(parts);
    const double f0 = typed_f0.f0, f0_delta = typed_f0.delta;
    for (const auto& c : comps)
        if (c.transmission) refuse_outside_interface(c, f0, 0, "--model: ");
    struct task {
        std::size_t model, a, m;
    };
    std::vector<task> tasks;
    for (std::size_t c = 0; c < comps.size(); ++c)
        for (std::size_t a = 0; a < roughness.size(); ++a)
            for (std::size_t m = 0; m < incidence.size(); ++m) tasks.push_back({c, a, m});
    // Kulla-Conty's terms of alpha alone (two hemispherical averages of E), once per (model, alpha);
    // none for the other compositions.
    std::vector<std::vector<mf::kulla_conty_terms>> terms(comps.size() * roughness.size());
    normzoo::detail::parallel_for(terms.size(), jobs, [&](std::size_t i) {
        const auto alpha = alpha_of(roughness[i % roughness.size()]);
        terms[i] = kulla_conty_row(comps[i / roughness.size()], alpha.alpha, alpha.delta, f0, f0_delta, parts);
    });
    std::vector<record> rows(tasks.size());
    normzoo::detail::parallel_for(tasks.size(), jobs, [&](std::size_t i) {
        const auto& t = tasks[i];
        const auto& c = comps[t.model];
        const auto mu = mu_of(incidence[t.m]);
        const auto alpha = alpha_of(roughness[t.a]);
        const auto& row = terms[t.model * roughness.size() + t.a];
        auto at_with = [&](const mf::composition& with, double m, double a, double f) {
            return mf::compensated_albedo(with, m, a, f, {}, row.data(), row.size());
        };
        auto at = [&](double m, double a, double f) { return at_with(c, m, a, f); };
        const estimate e = at(mu.mu, alpha.alpha, f0);
        // what the inputs' rounding to double can move
        const double from_inputs =
            normzoo::albedo_input_rounding([&](double m) { return at(m, alpha.alpha, f0); }, mu.mu, mu.delta, e, 1.0) +
            normzoo::albedo_input_rounding([&](double a) { return at(mu.mu, a, f0); }, alpha.alpha, alpha.delta, e) +
            normzoo::albedo_input_rounding([&](double f) { return at(mu.mu, alpha.alpha, f); }, f0, f0_delta, e, 1.0) +
            part_inputs_rounding(c, parts, e, [&](const mf::composition& moved) { return at_with(moved, mu.mu, alpha.alpha, f0); });
        const double error = e.abs_error + from_inputs;
        record r{"energy", {}};
        r.set("model", c.id).set("alpha", alpha.alpha);
        if (roughness[t.a].perceptual) r.set("r", roughness[t.a].value.to<double>()).set("r_input", roughness[t.a].value.text());
        else r.set("alpha_input", roughness[t.a].value.text());
        r.set("mu", mu.mu).set("theta_deg", mu.theta_deg);
        r.set(incidence[t.m].degrees ? "theta_input" : "mu_input", incidence[t.m].value.text());
        set_part_keys(r, c, parts, f0);
        r.set("albedo", e.value)
            .set("error_estimate", error)
            .set("conserving", std::isfinite(e.value) && std::isfinite(error) && !(e.value - error > 1))
            .set("evaluations", static_cast<std::int64_t>(e.evaluations));
        if (c.compensation != mf::composition::compensation_kind::none && c.f_part == mf::detail::index_of<mf::fresnel_parts>("one"))
            r.set("furnace_deviation", e.value - 1).set("pass", std::abs(e.value - 1) <= std::max(error, 1e-10));
        if (!std::isfinite(e.value) || !std::isfinite(error)) r.set("pass", false);  // an integral that broke fails
        rows[i] = std::move(r);
    });
    return {composition_energy_info(), std::move(rows), "", ""};
}

std::vector<decimal> microfacet_energy_alphas() {
    return decimals({"1e-3", "0.01", "0.05", "0.1", "0.2", "0.3", "0.5", "0.7", "1"});
}
std::vector<decimal> microfacet_energy_mus() {
    return decimals({"1e-4", "1e-3", "0.01", "0.05", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "1"});
}

std::vector<table_output> microfacet_tables(unsigned jobs) {
    const std::vector<std::string> reference = {"ggx/smith-height-correlated/one", "ggx/smith-separable/one",
                                                "beckmann/smith-height-correlated/one", "beckmann/smith-separable/one",
                                                "ggx/smith-height-correlated/one/kulla-conty",
                                                "ggx/smith-height-correlated/one/turquin"};
    std::vector<roughness_input> alphas;
    for (const auto& a : microfacet_energy_alphas()) alphas.push_back({a, false});
    std::vector<incidence_input> mus;
    for (const auto& m : microfacet_energy_mus()) mus.push_back({m, false});
    std::vector<table_output> out;
    auto energy = composition_energy_table(reference, alphas, mus, part_inputs{}, jobs);
    energy.info = microfacet_energy_info();
    for (auto& r : energy.records) r.table = "microfacet-energy";
    energy.parameters = "alpha = " + list_text(microfacet_energy_alphas()) + "; mu = " + list_text(microfacet_energy_mus());
    energy.info.md_pivot = pivot_view{{"model", "alpha"}, "mu", {1e-4, 0.01, 0.1, 0.5, 1}, "albedo"};
    energy.figure = plot_microfacet_energy;
    out.push_back(std::move(energy));

    // E_avg(alpha) and what multiple scattering returns, 1 - E_avg
    const std::vector<std::string> base(reference.begin(), reference.begin() + 4);
    // a few small alphas, then 0.1 to 1 densely: the head names the dense part by its ends
    const std::vector<double> avg_small = {1e-3, 0.01, 0.02, 0.05};
    const std::vector<double> avg_dense = {0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1};
    std::vector<double> avg_alphas = avg_small;
    avg_alphas.insert(avg_alphas.end(), avg_dense.begin(), avg_dense.end());
    std::vector<record> avg(base.size() * avg_alphas.size());
    normzoo::detail::parallel_for(avg.size(), jobs, [&](std::size_t i) {
        const auto c = mf::composition::parse(base[i / avg_alphas.size()]);
        const double a = avg_alphas[i % avg_alphas.size()];
        const auto e = mf::average_albedo(c, a);
        record r{"microfacet-eavg", {}};
        r.set("model", c.id).set("alpha", a).set("E_avg", e.value).set("error_estimate", e.abs_error)
            .set("single_scattering_loss", 1 - e.value).set("evaluations", static_cast<std::int64_t>(e.evaluations))
            .set("pass", e.abs_error <= 1e-10);
        avg[i] = std::move(r);
    });
    out.push_back({table_info{"microfacet-eavg",
                                       "E_avg(alpha) = 2 integral of E(mu) mu dmu, and the energy single scattering loses, "
                                       "1 - E_avg (docs/microfacet.md, \"Multiple scattering\")",
                                       {"E(mu) by microfacet/albedo.hpp at tolerance 5e-11; the integral in mu by adaptive "
                                        "Gauss-Kronrod 15 with panels at 1e-4, 1e-3, 1e-2, 0.1, 0.5 (E moves like mu ln mu at 0)",
                                        "pass: error_estimate <= 1e-10"},
                                       {"model", "alpha", "E_avg", "error_estimate", "single_scattering_loss"},
                                       {"E_avg"}},
                   std::move(avg), "alpha = " + list_text(avg_small) + ", " + range_text(avg_dense), "",
                   plot_microfacet_eavg});
    out.push_back(shortcuts_table(jobs));
    return out;
}

}  // namespace verify
