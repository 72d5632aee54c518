#include "microfacet_shortcuts.hpp"

#include "plots.hpp"

#include <normzoo/detail/parallel.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/split_sum.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace verify {

namespace mf = normzoo::microfacet;
using normzoo::record;

std::pair<double, double> env_brdf_approx(double r, double mu) {
    const double c0[4] = {-1, -0.0275, -0.572, 0.022}, c1[4] = {1, 0.0425, 1.04, -0.04};
    double v[4];
    for (int i = 0; i < 4; ++i) v[i] = r * c0[i] + c1[i];
    const double a004 = std::min(v[0] * v[0], std::exp2(-9.28 * mu)) * v[0] + v[1];
    return {-1.04 * a004 + v[2], 1.04 * a004 + v[3]};
}

std::pair<double, double> lazarov_2013(double gloss, double mu) {
    const double tx = gloss / 0.96, ty = 0.475 * gloss;
    const double tz = (0.0275 - 0.25 * 0.04) / 0.96 * gloss + (0.015 - 0.75 * 0.04) / 0.96, tw = 0.25 * gloss + 0.75;
    const double a0 = tx * std::min(ty, std::exp2(-9.28 * mu)) + tz, a1 = tw;
    return {a1 - a0, a0};
}

double lazarov_alpha(double gloss) { return std::sqrt(2 / (std::pow(8192.0, gloss) + 2)); }

std::pair<float, float> monte_carlo_split_sum(float r, float mu, unsigned samples) {
    const float alpha = r * r, a2 = alpha * alpha;
    const float vx = std::sqrt(1.0f - mu * mu), vz = mu;
    float a = 0, b = 0;
    for (unsigned i = 0; i < samples; ++i) {
        // Hammersley point (i/n, radical inverse of i in base 2)
        unsigned bits = i;
        bits = (bits << 16u) | (bits >> 16u);
        bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
        bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
        bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
        bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
        const float u1 = float(i) / float(samples), u2 = float(bits) * 2.3283064365386963e-10f;
        // GGX importance sampling of h (Walter et al. 2007; Karis 2013)
        const float phi = 6.2831853f * u1;
        const float cos_t = std::sqrt((1 - u2) / (1 + (a2 - 1) * u2)), sin_t = std::sqrt(1 - cos_t * cos_t);
        const float hx = sin_t * std::cos(phi), hz = cos_t;
        const float vh = vx * hx + vz * hz;
        const float lz = 2 * vh * hz - vz;
        const float nl = std::min(std::max(lz, 0.0f), 1.0f), nh = std::min(std::max(hz, 0.0f), 1.0f);
        const float vhc = std::min(std::max(vh, 0.0f), 1.0f);
        if (nl > 0) {
            // height-correlated Smith visibility V = G / (4 N.L N.V) (Heitz 2014, as Filament writes it)
            const float vis = 0.5f / (mu * std::sqrt(nl * nl * (1 - a2) + a2) + nl * std::sqrt(mu * mu * (1 - a2) + a2));
            const float g_vis = vis * 4 * nl * vhc / nh;
            const float x = 1 - vhc, fc = x * x * x * x * x;
            a += (1 - fc) * g_vis;
            b += fc * g_vis;
        }
    }
    return {a / float(samples), b / float(samples)};
}

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

// The texel centres of an n x n table in mu and r (docs/lut.md, "Texel centres").
double centre(std::size_t i, std::size_t n) { return (double(i) + 0.5) / double(n); }

}  // namespace

table_output shortcuts_table(unsigned jobs) {
    std::vector<record> rows;
    std::vector<error_map> maps;  // the figure's error maps
    // 1. Visibility shortcuts against the exact Smith forms, E with F = 1 on the energy grid.
    const std::vector<double> alphas = {1e-3, 0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1};
    const std::vector<double> mus = {1e-4, 1e-3, 0.01, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1};
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
    const std::string energy_grid = "alpha 1e-3 to 1 (9), mu 1e-4 to 1 (14)";
    for (std::size_t g = 1; g < gs.size(); ++g)
        for (std::size_t ref : {std::size_t(0), std::size_t(1)}) {
            if (ref == g) continue;
            worst w;
            for (std::size_t i = 0; i < e[g].size(); ++i)
                w.add(e[g][i].value - e[ref][i].value, alphas[i / mus.size()], mus[i % mus.size()],
                      e[g][i].abs_error + e[ref][i].abs_error);
            rows.push_back(shortcut_record("ggx/" + gs[g] + "/one", "ggx/" + gs[ref] + "/one", "E", energy_grid, w));
            if (ref == 0 && g != 5) {  // against height-correlated Smith; Filament's fast form is Hammon's, algebraically
                error_map m{"E: " + gs[g] + " - smith-height-correlated", mus, alphas, {}};
                for (std::size_t i = 0; i < e[g].size(); ++i) m.values.push_back(e[g][i].value - e[ref][i].value);
                maps.push_back(std::move(m));
            }
        }

    // 2. The split-sum pair at the texel centres of a 32 x 32 table in (mu, r), alpha = r^2: exact
    // for Unreal's G (Schlick-GGX, k = alpha/2) and for height-correlated Smith.
    // Texel k sits at mu = centre(k % n) in row j = k / n, whose roughness alpha is alpha_of(centre(j)).
    const std::size_t n = 32;
    auto alpha_of_r = [](double r) { return r * r; };
    auto exact_table = [&](const std::string& id, const auto& alpha_of) {
        const auto c = mf::composition::parse(id);
        std::vector<mf::split_sum_value> t(n * n);
        normzoo::detail::parallel_for(t.size(), jobs, [&](std::size_t k) {
            t[k] = mf::split_sum(c, centre(k % n, n), alpha_of(centre(k / n, n)));
        });
        return t;
    };
    // An error map over the texel centres, its rows at alpha_of(centre(j)).
    auto texel_map = [&](const std::string& title, const auto& alpha_of) {
        error_map m{title, {}, {}, {}};
        for (std::size_t k = 0; k < n; ++k) m.mus.push_back(centre(k, n)), m.alphas.push_back(alpha_of(centre(k, n)));
        return m;
    };
    const auto unreal = exact_table("ggx/schlick-ggx/schlick", alpha_of_r);
    const auto correlated = exact_table("ggx/smith-height-correlated/schlick", alpha_of_r);
    const std::string lut_grid = "32 x 32 texel centres, mu = (i + 0.5)/32, r = (j + 0.5)/32, alpha = r^2";
    for (const auto* ref : {&unreal, &correlated}) {
        worst wa, wb;
        for (std::size_t k = 0; k < n * n; ++k) {
            const double r = centre(k / n, n), mu = centre(k % n, n);
            const auto [a, b] = env_brdf_approx(r, mu);
            wa.add(a - (*ref)[k].a.value, r * r, mu, (*ref)[k].a.abs_error);
            wb.add(b - (*ref)[k].b.value, r * r, mu, (*ref)[k].b.abs_error);
        }
        const std::string id = ref == &unreal ? "ggx/schlick-ggx/schlick" : "ggx/smith-height-correlated/schlick";
        if (ref == &unreal) {  // the fit against the G it was made for, over the texel centres (alpha = r^2)
            error_map m = texel_map("A: EnvBRDFApprox - exact (Schlick-GGX, k = alpha/2)", alpha_of_r);
            for (std::size_t k = 0; k < n * n; ++k)
                m.values.push_back(env_brdf_approx(centre(k / n, n), centre(k % n, n)).first - (*ref)[k].a.value);
            maps.push_back(std::move(m));
        }
        rows.push_back(shortcut_record("EnvBRDFApprox (Karis 2014)", id, "A", lut_grid, wa));
        rows.push_back(shortcut_record("EnvBRDFApprox (Karis 2014)", id, "B", lut_grid, wb));
    }
    // 2b. Lazarov 2013's fit, against the BRDF it was made for, at the texel centres of a 32 x 32
    // table in (mu, gloss).
    {
        const auto t = exact_table("blinn-phong/schlick-beckmann/schlick", lazarov_alpha);
        worst wa, wb;
        error_map m = texel_map("A: Lazarov 2013 - exact (Blinn-Phong, Schlick-Beckmann)", lazarov_alpha);
        for (std::size_t k = 0; k < n * n; ++k) {
            const double g = centre(k / n, n), mu = centre(k % n, n);
            const auto [a, b] = lazarov_2013(g, mu);
            wa.add(a - t[k].a.value, lazarov_alpha(g), mu, t[k].a.abs_error);
            wb.add(b - t[k].b.value, lazarov_alpha(g), mu, t[k].b.abs_error);
            m.values.push_back(a - t[k].a.value);
        }
        maps.push_back(std::move(m));
        const std::string grid = "32 x 32 texel centres, mu = (i + 0.5)/32, gloss g = (j + 0.5)/32, alpha = sqrt(2/(8192^g + 2))";
        rows.push_back(shortcut_record("Lazarov 2013 (Black Ops II)", "blinn-phong/schlick-beckmann/schlick", "A", grid, wa));
        rows.push_back(shortcut_record("Lazarov 2013 (Black Ops II)", "blinn-phong/schlick-beckmann/schlick", "B", grid, wb));
    }
    // 3. The Monte Carlo baker, against the exact height-correlated table.
    for (unsigned samples : {64u, 256u, 1024u, 4096u}) {
        std::vector<std::pair<float, float>> mc(n * n);
        normzoo::detail::parallel_for(mc.size(), jobs, [&](std::size_t k) {
            mc[k] = monte_carlo_split_sum(float(centre(k / n, n)), float(centre(k % n, n)), samples);
        });
        worst wa, wb;
        for (std::size_t k = 0; k < n * n; ++k) {
            const double r = centre(k / n, n), mu = centre(k % n, n);
            wa.add(double(mc[k].first) - correlated[k].a.value, r * r, mu, correlated[k].a.abs_error);
            wb.add(double(mc[k].second) - correlated[k].b.value, r * r, mu, correlated[k].b.abs_error);
        }
        const std::string id = "Monte Carlo baker, GGX sampling at Hammersley points, float";
        if (samples == 256) {
            error_map m = texel_map("A: Monte Carlo baker, N = 256, float - exact", alpha_of_r);
            for (std::size_t k = 0; k < n * n; ++k) m.values.push_back(double(mc[k].first) - correlated[k].a.value);
            maps.push_back(std::move(m));
        }
        rows.push_back(shortcut_record(id, "ggx/smith-height-correlated/schlick", "A", lut_grid, wa, samples));
        rows.push_back(shortcut_record(id, "ggx/smith-height-correlated/schlick", "B", lut_grid, wb, samples));
    }
    // 4. Schlick's Fresnel against the exact dielectric at F0 = ((eta - 1)/(eta + 1))^2, over
    // cos = k/10000.
    for (double eta : {1.2, 1.33, 1.5, 1.8, 2.0, 2.5}) {
        mf::fresnel_params<double> p;
        p.eta = eta, p.f0 = mf::f0_of_eta(eta);
        worst w;
        for (int k = 0; k <= 10000; ++k) {
            const double c = k / 10000.0;
            w.add(mf::fresnel_schlick::eval(c, p) - mf::fresnel_dielectric::eval(c, p), 0, c, 1e-15);
        }
        rows.push_back(shortcut_record("schlick", "dielectric, eta = " + std::to_string(eta).substr(0, 4), "F",
                                       "cos = 0 to 1 by 1e-4", w));
    }
    // 5. Schlick's Fresnel with F0 = F(1) against the exact conductor, for metals at 550 nm as
    // tabulated in the Wolfram Demonstration "Fresnel Coefficients of Metals" (Coleman and
    // Petrova-Mayor 2020, after Hecht's Optics, 5th ed.).
    struct metal {
        const char* name;
        double n, k;
    };
    for (const metal& m : {metal{"gold", 0.421, 2.345}, metal{"silver", 0.145, 3.190}, metal{"aluminium", 0.965, 6.399},
                           metal{"copper", 0.676, 2.624}}) {
        mf::fresnel_params<double> p;
        p.eta = m.n, p.k = m.k;
        p.f0 = mf::fresnel_conductor::eval(1.0, p);
        worst w;
        for (int k = 0; k <= 10000; ++k) {
            const double c = k / 10000.0;
            w.add(mf::fresnel_schlick::eval(c, p) - mf::fresnel_conductor::eval(c, p), 0, c, 1e-15);
        }
        char label[96];
        std::snprintf(label, sizeof label, "conductor, %s, %.3f + %.3fi at 550 nm", m.name, m.n, m.k);
        rows.push_back(shortcut_record("schlick", label, "F", "cos = 0 to 1 by 1e-4", w));
    }
    normzoo::table_info info{
        "microfacet-shortcuts",
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
    return {info, std::move(rows), "visibility on alpha x mu; tables at 32 x 32 texel centres; Fresnel eta 1.2 to 2.5 and four metals", "",
            [maps = std::move(maps)](const table_output&, file_set& files) { return plot_error_maps(maps, files); }};
}

}  // namespace verify
