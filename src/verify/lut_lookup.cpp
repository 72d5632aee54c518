// The error of a shader's bilinear lookup of a checked table (lut_lookup.hpp; docs/lut.md, "The
// lookup's error"): the fine points, the exact values there, and the lookup against them.
#include "lut_lookup.hpp"

#include <normzoo/microfacet/albedo.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace verify {

namespace mf = normzoo::microfacet;

std::vector<double> wanted_tolerances(const read_table& t, lut_kind kind, std::optional<double> tolerance,
                                      const std::vector<std::size_t>& texels) {
    const std::size_t n = t.channels.size(), per = kind == lut_kind::dfg ? 2 : 1;
    std::vector<double> wanted(per * texels.size(), std::numeric_limits<double>::infinity());
    std::vector<char> reads_a(n), reads_b(n), sum(n);  // per channel, once: not a text per texel
    for (std::size_t ch = 0; ch < n; ++ch)
        reads_a[ch] = t.channels[ch] != "B", reads_b[ch] = t.channels[ch] != "A", sum[ch] = t.channels[ch] == "A+B";
    for (std::size_t p = 0; p < texels.size(); ++p)
        for (std::size_t ch = 0; ch < n; ++ch) {
            const double tol = tolerance ? *tolerance : t.tolerance[texels[p] * n + ch];
            const double part = std::isfinite(tol) ? tol / 100 : 1e-10;  // a value not finite fails at any accuracy
            if (per == 1) {  // E or E_avg: the one channel
                wanted[p] = std::min(wanted[p], part);
                continue;
            }
            if (reads_a[ch]) wanted[2 * p] = std::min(wanted[2 * p], sum[ch] ? part / 2 : part);
            if (reads_b[ch]) wanted[2 * p + 1] = std::min(wanted[2 * p + 1], sum[ch] ? part / 2 : part);
        }
    for (double& w : wanted) w = std::max(1e-10, w);
    return wanted;
}

namespace {

// One axis as a shader samples it: its texels' coordinates ascending, and the row or column each
// is stored at.
struct sampled_axis {
    lut_axis axis = lut_axis::mu;
    std::vector<double> coord;
    std::vector<std::size_t> stored;
};

sampled_axis sampled(const std::vector<double>& coords, lut_axis a) {
    sampled_axis s;
    s.axis = a;
    s.stored.resize(coords.size());
    std::iota(s.stored.begin(), s.stored.end(), std::size_t(0));
    std::stable_sort(s.stored.begin(), s.stored.end(), [&](std::size_t x, std::size_t y) { return coords[x] < coords[y]; });
    for (std::size_t k : s.stored) s.coord.push_back(coords[k]);
    return s;
}

// Where a coordinate falls (span): the two texels (stored rows or columns) it lies between and the
// weight of the second; held at the outermost texel beyond it (clamp to edge).
struct span {
    std::size_t lo = 0, hi = 0;
    double w = 0;
};

span along(const sampled_axis& a, double u) {
    const auto& c = a.coord;
    if (u <= c.front()) return {a.stored.front(), a.stored.front(), 0};
    if (u >= c.back()) return {a.stored.back(), a.stored.back(), 0};
    const std::size_t k = std::size_t(std::upper_bound(c.begin(), c.end(), u) - c.begin()) - 1;
    return {a.stored[k], a.stored[k + 1], (u - c[k]) / (c[k + 1] - c[k])};
}

// The table's axes as a shader samples them: x along mu (one texel for E_avg), y along the
// roughness, and where texel (x, y) is stored.
struct table_axes {
    sampled_axis x, y;
    bool rough_rows;  // the rows index the roughness
    std::size_t width;
    std::size_t texel(std::size_t xs, std::size_t ys) const { return rough_rows ? ys * width + xs : xs * width + ys; }
};

table_axes axes_of(const read_table& t, lut_kind kind) {
    const bool eavg = kind == lut_kind::eavg, rough_rows = eavg || is_roughness(t.row_axis);
    table_axes a{{}, sampled(rough_rows ? t.row_coord : t.col_coord, rough_rows ? t.row_axis : t.col_axis), rough_rows, t.width};
    a.x = eavg ? sampled({1.0}, lut_axis::mu) : sampled(rough_rows ? t.col_coord : t.row_coord, rough_rows ? t.col_axis : t.row_axis);
    return a;
}

// A coordinate measured along an axis: a texel's own (centre), in the strided subset (kept), or
// in the first or last cell, at an end texel or in a band (boundary: crossed with every position
// of the other axis).
struct position {
    double u;
    bool centre, kept, boundary, band = false;
};

std::vector<position> positions_of(const sampled_axis& a) {
    const auto& c = a.coord;
    const std::size_t n = c.size(), s = n > 257 ? (n - 1 + 99) / 100 : 1;
    std::vector<position> p;
    if (c.front() > 0) p.push_back({0, false, true, true, true}), p.push_back({c.front() / 2, false, true, true, true});
    for (std::size_t k = 0; k < n; ++k) {
        p.push_back({c[k], true, k % s == 0 || k + 1 == n, k == 0 || k + 1 == n});
        if (k + 1 < n) p.push_back({(c[k] + c[k + 1]) / 2, false, k % s == 0 || k + 2 == n, k == 0 || k + 2 == n});
    }
    if (c.back() < 1) p.push_back({(c.back() + 1) / 2, false, true, true, true}), p.push_back({1, false, true, true, true});
    return p;
}

// The value a mu or roughness axis takes at a coordinate, and the least coordinate whose value the
// exact values take (mu, alpha >= 1e-8: microfacet/albedo.hpp).
double value_at(lut_axis a, double u) { return is_roughness(a) ? alpha_of_coordinate(a, u) : mu_of_coordinate(a, u); }
double least_coordinate(lut_axis a) {
    double u = a == lut_axis::r || a == lut_axis::sqrt_mu ? 1e-4 : 1e-8;
    while (value_at(a, u) < 1e-8) u = std::nextafter(u, 1.0);
    return u;
}

// A point of the fine grid: its mu and roughness (r or alpha as the table indexes it), and the
// four texels the lookup weighs (x along mu, y along the roughness).
struct fine_point {
    double mu, roughness, alpha;
    span x, y;
    bool between;  // between the outermost texels along both axes (in no band)
};

struct fine_grid {
    std::vector<fine_point> points;
    std::vector<std::size_t> nearest;  // the texel below each, whose tolerance it is computed to
};

fine_grid fine_points(const table_axes& axes, lut_kind kind, const mf::composition& c) {
    const sampled_axis &ax = axes.x, &ay = axes.y;
    // E_avg's one mu: a texel's own, so that its points are the roughness axis' between the texels
    const std::vector<position> px = kind == lut_kind::eavg ? std::vector<position>{{1, true, true, true}} : positions_of(ax);
    const std::vector<position> py = positions_of(ay);
    // where the split-sum pair has its limits (docs/lut.md, "Edges"): mu = 0 and alpha = 0 are measured
    const bool dfg = kind == lut_kind::dfg;
    const bool limit_mu0 = dfg && pair_has_limit(c, 0, 0.5), limit_alpha0 = dfg && pair_has_limit(c, 0.5, 0);
    auto computable = [&](double mu, double alpha) {
        return comparable_point(mu, alpha) || (mu == 0 && alpha >= mf::smallest_alpha && limit_mu0) ||
               (alpha == 0 && mu >= mf::smallest_mu && limit_alpha0);
    };
    fine_grid g;
    for (const auto& q : py)
        for (const auto& p : px) {
            if ((p.centre && q.centre) || !((p.kept && q.kept) || p.boundary || q.boundary)) continue;
            double ux = p.u, uy = q.u;  // E_avg's one mu is 1, never moved
            // an edge without a limit: the least mu, then alpha, the exact values take
            if (!computable(value_at(ax.axis, ux), value_at(ay.axis, uy)) && value_at(ax.axis, ux) < mf::smallest_mu)
                ux = least_coordinate(ax.axis);
            if (!computable(value_at(ax.axis, ux), value_at(ay.axis, uy))) uy = std::max(uy, least_coordinate(ay.axis));
            const fine_point f{value_at(ax.axis, ux), uy, value_at(ay.axis, uy), along(ax, ux), along(ay, uy), !p.band && !q.band};
            g.nearest.push_back(axes.texel(f.x.lo, f.y.lo));
            g.points.push_back(f);
        }
    return g;
}

// The lookup of channel ch at f: bilinear in the four texels' stored values.
double looked_up(const read_table& t, const table_axes& axes, const fine_point& f, std::size_t ch) {
    const std::size_t n = t.channels.size();
    auto v = [&](std::size_t xs, std::size_t ys) { return t.values[axes.texel(xs, ys) * n + ch]; };
    const double lo = (1 - f.x.w) * v(f.x.lo, f.y.lo) + f.x.w * v(f.x.hi, f.y.lo);
    const double hi = (1 - f.x.w) * v(f.x.lo, f.y.hi) + f.x.w * v(f.x.hi, f.y.hi);
    return (1 - f.y.w) * lo + f.y.w * hi;
}

void keep_worst(lookup_worst& w, double looked, double exact, const fine_point& f) {
    double err = std::abs(looked - exact);
    if (std::isnan(err) || !std::isfinite(looked)) err = std::numeric_limits<double>::infinity();  // a texel a baker broke
    if (f.between) w.between = std::max(w.between, err);
    if (err > w.error) w = {err, f.mu, f.roughness, f.alpha, w.between};
}

}  // namespace

lookup_errors measure_lookup(const read_table& t, lut_kind kind, const mf::composition& c, std::optional<double> tolerance,
                             unsigned jobs) {
    const table_axes axes = axes_of(t, kind);
    const fine_grid fine = fine_points(axes, kind, c);
    lut_grid g = t.points;
    g.mus.clear(), g.roughness.clear(), g.mu_delta.clear(), g.alpha_delta.clear();
    for (const auto& f : fine.points) {
        if (kind != lut_kind::eavg) g.mus.push_back(f.mu);
        g.roughness.push_back(f.roughness);
    }
    // each value as the check computes its texels: to a hundredth of the tolerance of the texel
    // below it
    const std::vector<double> wanted = wanted_tolerances(t, kind, tolerance, fine.nearest);
    const exact_table exact = exact_lut(kind, c, g, jobs, &wanted);
    lookup_errors r;
    r.points = fine.points.size();
    r.channels.resize(t.channels.size());
    if (kind == lut_kind::dfg) r.dielectric = lookup_worst{}, r.metal = lookup_worst{};
    const std::size_t n = t.channels.size();
    auto at = [&](const char* name) { return std::size_t(std::find(t.channels.begin(), t.channels.end(), name) - t.channels.begin()); };
    const std::size_t ia = at("A"), ib = at("B"), is = at("A+B");
    std::vector<double> v(n);
    for (std::size_t p = 0; p < fine.points.size(); ++p) {
        const fine_point& f = fine.points[p];
        for (std::size_t ch = 0; ch < n; ++ch) {
            v[ch] = looked_up(t, axes, f, ch);
            keep_worst(r.channels[ch], v[ch], exact_channel(exact, t.channels[ch], p).value, f);
        }
        if (kind != lut_kind::dfg) continue;
        // E = F0 A + B from the channels looked up (linear: the same as E's own lookup)
        const double a = ia < n ? v[ia] : v[is] - v[ib], b = ib < n ? v[ib] : v[is] - v[ia];
        const double ea = exact.values[2 * p].value, eb = exact.values[2 * p + 1].value;
        keep_worst(*r.dielectric, 0.04 * a + b, 0.04 * ea + eb, f);
        keep_worst(*r.metal, a + b, ea + eb, f);
    }
    return r;
}

namespace {

// Each stored row or column's place in ascending order, and the coordinate its cell is drawn at:
// texel k (ascending) at c_0 + k (c_1 - c_0), the grid's step from its first texel (regular where
// a grid is: centres, edges; filament's clamped last texel at its unclamped place).
struct drawn_axis {
    std::vector<std::size_t> rank;  // stored -> ascending
    std::vector<double> cells;      // each cell's coordinate
};

drawn_axis drawn(const sampled_axis& a, std::size_t block) {
    drawn_axis d;
    const std::size_t n = a.coord.size();
    d.rank.resize(n);
    for (std::size_t k = 0; k < n; ++k) d.rank[a.stored[k]] = k;
    const double step = n > 1 ? a.coord[1] - a.coord[0] : 0;
    for (std::size_t first = 0; first < n; first += block) {
        const std::size_t last = std::min(n, first + block) - 1;
        d.cells.push_back(a.coord[0] + step * double(first + last) / 2);
    }
    return d;
}

}  // namespace

lut_error_map error_map_of(const read_table& t, const exact_table& exact, lut_kind kind, std::optional<double> tolerance) {
    const table_axes axes = axes_of(t, kind);
    const sampled_axis &ax = axes.x, &ay = axes.y;
    lut_error_map m;
    m.mu_axis = axis_name(ax.axis), m.roughness_axis = axis_name(ay.axis);
    m.block = (std::max(ax.coord.size(), ay.coord.size()) + 255) / 256;
    const drawn_axis dx = drawn(ax, m.block), dy = drawn(ay, m.block);
    m.xs = dx.cells, m.ys = dy.cells;
    m.names = m.checked = t.channels;
    if (kind == lut_kind::dfg) m.names.push_back("E at F0 = 0.04");
    const std::size_t cells = m.xs.size() * m.ys.size(), n = t.channels.size();
    m.errors.assign(m.names.size(), std::vector<double>(cells, std::numeric_limits<double>::quiet_NaN()));
    m.above.assign(cells, 0);
    auto at = [&](const char* name) { return std::size_t(std::find(t.channels.begin(), t.channels.end(), name) - t.channels.begin()); };
    const std::size_t ia = at("A"), ib = at("B"), is = at("A+B");
    auto worse = [](double& cell, double err) {
        if (std::isnan(err)) err = std::numeric_limits<double>::infinity();  // a texel a baker broke
        if (std::isnan(cell) || err > cell) cell = err;
    };
    for (std::size_t p = 0; p < t.texel.size(); ++p) {
        const std::size_t k = t.texel[p], row = k / t.width, col = k % t.width;
        const std::size_t xs = axes.rough_rows ? col : row, ys = axes.rough_rows ? row : col;
        const std::size_t cell = dy.rank[ys] / m.block * m.xs.size() + dx.rank[xs] / m.block;
        const double* v = &t.values[k * n];
        for (std::size_t ch = 0; ch < n; ++ch) {
            const auto truth = exact_channel(exact, t.channels[ch], p);
            const double err = std::abs(v[ch] - truth.value);
            worse(m.errors[ch][cell], err);
            const double tol = (tolerance ? *tolerance : t.tolerance[k * n + ch]) + truth.abs_error;
            if (!std::isfinite(v[ch]) || !(err <= tol)) m.above[cell] |= 1u << ch;
        }
        if (kind != lut_kind::dfg) continue;
        const double a = ia < n ? v[ia] : v[is] - v[ib], b = ib < n ? v[ib] : v[is] - v[ia];
        worse(m.errors[n][cell], std::abs(0.04 * a + b - (0.04 * exact.values[2 * p].value + exact.values[2 * p + 1].value)));
    }
    return m;
}

}  // namespace verify
