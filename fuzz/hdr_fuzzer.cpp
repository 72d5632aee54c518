// libFuzzer harness of the Radiance HDR reader (src/verify/lut_formats/hdr.cpp): bytes = a file.
// It must return a whole table or throw bad_input naming the file; each value read is Radiance's
// (c + 0.5) 2^(E - 136), with that step as its precision, or 0.
#include <cmath>
#include <cstdint>
#include <string>

#include "lut_formats/hdr.hpp"
#include "lut_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size), path = "fuzz.hdr";
    verify::decoded_lut d;
    try {
        d = verify::read_hdr(path, bytes);
    } catch (const verify::bad_input& e) {
        lut_fuzz::check_refusal(e, path);
        return 0;
    }
    lut_fuzz::check_decoded(d);
    lut_fuzz::expect(d.format == "hdr" && d.image.channels == 3 && d.precision.size() == d.image.data.size(), "an HDR table's shape");
    lut_fuzz::expect(std::isfinite(d.exposure) && d.exposure > 0, "an exposure that is not a positive number");
    for (std::size_t k = 0; k < d.image.data.size(); ++k) {
        const double v = d.image.data[k], step = d.precision[k];
        if (v == 0) lut_fuzz::expect(step == 1e-32, "a zero whose precision is not 1e-32");
        else lut_fuzz::expect(v / step >= 0.5 && v / step < 256 && std::floor(v / step) + 0.5 == v / step, "a value that is not (c + 0.5) step");
    }
    return 0;
}
