// libFuzzer harness of the command line: bytes -> argv -> parse_command_line (CLI11 and the
// list parsers), without running any table. The input is split on NUL bytes if it has any
// (so an argument may hold white space), else on white space (so seeds read as command lines).
// It must return or throw bad_input with a message; anything else is a finding, and so is an
// accepted command line whose values break the contract of docs/command-line.md, "Command reference".
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <normzoo/microfacet/composition.hpp>
#include <normzoo/registry.hpp>

#include "args.hpp"
#include "command_line.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "args_fuzzer: %s\n", what.c_str());
    std::abort();
}

void expect(bool ok, const char* what) {
    if (!ok) finding(std::string("accepted ") + what);
}

// Every decimal in [lo, hi] (or [lo, hi)), compared exactly, and readable as a finite double that
// is 0 only for 0 (the parser's promise: docs/conventions.md, "Inputs are decimals").
bool all_in(const std::vector<normzoo::decimal>& xs, const char* lo, const char* hi, bool hi_open = false) {
    const normzoo::decimal a(lo), b(hi);
    return std::all_of(xs.begin(), xs.end(), [&](const normzoo::decimal& x) {
        const double d = x.to<double>();
        return std::isfinite(d) && (x.is_zero() || std::isnormal(d)) && x >= a && (hi_open ? x < b : x <= b);
    });
}

std::vector<std::string> split(const std::string& text) {
    const bool nul = text.find('\0') != std::string::npos;
    std::vector<std::string> out;
    std::string cur;
    bool any = false;
    for (char c : text) {
        const bool sep = nul ? c == '\0' : (c == ' ' || c == '\t' || c == '\n' || c == '\r');
        if (sep) {
            if (nul || any) out.push_back(cur);
            cur.clear();
            any = false;
        } else {
            cur += c;
            any = true;
        }
    }
    if (any || (nul && !cur.empty())) out.push_back(cur);
    return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Table names the parser is given (the command takes them from its specs, specs/registry.cpp).
    static const std::vector<std::string> tables{"zoo", "bounds", "energy", "irradiance", "shader-precision", "stability", "audit"};
    std::vector<std::string> args = split(std::string(reinterpret_cast<const char*>(data), size));
    args.insert(args.begin(), "verify");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    argv.push_back(nullptr);
    try {
        const auto cl = verify::parse_command_line(static_cast<int>(args.size()), argv.data(), tables);
        if (cl.help) {
            expect(!cl.help->empty(), "an empty help text");
            return 0;
        }
        const auto& o = cl.opts;
        expect(all_in(o.exponents, "0", "1e9"), "an exponent out of [0, 1e9]");
        expect(all_in(o.angles, "0", "90", true), "an angle out of [0, 90)");
        expect(all_in(o.tilts, "0", "180"), "a tilt out of [0, 180]");
        expect(all_in(o.ratios, "0", "1e100") &&
                   std::none_of(o.ratios.begin(), o.ratios.end(), [](const normzoo::decimal& x) { return x.is_zero(); }),
               "a ratio out of (0, 1e100]");
        const bool sphere = o.lights.empty() || std::find(o.lights.begin(), o.lights.end(), "sphere") != o.lights.end();
        expect(!sphere || all_in(o.ratios, "0", "1", true), "a sphere ratio >= 1");
        const bool compositions = !o.models.empty() && o.models.front().find('/') != std::string::npos;
        for (const auto& m : o.models) {
            const auto ids = normzoo::brdf_ids();
            if (compositions) {
                try {
                    normzoo::microfacet::composition::parse(m);
                } catch (const std::invalid_argument&) {
                    finding("an unknown composition accepted: " + m);
                }
            } else {
                expect(std::find(ids.begin(), ids.end(), m) != ids.end(), "an unknown model");
            }
        }
        expect(all_in(o.roughness, "0", o.roughness_is_r ? "10" : "100") &&
                   std::none_of(o.roughness.begin(), o.roughness.end(), [](const normzoo::decimal& x) { return x.is_zero(); }),
               "a roughness out of range");
        expect(all_in(o.mus, "0", "1") &&
                   std::none_of(o.mus.begin(), o.mus.end(), [](const normzoo::decimal& x) { return x.is_zero(); }),
               "a mu out of (0, 1]");
        const auto& f0 = o.parts.f0;
        expect(!f0 || (*f0 >= normzoo::decimal("0") && *f0 < normzoo::decimal("1")), "an f0 out of [0, 1)");
        bool any_part = false;
        for (const auto& q : verify::part_parameters()) {
            const auto& x = o.parts.*q.input;
            if (!x) continue;
            any_part = true;
            const normzoo::decimal lo(q.min), hi(q.max);
            if (!((q.min_open ? *x > lo : *x >= lo) && *x <= hi)) finding(std::string("accepted a ") + q.name + " out of its range");
        }
        expect(compositions || (o.roughness.empty() && o.mus.empty() && !f0 && !any_part),
               "--alpha, --r, --mu, --f0 or a part's parameter without a composition");
        for (const auto& l : o.lights) expect(l == "sphere" || l == "disk", "an unknown light");
        // a table named, or the job --brdf or --material plans (brdf-file, material: never named,
        // so never in the list)
        for (const auto& t : cl.tables)
            expect(std::find(tables.begin(), tables.end(), t) != tables.end() || (t == "brdf-file" && !cl.brdf_file.empty()) ||
                       (t == "material" && o.typed.count("--material") && cl.tables.size() == 1),
                   "an unknown table");
        expect(o.jobs >= 1 && o.jobs <= 256, "--jobs out of [1, 256]");
        expect(cl.scene_path.empty() || (cl.tables.empty() && o.exponents.empty() && o.angles.empty() && o.models.empty() &&
                                         o.lights.empty() && o.ratios.empty() && o.tilts.empty()),
               "--scene with tables or table options");
    } catch (const verify::bad_input& e) {
        if (std::string(e.what()).empty()) finding("bad_input without a message");
    } catch (const std::exception& e) {
        finding(std::string("an exception other than bad_input: ") + e.what());
    }
    return 0;
}
