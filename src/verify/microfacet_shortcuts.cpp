#include "microfacet_shortcuts.hpp"

#include "microfacet_tables.hpp"
#include "plots.hpp"
#include "tables/grid.hpp"

#include <normzoo/detail/parallel.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/split_sum.hpp>
#include <normzoo/microfacet/split_sum_shortcuts.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace verify {

namespace mf = normzoo::microfacet;

namespace {

struct worst {
    double error = -1, alpha = 0, mu = 0, sum2 = 0, bound = 0;
    std::size_t count = 0;
    void add(double e, double a, double m, double reference_bound) {
        if (std::abs(e) > error) error = std::abs(e), alpha = a, mu = m;
        sum2 += e * e;
        ++count;
        bound = std::max(bound, reference_bound);
    }
};

record shortcut_record(const std::string& shortcut, const std::string& reference, const std::string& quantity,
                       const std::string& grid, const worst& w, std::int64_t samples = 0) {
    record r{"microfacet-shortcuts", {}};
    r.set("shortcut", shortcut)
        .set("reference", reference)
        .set("quantity", quantity)
        .set("grid", grid)
        .set("max_abs_error", w.error)
        .set("at_alpha", w.alpha)
        .set("at_mu", w.mu)
        .set("rms_error", std::sqrt(w.sum2 / double(w.count)))
        .set("reference_error_bound", w.bound)
        .set("samples", samples);
    return r;
}

// What each family of shortcuts adds to: the table's rows and its figure's error maps, in order.
struct shortcut_rows {
    std::vector<record> rows;
    std::vector<error_map> maps;
};

// 1. Visibility shortcuts against the exact Smith forms, E with F = 1 on the grid of microfacet-energy.
void visibility_rows(unsigned jobs, shortcut_rows& out) {
    const auto alpha_inputs = microfacet_energy_alphas(), mu_inputs = microfacet_energy_mus();
    const std::vector<double> alphas = doubles_of(alpha_inputs), mus = doubles_of(mu_inputs);
    const std::vector<std::string> gs = {"smith-height-correlated", "smith-separable", "schlick-ggx",
                                         "schlick-ggx-remapped", "hammon", "smith-height-correlated-fast"};
    std::vector<std::vector<normzoo::quadrature::estimate<double>>> e(gs.size());
    for (std::size_t g = 0; g < gs.size(); ++g) {
        const auto c = mf::composition::parse("ggx/" + gs[g] + "/one");
        e[g].resize(alphas.size() * mus.size());
        normzoo::detail::parallel_for(e[g].size(), jobs, [&](std::size_t i) {
            e[g][i] = mf::directional_albedo(c, mus[i % mus.size()], alphas[i / mus.size()]);
        });
    }
    const std::string energy_grid = "alpha " + range_text(alpha_inputs) + " (" + std::to_string(alphas.size()) + "), mu " +
                                    range_text(mu_inputs) + " (" + std::to_string(mus.size()) + ")";
    for (std::size_t g = 1; g < gs.size(); ++g)
        for (std::size_t ref : {std::size_t(0), std::size_t(1)}) {
            if (ref == g) continue;
            worst w;
            for (std::size_t i = 0; i < e[g].size(); ++i)
                w.add(e[g][i].value - e[ref][i].value, alphas[i / mus.size()], mus[i % mus.size()],
                      e[g][i].abs_error + e[ref][i].abs_error);
            out.rows.push_back(shortcut_record("ggx/" + gs[g] + "/one", "ggx/" + gs[ref] + "/one", "E", energy_grid, w));
            if (ref == 0 && g != 5) {  // against height-correlated Smith; Filament's fast form is Hammon's, algebraically
                error_map m{"E: " + gs[g] + " - smith-height-correlated", mus, alphas, {}};
                for (std::size_t i = 0; i < e[g].size(); ++i) m.values.push_back(e[g][i].value - e[ref][i].value);
                out.maps.push_back(std::move(m));
            }
        }
}

// The split-sum pairs of 2, 2b and 3 sit at the texel centres of an n x n table in mu and a
// roughness variable (docs/lut.md, "Texel centres"): texel k at mu = centre(k % n) in row
// j = k / n, whose alpha is alpha_of(centre(j)).
constexpr std::size_t n = 32;

// "32 x 32 texel centres, mu = (i + 0.5)/32, r = (j + 0.5)/32": those centres in words.
std::string texel_centres(const std::string& roughness) {
    const std::string size = std::to_string(n);
    return size + " x " + size + " texel centres, mu = (i + 0.5)/" + size + ", " + roughness + " = (j + 0.5)/" + size;
}
std::string lut_grid() { return texel_centres("r") + ", alpha = r^2"; }
using texel_table = std::vector<mf::split_sum_value>;

double centre(std::size_t i, std::size_t texels) { return (double(i) + 0.5) / double(texels); }
double alpha_of_r(double r) { return r * r; }  // the perceptual roughness engines index by

// The exact pair of composition `id` at every texel.
template <class AlphaOf>
texel_table exact_table(const std::string& id, const AlphaOf& alpha_of, unsigned jobs) {
    const auto c = mf::composition::parse(id);
    texel_table t(n * n);
    normzoo::detail::parallel_for(t.size(), jobs, [&](std::size_t k) {
        t[k] = mf::split_sum(c, centre(k % n, n), alpha_of(centre(k / n, n)));
    });
    return t;
}

// An error map over the texel centres, its rows at alpha_of(centre(j)).
template <class AlphaOf>
error_map texel_map(const std::string& title, const AlphaOf& alpha_of) {
    error_map m{title, {}, {}, {}};
    for (std::size_t k = 0; k < n; ++k) m.mus.push_back(centre(k, n)), m.alphas.push_back(alpha_of(centre(k, n)));
    return m;
}

// 2. EnvBRDFApprox at the texel centres in (mu, r), alpha = r^2: against the exact pair of the G
// it was fitted for (Unreal's, Schlick-GGX with k = alpha/2) and of height-correlated Smith.
void env_brdf_approx_rows(const texel_table& unreal, const texel_table& correlated, shortcut_rows& out) {
    using fit = mf::env_brdf_approx;
    for (const auto* ref : {&unreal, &correlated}) {
        worst wa, wb;
        for (std::size_t k = 0; k < n * n; ++k) {
            const double r = centre(k / n, n), mu = centre(k % n, n);
            const auto [a, b] = fit::eval(r, mu);
            wa.add(a - (*ref)[k].a.value, r * r, mu, (*ref)[k].a.abs_error);
            wb.add(b - (*ref)[k].b.value, r * r, mu, (*ref)[k].b.abs_error);
        }
        const std::string id = ref == &unreal ? std::string(fit::made_for) : "ggx/smith-height-correlated/schlick";
        if (ref == &unreal) {  // the fit against the G it was made for, over the texel centres (alpha = r^2)
            error_map m = texel_map("A: EnvBRDFApprox - exact (Schlick-GGX, k = alpha/2)", alpha_of_r);
            for (std::size_t k = 0; k < n * n; ++k)
                m.values.push_back(fit::eval(centre(k / n, n), centre(k % n, n)).a - (*ref)[k].a.value);
            out.maps.push_back(std::move(m));
        }
        out.rows.push_back(shortcut_record(std::string(fit::id), id, "A", lut_grid(), wa));
        out.rows.push_back(shortcut_record(std::string(fit::id), id, "B", lut_grid(), wb));
    }
}

// 2b. Lazarov 2013's fit, against the BRDF it was made for, at the texel centres of a 32 x 32
// table in (mu, gloss).
void lazarov_rows(unsigned jobs, shortcut_rows& out) {
    using fit = mf::lazarov_2013;
    const std::string reference(fit::made_for);
    const auto t = exact_table(reference, fit::alpha, jobs);
    worst wa, wb;
    error_map m = texel_map("A: Lazarov 2013 - exact (Blinn-Phong, Schlick-Beckmann)", fit::alpha);
    for (std::size_t k = 0; k < n * n; ++k) {
        const double g = centre(k / n, n), mu = centre(k % n, n);
        const auto [a, b] = fit::eval(g, mu);
        wa.add(a - t[k].a.value, fit::alpha(g), mu, t[k].a.abs_error);
        wb.add(b - t[k].b.value, fit::alpha(g), mu, t[k].b.abs_error);
        m.values.push_back(a - t[k].a.value);
    }
    out.maps.push_back(std::move(m));
    const std::string grid = texel_centres("gloss g") + ", alpha = sqrt(2/(8192^g + 2))";
    out.rows.push_back(shortcut_record(std::string(fit::id), reference, "A", grid, wa));
    out.rows.push_back(shortcut_record(std::string(fit::id), reference, "B", grid, wb));
}

// 3. The Monte Carlo baker, against the exact height-correlated table.
void monte_carlo_rows(const texel_table& correlated, unsigned jobs, shortcut_rows& out) {
    using baker = mf::monte_carlo_baker;
    const std::string id(baker::id), reference(baker::made_for);
    for (unsigned samples : {64u, 256u, 1024u, 4096u}) {
        std::vector<mf::split_sum_pair<float>> mc(n * n);
        normzoo::detail::parallel_for(mc.size(), jobs, [&](std::size_t k) {
            mc[k] = baker::eval(float(centre(k / n, n)), float(centre(k % n, n)), samples);
        });
        worst wa, wb;
        for (std::size_t k = 0; k < n * n; ++k) {
            const double r = centre(k / n, n), mu = centre(k % n, n);
            wa.add(double(mc[k].a) - correlated[k].a.value, r * r, mu, correlated[k].a.abs_error);
            wb.add(double(mc[k].b) - correlated[k].b.value, r * r, mu, correlated[k].b.abs_error);
        }
        if (samples == 256) {
            error_map m = texel_map("A: Monte Carlo baker, N = 256, float - exact", alpha_of_r);
            for (std::size_t k = 0; k < n * n; ++k) m.values.push_back(double(mc[k].a) - correlated[k].a.value);
            out.maps.push_back(std::move(m));
        }
        out.rows.push_back(shortcut_record(id, reference, "A", lut_grid(), wa, samples));
        out.rows.push_back(shortcut_record(id, reference, "B", lut_grid(), wb, samples));
    }
}

// Schlick's Fresnel is compared over cos = k/10000, k = 0 to 10000.
constexpr int cosine_steps = 10000;
std::string cosine_grid() { return "cos = 0 to 1 by " + value_text(1.0 / cosine_steps); }

// The dielectrics' indices of refraction.
std::vector<double> dielectric_etas() { return {1.2, 1.33, 1.5, 1.8, 2.0, 2.5}; }

// 4. Schlick's Fresnel against the exact dielectric at F0 = ((eta - 1)/(eta + 1))^2, over
// cos = k/10000.
void schlick_dielectric_rows(shortcut_rows& out) {
    for (double eta : dielectric_etas()) {
        mf::fresnel_params<double> p;
        p.eta = eta, p.f0 = mf::f0_of_eta(eta);
        worst w;
        for (int k = 0; k <= cosine_steps; ++k) {
            const double c = k / double(cosine_steps);
            w.add(mf::fresnel_schlick::eval(c, p) - mf::fresnel_dielectric::eval(c, p), 0, c, 1e-15);
        }
        out.rows.push_back(shortcut_record("schlick", "dielectric, eta = " + std::to_string(eta).substr(0, 4), "F",
                                           cosine_grid(), w));
    }
}

// Metals at 550 nm as tabulated in the Wolfram Demonstration "Fresnel Coefficients of Metals"
// (Coleman and Petrova-Mayor 2020, after Hecht's Optics, 5th ed.).
struct metal {
    const char* name;
    double n, k;
};
std::vector<metal> metals() {
    return {{"gold", 0.421, 2.345}, {"silver", 0.145, 3.190}, {"aluminium", 0.965, 6.399}, {"copper", 0.676, 2.624}};
}

// 5. Schlick's Fresnel with F0 = F(1) against the exact conductor, for the metals above.
void schlick_conductor_rows(shortcut_rows& out) {
    for (const metal& m : metals()) {
        mf::fresnel_params<double> p;
        p.eta = m.n, p.k = m.k;
        p.f0 = mf::fresnel_conductor::eval(1.0, p);
        worst w;
        for (int k = 0; k <= cosine_steps; ++k) {
            const double c = k / double(cosine_steps);
            w.add(mf::fresnel_schlick::eval(c, p) - mf::fresnel_conductor::eval(c, p), 0, c, 1e-15);
        }
        char label[96];
        std::snprintf(label, sizeof label, "conductor, %s, %.3f + %.3fi at 550 nm", m.name, m.n, m.k);
        out.rows.push_back(shortcut_record("schlick", label, "F", cosine_grid(), w));
    }
}

table_info shortcuts_info() {
    return {"microfacet-shortcuts",
            "The shortcuts engines take, against the exact integrals: visibility approximations, the EnvBRDFApprox and "
            "Lazarov 2013 fits, Monte Carlo bakers, Schlick's Fresnel for dielectrics and metals (docs/microfacet.md, "
            "\"The shortcuts, measured\")",
            {"E and the split-sum pair (A, B) by microfacet/albedo.hpp and microfacet/split_sum.hpp at tolerance 1e-10; "
             "reference_error_bound: the largest bound on the exact values compared (both sides' where both are "
             "integrals)",
             "max_abs_error: the largest |shortcut - reference| over the grid, at (at_alpha, at_mu); signed errors enter "
             "rms_error",
             "Monte Carlo baker: Karis 2013's IntegrateBRDF loop with height-correlated Smith visibility, in float, N "
             "Hammersley points; EnvBRDFApprox and Lazarov 2013 in double (the fits alone, before any saturate)",
             "metals: n + ik at 550 nm from the Wolfram Demonstration \"Fresnel Coefficients of Metals\" (Coleman and "
             "Petrova-Mayor 2020, after Hecht, Optics, 5th ed.); Schlick's F0 is the conductor's F at normal incidence"},
            {"shortcut", "reference", "quantity", "samples", "max_abs_error", "at_alpha", "at_mu", "rms_error"},
            {}};
}

}  // namespace

table_output shortcuts_table(unsigned jobs) {
    shortcut_rows out;
    visibility_rows(jobs, out);
    // Both exact tables of 2 at alpha = r^2; height-correlated Smith's serves 3 as well.
    const texel_table unreal = exact_table(std::string(mf::env_brdf_approx::made_for), alpha_of_r, jobs);
    const texel_table correlated = exact_table("ggx/smith-height-correlated/schlick", alpha_of_r, jobs);
    env_brdf_approx_rows(unreal, correlated, out);
    lazarov_rows(jobs, out);
    monte_carlo_rows(correlated, jobs, out);
    schlick_dielectric_rows(out);
    schlick_conductor_rows(out);
    const std::string size = std::to_string(n);
    return {shortcuts_info(), std::move(out.rows),
            "visibility on alpha x mu; tables at " + size + " x " + size + " texel centres; Fresnel eta " +
                range_text(dielectric_etas()) + " and " + count_text(metals().size()) + " metals",
            "",
            [maps = std::move(out.maps)](const table_output&, file_set& files) { return plot_error_maps(maps, files); }};
}

}  // namespace verify
