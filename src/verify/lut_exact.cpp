// The exact tables of `verify lut` (lut_exact.hpp): each texel's split-sum pair, E or E_avg by
// the library (microfacet/split_sum_to.hpp, multiple_scattering.hpp) with its bound, and the lut
// records and image made of them.
#include "lut_exact.hpp"

#include <normzoo/albedo_input.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>
#include <normzoo/microfacet/split_sum_to.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

#include "args.hpp"
#include "microfacet_tables.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

std::vector<double> texel_centres(std::size_t n) {
    std::vector<double> c(n);
    for (std::size_t i = 0; i < n; ++i) c[i] = (double(i) + 0.5) / double(n);
    return c;
}

std::string lut_kind_name(lut_kind k) { return k == lut_kind::dfg ? "dfg" : k == lut_kind::e ? "E" : "Eavg"; }

lut_kind lut_kind_of(const std::string& text) {
    if (text == "dfg") return lut_kind::dfg;
    if (text == "E" || text == sheen_e_kind) return lut_kind::e;
    if (text == "Eavg") return lut_kind::eavg;
    throw bad_input("--kind '" + text + "' is not dfg, E, Eavg or sheen-E");
}

std::vector<std::string> lut_channels(lut_kind k) {
    if (k == lut_kind::dfg) return {"A", "B"};
    return {k == lut_kind::e ? "E" : "E_avg"};
}

namespace {

using estimate = normzoo::quadrature::estimate<double>;

// The exact channels of one texel or point (one for E and Eavg, A and B for dfg); mu is not read
// for Eavg; terms: Kulla-Conty's at this alpha and f0, or null; tol: what A and B are asked to;
// e_tol what E and E_avg are (1e-10 in a table, as it says; in a check, the texel's wanted
// tolerance), but under Kulla-Conty's terms 1e-10: they hold at the tolerance they were computed
// at, 1e-10, and a texel at another would compute its own.
std::array<estimate, 2> exact_texel(lut_kind kind, const mf::composition& c, double mu, double alpha, double f0,
                                    const std::vector<mf::kulla_conty_terms>* terms, mf::split_sum_tolerance tol = {},
                                    double e_tol = 1e-10) {
    normzoo::albedo_settings s;
    s.tolerance = terms ? 1e-10 : e_tol;
    if (kind == lut_kind::eavg) return {mf::average_albedo(c, alpha, f0, s), estimate{}};
    if (kind == lut_kind::e)
        return {mf::compensated_albedo(c, mu, alpha, f0, s, terms ? terms->data() : nullptr, terms ? terms->size() : 0), estimate{}};
    try {
        const auto s = mf::split_sum_to(c, mu, alpha, tol);
        return {s.a, s.b};
    } catch (const std::invalid_argument& e) {  // an edge (mu = 0, alpha = 0) of a model without its limits
        throw bad_input(std::string("lut: ") + e.what());
    }
}

// Where an input's rounding is measured (albedo_input_rounding: the slope over a relative step of
// 1e-6, the two values' bounds added to it), the value at the step (A and B, E and E_avg; an
// alpha's, mu's, F0's or a part's parameter's step) needs no more than 1e-5: its
// bound enters the slope as 1e-5 / (1e-6 x) and the rounding moves x by at most 3.4e-16 x (r^2
// from r), so it adds at most 7e-15 to the texel's bound, and costs a few panels, not a texel at
// 1e-10 (docs/lut.md, "How a check chooses its accuracy").
constexpr mf::split_sum_tolerance step_tolerance{1e-5, 1e-5};

// Kulla-Conty's terms of alpha alone, once per row of an E table (and at its rounded inputs'
// steps); a list's points share those of their roughness. No sets: no compensation to compute.
struct row_terms {
    std::vector<std::vector<mf::kulla_conty_terms>> sets;
    std::vector<std::size_t> of;  // roughness j -> its set
    const std::vector<mf::kulla_conty_terms>* at(std::size_t j) const { return sets.empty() ? nullptr : &sets[of[j]]; }
};

row_terms kulla_conty_terms_of_rows(lut_kind kind, const mf::composition& c, const lut_grid& g, unsigned jobs) {
    row_terms terms;
    terms.of.resize(g.roughness.size());
    if (kind != lut_kind::e || c.compensation != mf::composition::compensation_kind::kulla_conty) return terms;
    auto delta = [&](std::size_t j) { return g.alpha_delta.empty() ? 0.0 : g.alpha_delta[j]; };
    std::vector<std::size_t> first;  // a roughness of each set of terms
    std::map<std::pair<double, double>, std::size_t> set_of;  // (alpha, its delta) -> set
    for (std::size_t j = 0; j < g.roughness.size(); ++j) {
        const auto [at, added] = set_of.emplace(std::make_pair(g.alpha(j), delta(j)), first.size());
        if (added) first.push_back(j);
        terms.of[j] = at->second;
    }
    terms.sets.resize(first.size());
    normzoo::detail::parallel_for(terms.sets.size(), jobs, [&](std::size_t m) {
        terms.sets[m] = kulla_conty_row(c, g.alpha(first[m]), delta(first[m]), g.f0, g.f0_delta, g.parts);
    });
    return terms;
}

}  // namespace

exact_table exact_lut(lut_kind kind, const mf::composition& c, const lut_grid& g, unsigned jobs, const std::vector<double>* wanted) {
    if (c.transmission) {
        refuse_outside_interface(c, g.f0, 0, "lut: ");
        for (std::size_t j = 0; j < g.roughness.size(); ++j) refuse_outside_interface(c, g.f0, g.alpha(j), "lut: ");
    }
    exact_table t;
    const bool one_row = kind == lut_kind::eavg || g.points;  // texel k has roughness k
    t.width = one_row ? g.roughness.size() : g.mus.size();
    t.height = one_row ? 1 : g.roughness.size();
    t.channels = kind == lut_kind::dfg ? 2 : 1;
    t.values.resize(t.width * t.height * t.channels);
    const row_terms terms = kulla_conty_terms_of_rows(kind, c, g, jobs);
    normzoo::detail::parallel_for(t.width * t.height, jobs, [&](std::size_t k) {
        const std::size_t i = kind == lut_kind::eavg ? 0 : g.points ? k : k % t.width, j = one_row ? k : k / t.width;
        const double mu = kind == lut_kind::eavg ? 1.0 : g.mus[i], alpha = g.alpha(j);
        // the split-sum pair's step in alpha stays <= 1, where its integral over N.L (and its limit
        // at mu = 0) is taken
        const double alpha_step_upper = kind == lut_kind::dfg && alpha <= 1 ? 1.0 : std::numeric_limits<double>::infinity();
        mf::split_sum_tolerance tol;
        if (wanted) tol = {(*wanted)[k * t.channels], (*wanted)[k * t.channels + (t.channels - 1)]};
        const auto v = exact_texel(kind, c, mu, alpha, g.f0, terms.at(j), tol, tol.a);
        for (std::size_t ch = 0; ch < t.channels; ++ch) t.values[k * t.channels + ch] = v[ch];
        // listed decimals: what their rounding to double can move, channel by channel; the texel at
        // each input's step is computed once for all channels (step_tolerance)
        using texel_at = std::optional<std::array<estimate, 2>>;
        texel_at at_alpha, at_mu, at_f0;
        const double step_e = step_tolerance.a;  // E and E_avg at the steps to 1e-5 too
        auto once = [](texel_at& cache, auto compute) -> const std::array<estimate, 2>& {
            if (!cache) cache = compute();
            return *cache;
        };
        for (std::size_t ch = 0; ch < t.channels; ++ch) {
            auto& e = t.values[k * t.channels + ch];
            double moved = 0;
            if (!g.alpha_delta.empty())
                moved += normzoo::albedo_input_rounding([&](double a) {
                    return once(at_alpha, [&] { return exact_texel(kind, c, mu, a, g.f0, terms.at(j), step_tolerance, step_e); })[ch];
                }, alpha, g.alpha_delta[j], e, alpha_step_upper);
            if (!g.mu_delta.empty() && kind != lut_kind::eavg)
                moved += normzoo::albedo_input_rounding([&](double m) {
                    return once(at_mu, [&] { return exact_texel(kind, c, m, alpha, g.f0, terms.at(j), step_tolerance, step_e); })[ch];
                }, mu, g.mu_delta[i], e, 1.0);
            if (g.f0_delta > 0)
                moved += normzoo::albedo_input_rounding([&](double f) {
                    return once(at_f0, [&] { return exact_texel(kind, c, mu, alpha, f, terms.at(j), step_tolerance, step_e); })[ch];
                }, g.f0, g.f0_delta, e, 1.0);
            moved += part_inputs_rounding(c, g.parts, e, [&](const mf::composition& m) {  // Kulla-Conty's terms move too
                return exact_texel(kind, m, mu, alpha, g.f0, terms.at(j), step_tolerance, step_e)[ch];
            });
            e.abs_error += moved;
        }
    });
    return t;
}

table_output lut_records(lut_kind kind, const mf::composition& c, const lut_grid& g, const exact_table& t) {
    std::vector<record> rows;
    const auto names = lut_channels(kind);
    for (std::size_t j = 0; j < t.height; ++j)
        for (std::size_t i = 0; i < t.width; ++i) {
            const std::size_t row = kind == lut_kind::eavg || g.points ? i : j;  // a list's point i has roughness i
            record r{"lut", {}};
            r.set("kind", lut_kind_name(kind)).set("model", c.id);
            r.set("alpha", g.alpha(row));
            if (g.perceptual) r.set("r", g.roughness[row]);
            if (kind != lut_kind::eavg) r.set("mu", g.mus[i]);
            set_part_keys(r, c, g.parts, kind == lut_kind::dfg ? std::nullopt : std::optional<double>(g.f0));
            bool finite = true;
            for (std::size_t ch = 0; ch < t.channels; ++ch) {
                const auto& v = t.values[(j * t.width + i) * t.channels + ch];
                r.set(names[ch], v.value).set(t.channels > 1 ? names[ch] + "_error_estimate" : "error_estimate", v.abs_error);
                finite = finite && std::isfinite(v.value) && !std::isnan(v.abs_error);
            }
            if (!finite) r.set("pass", false);  // an integral that broke is a failure, never a value
            rows.push_back(std::move(r));
        }
    table_info info{"lut",
                             "A baked table, exact: the split-sum pair (A, B), E(mu, alpha) or E_avg(alpha) of a "
                             "composition (docs/lut.md)",
                             {"each value by microfacet/albedo.hpp (split_sum_to.hpp, multiple_scattering.hpp; rough_dielectric.hpp for D/G/F/transmission) at tolerance "
                              "1e-10 absolute; *error_estimate: its bound",
                              "texels: rows are roughness (r, alpha = r^2, or alpha), columns mu; texel centres (i + 0.5)/N"},
                             {"alpha", "mu", names[0], names.size() > 1 ? names[1] : "error_estimate"},
                             {names[0]}};
    return {info, std::move(rows), "", ""};
}

lut_image lut_image_of(const exact_table& t) {
    lut_image im{t.width, t.height, t.channels, {}};
    for (const auto& v : t.values) im.data.push_back(v.value);
    return im;
}

}  // namespace verify
