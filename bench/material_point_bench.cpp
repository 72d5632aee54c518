// The time of one material point (docs/materials.md, "The albedo and its bound"): the glTF
// material's albedo with V fixed at 1e-10, whole (all its lobes and channels, albedo_of) and each
// lobe alone (its composition's two albedos), and node by node (albedo_by_nodes), the median of
// 15 runs on one core, over roughness and incidence. One JSON line per point. With the argument
// `peer`: the points bench/scipy_material.py takes, whole, with their albedos; `materials`: each
// material and compensation the command takes, its median and largest whole point over the grid.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <normzoo/material/albedo.hpp>
#include <normzoo/material/registry.hpp>

namespace {

namespace mat = normzoo::material;

// The grid every timing goes over: 25 points, roughness by mu.
constexpr double roughnesses[] = {0.01, 0.1, 0.3, 0.5, 1.0};
constexpr double mus[] = {1e-4, 0.01, 0.1, 0.5, 1.0};

template <class F>
double median_us(const F& f, int runs = 15) {
    std::vector<double> t;
    for (int i = 0; i < runs; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        t.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

}  // namespace

// The peer's points (bench/scipy_material.py, the same order): baseColor, metallic, roughness,
// mu, masking.
int peer_points() {
    struct point {
        mat::rgb color;
        double metallic, roughness, mu;
        mat::smith_form masking;
    };
    const point points[] = {{{0.8, 0.5, 0.2}, 0.5, 0.5, 0.5, mat::smith_form::separable},
                            {{1, 1, 1}, 1, 1, 1, mat::smith_form::height_correlated},
                            {{0.9, 0.9, 0.9}, 0, 0.3, 0.8, mat::smith_form::separable},
                            {{0.5, 0.5, 0.5}, 1, 0.1, 0.3, mat::smith_form::height_correlated}};
    volatile double sink = 0;
    for (const point& p : points) {
        mat::gltf m;
        m.in.baseColor = p.color, m.in.metallic = p.metallic, m.in.roughness = p.roughness, m.in.masking = p.masking;
        const double us = median_us([&] { sink = sink + mat::albedo_of(m, p.mu).whole.value[0]; });
        const auto a = mat::albedo_of(m, p.mu);
        std::printf("{\"whole_us\":%.1f,\"albedo_rgb\":[%.17g,%.17g,%.17g],\"error\":[%.3g,%.3g,%.3g]}\n", us, a.whole.value[0],
                    a.whole.value[1], a.whole.value[2], a.whole.abs_error[0], a.whole.abs_error[1], a.whole.abs_error[2]);
    }
    return 0;
}

// A material configuration timed over the grid: its name as the command takes it, and the
// material at a roughness (the inputs that do not move held).
template <class M>
struct configuration {
    const char* name;
    mat::compensation_kind compensation;
    M (*at)(double roughness);
    int runs = 15;  // per point (a sheen over a film takes about a second: one)
};

// The first point is also timed alone before the grid (`first_us`): under a sheen it builds the
// curve of E for the sheen's alpha (material/sheen_curve.hpp), and under Kulla-Conty its E_avg and
// lost energy, which the other points at that alpha read. A point's median of repeated runs reads
// them too, so the grid is also swept once, each point once, on a new thread, which has kept
// nothing (`sweep_us`, the mean a point): what a sweep over mu at five alphas pays.
template <class M>
void time_configuration(const configuration<M>& c) {
    volatile double sink = 0;
    std::vector<double> us;
    const M first = c.at(0.01);
    const double first_us = median_us([&] { sink = sink + mat::albedo(first, 1e-4, c.compensation).whole.value[0]; }, 1);
    double sweep_us = 0;
    std::thread([&] {
        const auto t0 = std::chrono::steady_clock::now();
        for (double roughness : roughnesses)
            for (double mu : mus) sink = sink + mat::albedo(c.at(roughness), mu, c.compensation).whole.value[0];
        sweep_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / 25;
    }).join();
    for (double roughness : roughnesses)
        for (double mu : mus) {
            const M m = c.at(roughness);
            us.push_back(median_us([&] { sink = sink + mat::albedo(m, mu, c.compensation).whole.value[0]; }, c.runs));
        }
    std::sort(us.begin(), us.end());
    std::printf("{\"material\":\"%s\",\"points\":%zu,\"median_us\":%.1f,\"largest_us\":%.1f,\"first_us\":%.1f,\"sweep_us\":%.1f}\n",
                c.name, us.size(), us[us.size() / 2], us.back(), first_us, sweep_us);
}

mat::gltf gltf_base(double roughness) {
    mat::gltf m;
    m.in.baseColor = {0.8, 0.4, 0.2}, m.in.metallic = 0.5, m.in.roughness = roughness;
    return m;
}

// Each registered material and compensation, whole points (mat::albedo, what the command takes)
// over the grid: baseColor 0.8, 0.4, 0.2, metallic 0.5 for glTF.
int material_configurations() {
    const auto gltf_at = [](double roughness) { return gltf_base(roughness); };
    using k = mat::compensation_kind;
    for (const auto& c : {configuration<mat::gltf>{"gltf", k::none, gltf_at}, configuration<mat::gltf>{"gltf/kulla-conty", k::kulla_conty, gltf_at},
                          configuration<mat::gltf>{"gltf/turquin", k::turquin, gltf_at},
                          configuration<mat::gltf>{"gltf/fdez-aguera", k::fdez_aguera, gltf_at}})
        time_configuration(c);
    // the extensions, each alone on the same material
    time_configuration(configuration<mat::gltf>{"gltf, sheenColor 1, sheenRoughness 0.5", k::none, [](double r) {
                                                    auto m = gltf_base(r);
                                                    m.in.sheenColor = mat::grey(1), m.in.sheenRoughness = 0.5;
                                                    return m;
                                                }, 5});
    // (sheenRoughness 0.6: a curve of its own, so that its first point builds one)
    time_configuration(configuration<mat::gltf>{"gltf, sheenColor 1, sheenRoughness 0.6, iridescence 1 (400 nm)", k::none,
                                                [](double r) {
                                                    auto m = gltf_base(r);
                                                    m.in.sheenColor = mat::grey(1), m.in.sheenRoughness = 0.6;
                                                    m.in.iridescence = 1;
                                                    return m;
                                                }, 1});
    time_configuration(configuration<mat::gltf>{"gltf, clearcoat 1, clearcoatRoughness 0.3", k::none, [](double r) {
                                                    auto m = gltf_base(r);
                                                    m.in.clearcoat = 1, m.in.clearcoatRoughness = 0.3;
                                                    return m;
                                                }});
    time_configuration(configuration<mat::gltf>{"gltf, iridescence 1 (400 nm)", k::none, [](double r) {
                                                    auto m = gltf_base(r);
                                                    m.in.iridescence = 1;
                                                    return m;
                                                }});
    time_configuration(configuration<mat::gltf>{"gltf, anisotropyStrength 0.5", k::none, [](double r) {
                                                    auto m = gltf_base(r);
                                                    m.in.anisotropyStrength = 0.5;
                                                    return m;
                                                }});
    time_configuration(configuration<mat::gltf>{"gltf, transmission 1", k::none, [](double r) {
                                                    auto m = gltf_base(r);
                                                    m.in.transmission = 1;
                                                    return m;
                                                }});
    const auto openpbr_at = [](double roughness) {
        mat::openpbr m;
        m.in.base_color = {0.8, 0.4, 0.2}, m.in.base_metalness = 0.5, m.in.specular_roughness = roughness;
        return m;
    };
    const auto layered_at = [](double roughness) {  // an absorbing coat and fuzz: their extra integrals
        mat::openpbr m;
        m.in.base_color = {0.8, 0.4, 0.2}, m.in.base_metalness = 0.5, m.in.specular_roughness = roughness;
        m.in.coat_weight = 1, m.in.coat_color = {0.9, 0.8, 0.7}, m.in.coat_roughness = 0.1;
        m.in.fuzz_weight = 0.5, m.in.fuzz_color = {0.9, 0.9, 0.9};
        return m;
    };
    time_configuration(configuration<mat::openpbr>{"openpbr", k::none, openpbr_at});
    time_configuration(configuration<mat::openpbr>{"openpbr, coat_weight 1 (coat_color 0.9, 0.8, 0.7), fuzz_weight 0.5", k::none, layered_at});
    time_configuration(configuration<mat::openpbr>{"openpbr, thin_film_weight 1 (0.5 um, index 1.4)", k::none, [](double r) {
                                                       mat::openpbr m;
                                                       m.in.base_color = {0.8, 0.4, 0.2}, m.in.base_metalness = 0.5;
                                                       m.in.specular_roughness = r, m.in.thin_film_weight = 1;
                                                       return m;
                                                   }});
    return 0;
}

int main(int argc, char** argv) {
    if (argc > 1 && std::string(argv[1]) == "peer") return peer_points();
    if (argc > 1 && std::string(argv[1]) == "materials") return material_configurations();
    volatile double sink = 0;
    for (double roughness : roughnesses)
        for (double mu : mus) {
            mat::gltf m;
            m.in.baseColor = {0.8, 0.4, 0.2}, m.in.metallic = 0.5, m.in.roughness = roughness;
            const double whole = median_us([&] { sink = sink + mat::albedo_of(m, mu).whole.value[0]; });
            double lobe_us[mat::gltf::lobe_count] = {};
            for (std::size_t i = 0; i < mat::gltf::lobe_count; ++i) {
                if (i >= mat::gltf::core_lobe_count) continue;  // the extensions, off here
                const auto l = m.lobe_composition(i);
                normzoo::albedo_settings s;
                s.tolerance = 1e-10 / 8;  // as albedo_of asks each
                lobe_us[i] = median_us([&] {
                    sink = sink + normzoo::microfacet::directional_albedo(l.c, mu, l.alpha, 1, s).value +
                           normzoo::microfacet::directional_albedo(l.c, mu, l.alpha, 0, s).value;
                });
            }
            const double nodes = median_us([&] { sink = sink + mat::albedo_by_nodes(m, mu).whole.value[0]; });
            std::printf("{\"roughness\":%g,\"mu\":%g,\"whole_us\":%.1f,\"diffuse_us\":%.1f,\"specular_us\":%.1f,\"metal_us\":%.1f,"
                        "\"by_nodes_us\":%.1f}\n",
                        roughness, mu, whole, lobe_us[0], lobe_us[1], lobe_us[2], nodes);
        }
    return 0;
}
