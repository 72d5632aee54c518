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
        for (const auto& tilt_input : verify::default_irradiance_tilts())
            for (const auto& ratio_input : verify::default_irradiance_ratios()) {
                const double tilt = tilt_input.to<double>(), ratio = ratio_input.to<double>();
                std::vector<double> t, td;
                for (int i = 0; i < 5; ++i) {
                    const auto a = std::chrono::steady_clock::now();
                    // the same cap at the doubles nearest the inputs: what the exact inputs cost
                    const auto cap = normzoo::light_cap<normzoo::quad>::of(kind, normzoo::quad(ratio));
                    const auto e = normzoo::cap_irradiance(cap, normzoo::degrees_angle<normzoo::quad>(tilt));
                    sink = static_cast<double>(e.value);
                    td.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
                }
                for (int i = 0; i < 5; ++i) {
                    const auto a = std::chrono::steady_clock::now();
                    // as the table computes it: at the decimals, the bound covering their rounding
                    const auto e = normzoo::cap_irradiance(kind, ratio_input, tilt_input);
                    sink = static_cast<double>(e.value);
                    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
                }
                std::sort(t.begin(), t.end());
                std::sort(td.begin(), td.end());
                std::printf("{\"light\":\"%s\",\"ratio\":%.17g,\"tilt\":%.17g,\"seconds\":%.6e,\"seconds_double_input\":%.6e}\n",
                            normzoo::light_name(kind), ratio, tilt, t[2], td[2]);
            }
}
