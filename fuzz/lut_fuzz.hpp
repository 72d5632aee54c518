// What the table-file harnesses share (ktx2, dds, hdr and array fuzzers): a finding aborts with
// its reason, and a decoded table must be whole (decoded.hpp's promises), its message naming the
// file when refused.
#pragma once
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "args.hpp"
#include "lut_formats/decoded.hpp"

namespace lut_fuzz {

[[noreturn]] inline void finding(const std::string& what) {
    std::fprintf(stderr, "lut_fuzzer: %s\n", what.c_str());
    std::abort();
}

inline void expect(bool ok, const char* what) {
    if (!ok) finding(what);
}

// A refusal names the file first, and says what is wrong after it.
inline void check_refusal(const verify::bad_input& e, const std::string& path) {
    const std::string m = e.what();
    if (m.rfind(path, 0) != 0 || m.size() <= path.size() + 2) finding("a message without the file: " + m);
}

// The image is whole: 1 to 4 channels, at most max_side a side (a source array without a shape is
// one row), its values and per-value precisions as many as its texels' channels.
inline void check_decoded(const verify::decoded_lut& d) {
    const auto& im = d.image;
    expect(im.channels >= 1 && im.channels <= 4, "channels out of 1 to 4");
    expect(im.width >= 1 && im.height >= 1, "an empty image");
    expect(!d.shaped || (im.width <= verify::max_side && im.height <= verify::max_side), "a side beyond max_side");
    expect(im.data.size() == im.width * im.height * im.channels, "values not width x height x channels");
    expect(d.precision.empty() || d.precision.size() == im.data.size(), "precisions not one per value");
    expect(!d.format.empty(), "no format name");
    for (std::size_t k = 0; k < im.data.size(); ++k) {
        const double t = d.tolerance(k);
        expect(std::isnan(im.data[k]) || (!std::isnan(t) && t >= 0), "a tolerance that is NaN or negative for a number");
    }
}

// Two reads of the same values: equal, NaN where NaN.
inline bool same_values(const verify::lut_image& a, const verify::lut_image& b) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels || a.data.size() != b.data.size()) return false;
    for (std::size_t k = 0; k < a.data.size(); ++k)
        if (!(a.data[k] == b.data[k] || (std::isnan(a.data[k]) && std::isnan(b.data[k])))) return false;
    return true;
}

}  // namespace lut_fuzz
