// One E(mu, alpha) point at 1e-10, over a grid: the time per point of directional_albedo
// (microfacet/albedo.hpp, what `verify energy` and `verify lut` run: the integral over N.L for
// F = 1 with GGX or Beckmann and Schlick's F with GGX, microfacet/azimuthal_albedo.hpp, else the
// integral in the distribution's own variable) against the generic lobe-centred integral of albedo.hpp at the same tolerance, in the
// same run, with the evaluations each took. Six compositions (the exact Smith G of Beckmann and
// GGX with F = 1 and Schlick, Kelemen's G on Blinn-Phong, Schlick-GGX), alpha = 1e-3 to 1 and
// mu = 1e-4 to 1, eight and seven values evenly spaced in log. Writes Markdown to standard output
// (docs/microfacet.md, "The albedo in the distribution's own variable"); with NORMZOO_BENCH_POINTS
// set, every point's figures to standard error as well. Release build, one core.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/composition.hpp>

namespace mf = normzoo::microfacet;
using clock_type = std::chrono::steady_clock;

namespace {

constexpr double tolerance = 1e-10, f0 = 0.04, target_us = 50;
constexpr int alphas = 8, mus = 7, calls = 5;
const char* const compositions[] = {"ggx/smith-height-correlated/one",      "ggx/smith-separable/schlick",
                                    "beckmann/smith-height-correlated/one", "beckmann/smith-separable/schlick",
                                    "blinn-phong/kelemen/schlick",          "ggx/schlick-ggx/schlick"};

// The median over `calls` calls after one to warm up, in microseconds, and the last result.
template <class F>
double median_us(const F& f, normzoo::quadrature::estimate<double>& out) {
    out = f();
    std::vector<double> t;
    for (int i = 0; i < calls; ++i) {
        const auto t0 = clock_type::now();
        out = f();
        t.push_back(std::chrono::duration<double, std::micro>(clock_type::now() - t0).count());
    }
    std::nth_element(t.begin(), t.begin() + calls / 2, t.end());
    return t[calls / 2];
}

double quantile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

struct point {
    double alpha, mu, fast_us, generic_us, fast_evaluations, generic_evaluations;
};

}  // namespace

int main() {
    const normzoo::albedo_settings settings{tolerance, 400};
    std::vector<std::vector<point>> rows;
    std::size_t over_tolerance = 0, disagree = 0;
    for (const char* id : compositions) {
        const mf::composition c = mf::composition::parse(id);
        std::vector<point> row;
        for (int i = 0; i < alphas; ++i)
            for (int j = 0; j < mus; ++j) {
                const double alpha = std::pow(10.0, -3.0 + 3.0 * i / (alphas - 1));
                const double mu = std::pow(10.0, -4.0 + 4.0 * j / (mus - 1));
                normzoo::quadrature::estimate<double> fast, generic;
                point p{};
                p.alpha = alpha, p.mu = mu;
                p.fast_us = median_us([&] { return mf::directional_albedo(c, mu, alpha, f0, settings); }, fast);
                p.generic_us = median_us(
                    [&] {
                        return normzoo::albedo<mf::composition>(mf::angle_of_cosine(mu), mf::composition::node_exponent(alpha), f0,
                                                                settings, alpha, c);
                    },
                    generic);
                p.fast_evaluations = static_cast<double>(fast.evaluations);
                p.generic_evaluations = static_cast<double>(generic.evaluations);
                if (!(fast.abs_error <= tolerance)) ++over_tolerance;
                // two independent integrals: their difference is within the sum of their bounds
                if (!(std::abs(fast.value - generic.value) <= fast.abs_error + generic.abs_error)) ++disagree;
                row.push_back(p);
            }
        rows.push_back(row);
    }

    auto column = [](const std::vector<point>& ps, double point::*m) {
        std::vector<double> v;
        for (const auto& p : ps) v.push_back(p.*m);
        return v;
    };
    auto ratios = [](const std::vector<point>& ps) {
        std::vector<double> v;
        for (const auto& p : ps) v.push_back(p.generic_us / p.fast_us);
        return v;
    };
    std::vector<point> all;
    for (const auto& r : rows) all.insert(all.end(), r.begin(), r.end());

    std::printf("# One microfacet albedo point at 1e-10: normzoo's integrals against the generic one\n\n");
    std::printf("Produced by `bench/run` (`normzoo-bench-microfacet`), Release build, one core, one process; "
                "docs/microfacet.md, \"The albedo in the distribution's own variable\", \"F = 1: D over L's azimuth in closed form\" "
                "and \"Schlick's F over L's azimuth\".\n\n");
    std::printf("E(mu, alpha) at %zu points: %zu compositions, %d alpha from 1e-3 to 1 and %d mu from 1e-4 to 1 (evenly "
                "spaced in log), F0 = %g, tolerance %g. Each time is the median of %d calls after a warm-up; the peer is "
                "the generic lobe-centred integral (albedo.hpp) at the same tolerance, in the same run.\n\n",
                all.size(), rows.size(), alphas, mus, f0, tolerance, calls);
    std::printf("| composition | median (us) | 90th percentile (us) | slowest (us) | evaluations (median) | generic: median (us) | "
                "generic: evaluations (median) | ratio (median; least, most) |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    auto line = [&](const std::string& name, const std::vector<point>& ps) {
        const auto fast = column(ps, &point::fast_us), r = ratios(ps);
        std::printf("| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.2fx (%.2fx, %.2fx) |\n", name.c_str(), quantile(fast, 0.5),
                    quantile(fast, 0.9), quantile(fast, 1), quantile(column(ps, &point::fast_evaluations), 0.5),
                    quantile(column(ps, &point::generic_us), 0.5), quantile(column(ps, &point::generic_evaluations), 0.5),
                    quantile(r, 0.5), quantile(r, 0), quantile(r, 1));
    };
    for (std::size_t k = 0; k < rows.size(); ++k) line("`" + std::string(compositions[k]) + "`", rows[k]);
    line("all", all);
    const double median = quantile(column(all, &point::fast_us), 0.5);
    std::printf("\nTarget: a median of %g us per point. Measured: %.0f us, %.1fx the target (%s).", target_us, median,
                median / target_us, median <= target_us ? "met" : "not met");
    // the rows of the integral over N.L (F = 1 with GGX or Beckmann, Schlick's F with GGX)
    std::vector<point> closed;
    std::string closed_ids;
    for (std::size_t k = 0; k < rows.size(); ++k)
        if (mf::detail::in_closed_azimuth(mf::composition::parse(compositions[k]), 1.0)) {
            closed.insert(closed.end(), rows[k].begin(), rows[k].end());
            closed_ids += (closed_ids.empty() ? "`" : ", `") + std::string(compositions[k]) + "`";
        }
    if (!closed.empty()) {
        const double m = quantile(column(closed, &point::fast_us), 0.5);
        std::printf(" Where the albedo is the integral over N.L (%s): %.0f us (%s).", closed_ids.c_str(), m,
                    m <= target_us ? "met" : "not met");
    }
    std::printf("\n");
    std::printf("Bounds above the tolerance: %zu of %zu points. The two integrals differing by more than the sum of their "
                "bounds: %zu.\n",
                over_tolerance, all.size(), disagree);
    if (std::getenv("NORMZOO_BENCH_POINTS"))
        for (std::size_t k = 0; k < rows.size(); ++k)
            for (const auto& p : rows[k])
                std::fprintf(stderr, "%s %g %g %g %g %g %g\n", compositions[k], p.alpha, p.mu, p.fast_us, p.generic_us, p.fast_evaluations, p.generic_evaluations);
    return over_tolerance == 0 && disagree == 0 ? 0 : 1;
}
