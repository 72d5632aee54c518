// --detect (lut_detect.hpp): the candidates enumerated, their points collected once, the exact
// values computed once per distinct (mu, alpha) and model, then every candidate's largest error
// on the subsample.
#include "lut_detect.hpp"

#include "args.hpp"
#include "lut_formats/read.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace verify {

namespace {

// Where the texels sit: the axes, their origins and the spacing.
struct geometry {
    lut_axis rows, cols;
    lut_origin row0, col0;
    lut_spacing grid;
};

// What the stored values are: the channels in file order and their encoding.
struct reading {
    std::vector<std::string> channels;
    lut_encoding encoding;
};

// The values of a key tried: the start's where it is fixed, else all (the default first).
template <class T>
std::vector<T> tried(const layout_search& s, const char* key, T start, std::vector<T> all) {
    if (s.fixed.count(key)) return {start};
    return all;
}

std::vector<geometry> geometries(const layout_search& s, std::size_t width, std::size_t height) {
    const bool eavg = s.kind == lut_kind::eavg;
    const auto ends = std::vector<lut_origin>{lut_origin::low, lut_origin::high};
    std::vector<geometry> out;
    for (bool rough_rows : eavg ? std::vector<bool>{true} : std::vector<bool>{true, false})
        for (lut_axis rough : {lut_axis::r, lut_axis::alpha})
            for (lut_axis mu : eavg ? std::vector<lut_axis>{lut_axis::mu} : std::vector<lut_axis>{lut_axis::mu, lut_axis::sqrt_mu}) {
                const lut_axis rows = rough_rows ? rough : mu, cols = rough_rows ? mu : rough;
                if ((s.fixed.count("rows") && rows != s.start.rows) || (!eavg && s.fixed.count("cols") && cols != s.start.cols))
                    continue;
                for (lut_origin row0 : tried(s, "row0", s.start.row0, ends))
                    for (lut_origin col0 : eavg ? std::vector<lut_origin>{lut_origin::low} : tried(s, "col0", s.start.col0, ends))
                        for (lut_spacing grid : tried(s, "grid", s.start.grid, {lut_spacing::centres, lut_spacing::edges, lut_spacing::filament})) {
                            if (grid == lut_spacing::edges && (height < 2 || (!eavg && width < 2))) continue;
                            out.push_back({rows, cols, row0, col0, grid});
                        }
            }
    return out;
}

// The readings the file can hold: sRGB where every value is in [0, 1], RGBD with a fourth channel;
// sRGB alone where the file's format is sRGB-encoded.
std::vector<reading> readings(const layout_search& s, const decoded_lut& d) {
    std::vector<std::vector<std::string>> lists = {layout_channels(s.start, s.kind)};
    if (!s.fixed.count("channels") && s.kind == lut_kind::dfg) lists = {{"A", "B"}, {"B", "A+B"}};
    // an E table alone, or beside a split-sum pair (Filament's cloth and Babylon's sheen channel: the
    // third); or its complement 1 - E (openpbr-bsdf's)
    if (!s.fixed.count("channels") && s.kind == lut_kind::e) lists = {{"E"}, {"-", "E"}, {"-", "-", "E"}, {"1-E"}};
    if (!s.fixed.count("channels") && s.kind == lut_kind::eavg) lists = {{"E_avg"}, {"1-E_avg"}};
    const bool unit = std::all_of(d.image.data.begin(), d.image.data.end(), [](double v) { return v >= 0 && v <= 1; });
    std::vector<lut_encoding> encodings = {s.start.encoding};
    if (!s.fixed.count("encoding") && sampled_as_srgb(d)) {
        encodings = {lut_encoding::srgb};  // the file says so, and a sampler decodes it
    } else if (!s.fixed.count("encoding")) {
        encodings = {lut_encoding::linear};
        if (unit) encodings.push_back(lut_encoding::srgb);
        if (unit && d.image.channels >= 4) encodings.push_back(lut_encoding::rgbd);
    }
    std::vector<reading> out;
    for (const auto& e : encodings)
        for (const auto& l : lists)
            if ((e == lut_encoding::rgbd ? 4 : l.size()) <= d.image.channels && (e != lut_encoding::rgbd || l.size() <= 3))
                out.push_back({l, e});
    return out;
}

// About s evenly spaced indices of n, both ends included, symmetric (i and n - 1 - i), so that a
// flipped axis meets the same coordinates and shares their exact values.
std::vector<std::size_t> subsample(std::size_t n, std::size_t s) {
    s = std::min(n, s);
    if (s <= 1) return {0};
    std::vector<std::size_t> idx(s);
    for (std::size_t k = 0; k < (s + 1) / 2; ++k) {
        idx[k] = std::size_t(std::floor(double(k) * double(n - 1) / double(s - 1) + 0.5));
        idx[s - 1 - k] = n - 1 - idx[k];
    }
    // and the texels next to each end: where a grid's ends (edges or centres) differ most, next to
    // mu = 0 at small r, which a large table's noise would otherwise hide (docs/lut.md, "Detecting a layout")
    if (n >= 4) idx.push_back(1), idx.push_back(n - 2);
    std::sort(idx.begin(), idx.end());
    idx.erase(std::unique(idx.begin(), idx.end()), idx.end());
    return idx;
}

// The distinct points of the candidates, and per geometry the point of each subsample texel (or
// none, where the exact values do not reach).
struct point_set {
    std::map<std::pair<double, double>, std::size_t> index;  // (mu, alpha) -> point
    lut_grid grid;
    std::vector<std::vector<long>> of;  // [geometry][subsample texel] -> point, -1: not compared

    long add(double mu, double alpha, bool eavg) {
        if (!comparable_point(mu, alpha)) return -1;
        const auto [at, added] = index.emplace(std::make_pair(mu, alpha), grid.roughness.size());
        if (added) {
            grid.roughness.push_back(alpha);
            if (!eavg) grid.mus.push_back(mu);
        }
        return long(at->second);
    }
};

point_set points_of(const std::vector<geometry>& gs, const std::vector<std::size_t>& texels, const decoded_lut& d, lut_kind kind) {
    const std::size_t w = d.image.width, h = d.image.height;
    const bool eavg = kind == lut_kind::eavg;
    point_set p;
    p.grid.points = true, p.grid.perceptual = false;
    for (const auto& g : gs) {
        std::vector<long> of;
        for (std::size_t k : texels) {
            const double ur = axis_coordinate(g.grid, is_roughness(g.rows) || eavg, g.row0, k / w, h);
            const double uc = eavg ? 0 : axis_coordinate(g.grid, is_roughness(g.cols), g.col0, k % w, w);
            const bool rough_rows = is_roughness(g.rows) || eavg;
            const double mu = eavg ? 1 : mu_of_coordinate(rough_rows ? g.cols : g.rows, rough_rows ? uc : ur);
            of.push_back(p.add(mu, alpha_of_coordinate(rough_rows ? g.rows : g.cols, rough_rows ? ur : uc), eavg));
        }
        p.of.push_back(std::move(of));
    }
    return p;
}

// The largest error of one candidate over the subsample: stored[t * channels + c] against the
// exact value of channel c at the texel's point.
double largest_error(const std::vector<long>& of, const std::vector<double>& stored, const std::vector<std::string>& names,
                     const exact_table& exact) {
    double worst = -1;
    for (std::size_t t = 0; t < of.size(); ++t) {
        if (of[t] < 0) continue;
        for (std::size_t c = 0; c < names.size(); ++c) {
            const double e = std::abs(stored[t * names.size() + c] - exact_channel(exact, names[c], std::size_t(of[t])).value);
            worst = std::isnan(e) ? std::numeric_limits<double>::infinity() : std::max(worst, e);
        }
    }
    return worst < 0 ? std::numeric_limits<double>::infinity() : worst;  // nothing compared: no fit
}

// The stored values of the subsample's texels as a reading decodes them, the "-" channels left out.
std::vector<double> decoded(const decoded_lut& d, const reading& r, const std::vector<std::size_t>& texels, std::vector<std::string>& names) {
    names.clear();
    std::vector<double> out;
    for (const auto& c : r.channels)
        if (c != "-") names.push_back(c);
    for (std::size_t k : texels)
        for (std::size_t c = 0; c < r.channels.size(); ++c)
            if (r.channels[c] != "-") out.push_back(decode_texel(d, r.encoding, k, c).value);
    return out;
}

}  // namespace

std::vector<std::string> baked_models() {
    return {"ggx/smith-height-correlated/one", "ggx/smith-separable/one", "ggx/schlick-ggx/one", "ggx/schlick-ggx-remapped/one"};
}

layout_ranking rank_layouts(const decoded_lut& d, const layout_search& s) {
    const std::size_t w = d.image.width, h = d.image.height;
    std::vector<std::size_t> texels;
    for (std::size_t j : subsample(h, s.kind == lut_kind::eavg ? 16 : 8))
        for (std::size_t i : subsample(w, 8)) texels.push_back(j * w + i);
    const std::vector<geometry> gs = geometries(s, w, h);
    const point_set points = points_of(gs, texels, d, s.kind);
    std::vector<exact_table> exact;  // per model, at every point
    for (const auto& m : s.models) exact.push_back(exact_lut(s.kind, composition_of(m, s.parts, "lut: --model: "), points.grid, s.jobs));
    layout_ranking out;
    out.texels = texels.size();
    std::vector<std::string> names;
    for (const auto& r : readings(s, d)) {
        const std::vector<double> stored = decoded(d, r, texels, names);
        for (std::size_t g = 0; g < gs.size(); ++g)
            for (std::size_t m = 0; m < s.models.size(); ++m) {
                layout_candidate c{s.start, s.models[m], largest_error(points.of[g], stored, names, exact[m])};
                c.layout.rows = gs[g].rows, c.layout.cols = gs[g].cols, c.layout.row0 = gs[g].row0, c.layout.col0 = gs[g].col0;
                c.layout.grid = gs[g].grid, c.layout.channels = r.channels, c.layout.encoding = r.encoding;
                out.ranked.push_back(std::move(c));
            }
    }
    std::stable_sort(out.ranked.begin(), out.ranked.end(),
                     [](const layout_candidate& a, const layout_candidate& b) { return a.max_abs_error < b.max_abs_error; });
    return out;
}

detected_table detect_table(const std::string& path, const lut_reading& reading, lut_kind kind, layout_search s) {
    std::vector<lut_encoding> hex_readings;
    if (!reading.stated.count("encoding") && read_lut_file(path, {"", reading.layout.width, reading.layout.height}).encoding ==
                                                 value_encoding::hex_integer)
        hex_readings = {lut_encoding::half, lut_encoding::unorm16, lut_encoding::unorm8};
    if (hex_readings.empty()) {
        decoded_lut image = shaped_lut(read_laid_out(path, reading, kind), reading.layout, kind, path);
        layout_ranking ranking = rank_layouts(image, s);
        return {std::move(image), std::move(ranking)};
    }
    // each reading of the integers ranked as if --layout gave it; the best image kept
    std::optional<detected_table> best;
    std::vector<layout_candidate> all;
    for (const lut_encoding e : hex_readings) {
        lut_reading as = reading;
        as.layout.encoding = s.start.encoding = e;
        as.stated.insert("encoding"), s.fixed.insert("encoding");
        std::optional<decoded_lut> read;
        try {
            read = shaped_lut(read_laid_out(path, as, kind), as.layout, kind, path);
        } catch (const bad_input&) {  // integers that reading cannot hold (unorm8 above 255): not it
            continue;
        }
        decoded_lut image = std::move(*read);
        layout_ranking ranking = rank_layouts(image, s);
        all.insert(all.end(), ranking.ranked.begin(), ranking.ranked.end());
        if (!ranking.ranked.empty() && (!best || ranking.ranked.front().max_abs_error < best->ranking.ranked.front().max_abs_error))
            best = detected_table{std::move(image), std::move(ranking)};
    }
    if (!best) return {shaped_lut(read_laid_out(path, reading, kind), reading.layout, kind, path), {}};
    std::stable_sort(all.begin(), all.end(), [](const layout_candidate& a, const layout_candidate& b) { return a.max_abs_error < b.max_abs_error; });
    best->ranking.ranked = std::move(all);
    return std::move(*best);
}

}  // namespace verify
