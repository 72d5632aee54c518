// libFuzzer harness of the scene loader (docs/command-line.md, "A guardrail for an engine"): bytes -> a scene's text -> load_scene_text.
// The loader must accept the scene or throw bad_input naming the file; any other exception, a
// crash, a leak or a sanitizer report is a finding. An accepted scene must also be one the run
// can take: the checks below are what scene_run.cpp and the library rely on.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <normzoo/microfacet/composition.hpp>

#include "args.hpp"
#include "brdf_file/shader_screen.hpp"
#include "layout_names.hpp"
#include "part_inputs.hpp"
#include "scene.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "scene_fuzzer: %s\n", what.c_str());
    std::abort();
}

void expect(bool ok, const char* what) {
    if (!ok) finding(std::string("accepted a scene with ") + what);
}

bool in(double x, double lo, double hi) { return x >= lo && x <= hi; }

void check_accepted(const verify::scene& s, const std::vector<std::string>& ids) {
    expect(!s.materials.empty() || !s.lights.empty(), "nothing in it");
    expect(!s.name.empty(), "no name");
    expect(s.digits > 0 && s.digits <= 33, "digits out of (0, 33]");
    expect(in(s.albedo, 1e-12, 1e-2), "an albedo tolerance out of [1e-12, 1e-2]");
    expect(s.normalization > 0 && std::isfinite(s.normalization), "a bad normalization tolerance");
    auto printable = [](const std::string& name) {
        return !name.empty() && std::none_of(name.begin(), name.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; });
    };
    for (const auto& m : s.materials) {
        expect(printable(m.name), "a material name that is empty or holds control characters");
        if (m.code()) {  // brdf = "file": an existing file, read when the scene runs (docs/brdf-code.md)
            expect(!m.brdf_written.empty() && !m.composition, "a shader material without a file");
            for (const auto& d : m.brdf_defines) {
                bool valid = true;
                try {
                    verify::check_define(d);
                } catch (const verify::bad_input&) {
                    valid = false;
                }
                expect(valid, "a define --define refuses");
            }
            for (const auto& d : m.brdf_include_dirs) expect(std::filesystem::is_directory(d), "an include folder that is not one");
            continue;
        }
        if (m.composition) {  // model D/G/F (docs/microfacet.md): what the energy sweep and its LUT check take
            bool parses = true;
            try {
                (void)normzoo::microfacet::composition::parse(m.model);
            } catch (const std::invalid_argument&) {
                parses = false;
            }
            expect(parses, "an unknown composition");
            const double lo = m.rough_lo.to<double>(), hi = m.rough_hi.to<double>();
            expect(lo > 0 && hi >= lo && hi <= (m.rough_is_r ? 10 : 100), "a roughness range out of (0, 100] (r: 10) or reversed");
            if (m.parts.f0) expect(!(*m.parts.f0 < normzoo::decimal("0")) && *m.parts.f0 < normzoo::decimal("1"), "an f0 out of [0, 1)");
            for (const auto& q : verify::part_parameters())
                if (m.parts.*q.input)
                    expect(in((m.parts.*q.input)->to<double>(), std::stod(q.min), std::stod(q.max)), "a part parameter out of its range");
            expect(!m.normalization && !m.shader, "a composition with a normalization expression");
            continue;
        }
        expect(std::find(ids.begin(), ids.end(), m.model) != ids.end(), "an unknown model");
        expect(in(m.n_min, 0, 1e9) && in(m.n_max, m.n_min, 1e9), "an exponent range out of [0, 1e9] or reversed");
        expect(in(m.specular, 0, 1), "a specular out of [0, 1]");
        expect(m.normalization.has_value() == static_cast<bool>(m.shader), "an expression without its compiled form");
        // The run evaluates the expression over [n_min, n_max]: hostile expressions must not crash it.
        if (m.shader) {
            expect(std::isfinite(m.shader(m.n_min)) && std::isfinite(m.shader(m.n_max)), "an expression not finite at an end");
            (void)m.shader(0.5 * (m.n_min + m.n_max));
        }
    }
    for (const auto& l : s.lights) {
        expect(printable(l.name), "a light name that is empty or holds control characters");
        expect(l.type == "sphere" || l.type == "disk", "an unknown light type");
        const double ratio = l.radius / l.distance;
        expect(std::isnormal(ratio) && ratio > 0 && ratio <= 1e100, "r0/r out of what --ratio accepts");
        expect(l.type == "disk" || ratio < 1, "a sphere as large as its distance");
        if (l.tilt_deg) expect(in(l.tilt_deg->first, 0, 180) && in(l.tilt_deg->second, l.tilt_deg->first, 180), "a bad tilt range");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const auto ids = verify::scene_model_ids();
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string path = "fuzz.toml";
    try {
        check_accepted(verify::load_scene_text(text, path, ids), ids);
    } catch (const verify::bad_input& e) {
        // The message says where: "fuzz.toml:LINE: key: what" or "fuzz.toml: what".
        const std::string msg = e.what();
        if (msg.rfind(path + ":", 0) != 0 || msg.size() <= path.size() + 2) finding("a message without the file: " + msg);
    } catch (const std::exception& e) {
        finding(std::string("an exception other than bad_input: ") + e.what());
    }
    return 0;
}
