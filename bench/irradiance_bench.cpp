// Times the cap irradiance (binary128, both product rules) one record at a time on one core,
// over the default ratios and tilts of both lights: median of 5 runs each, a JSON line per record.
#include <normzoo/normzoo.hpp>
#include <verify/tables/irradiance.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace {
volatile double sink;
}

int main() {
    for (auto kind : {normzoo::light_kind::sphere, normzoo::light_kind::disk})
        for (double tilt : normzoo::default_irradiance_tilts())
            for (double ratio : normzoo::default_irradiance_ratios()) {
                std::vector<double> t;
                for (int i = 0; i < 5; ++i) {
                    const auto a = std::chrono::steady_clock::now();
                    const auto cap = normzoo::light_cap<normzoo::quad>::of(kind, normzoo::quad(ratio));
                    const auto e = normzoo::cap_irradiance(cap, normzoo::degrees_angle<normzoo::quad>(tilt));
                    sink = static_cast<double>(e.value);
                    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
                }
                std::sort(t.begin(), t.end());
                std::printf("{\"light\":\"%s\",\"ratio\":%.17g,\"tilt\":%.17g,\"seconds\":%.6e}\n",
                            normzoo::light_name(kind), ratio, tilt, t[2]);
            }
}
