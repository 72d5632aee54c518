// Times the directional albedo at 1e-10, one point at a time on one core, one JSON object per line:
//   normzoo-bench-albedo sweep          every point of the default energy grid, one run each
//   normzoo-bench-albedo points RUNS    the peer points of bench/scipy_albedo.py, median of RUNS
#include <normzoo/normzoo.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {
struct point {
    const char* model;
    double n, theta;
};

// Shared with bench/scipy_albedo.py (same order).
const std::vector<point> peer_points = {
    {"lambert", 0, 45},           {"phong-modified", 16, 30},          {"phong-modified", 256, 60},
    {"phong-modified", 1e4, 75},  {"blinn-phong-modified", 16, 45},    {"blinn-phong-modified", 1024, 80},
    {"microfacet-blinn", 64, 60}, {"minimalist-cook-torrance", 16, 70}, {"minimalist-cook-torrance", 256, 89},
    {"cook-torrance-ksk", 100, 85}, {"cook-torrance-ksk", 1e4, 30},    {"phong", 4, 89.9},
    {"minimalist-cook-torrance", 16, 89.99}, {"blinn-phong-modified", 1e5, 89.9}};

normzoo::quadrature::estimate<double> run(const std::string& model, double n, double theta) {
    normzoo::quadrature::estimate<double> e{};
    normzoo::with_brdf(model, [&](auto form) { e = normzoo::albedo<decltype(form)>(theta, n); });
    return e;
}

double seconds(const std::string& model, double n, double theta, normzoo::quadrature::estimate<double>& e) {
    const auto a = std::chrono::steady_clock::now();
    e = run(model, n, theta);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

void print(const std::string& model, double n, double theta, double s, const normzoo::quadrature::estimate<double>& e) {
    std::printf("{\"model\":\"%s\",\"n\":%.17g,\"theta\":%.17g,\"seconds\":%.6e,\"albedo\":%.17g,\"error\":%.3e,"
                "\"evaluations\":%zu}\n",
                model.c_str(), n, theta, s, e.value, e.abs_error, e.evaluations);
}
}  // namespace

int main(int argc, char** argv) {
    const bool sweep = argc > 1 && std::strcmp(argv[1], "sweep") == 0;
    normzoo::quadrature::estimate<double> e{};
    seconds("minimalist-cook-torrance", 16, 60, e);  // warm-up: rule tables
    if (sweep) {
        for (auto id : normzoo::zoo_brdf_ids()) {
            bool has_exponent = true;
            normzoo::with_brdf(id, [&](auto form) { has_exponent = decltype(form)::has_exponent; });
            for (double n : has_exponent ? normzoo::default_energy_exponents() : std::vector<double>{0})
                for (double t : normzoo::default_energy_angles()) {
                    const double s = seconds(std::string(id), n, t, e);
                    print(std::string(id), n, t, s, e);
                }
        }
        return 0;
    }
    const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
    for (const auto& p : peer_points) {
        std::vector<double> t;
        for (int i = 0; i < runs; ++i) t.push_back(seconds(p.model, p.n, p.theta, e));
        std::sort(t.begin(), t.end());
        print(p.model, p.n, p.theta, t[t.size() / 2], e);
    }
}
