// libFuzzer harness of the source-array reader (src/verify/lut_formats/source_array.cpp and
// source_tokens.cpp, source_values.cpp; PNG strings through png.cpp). The first byte chooses the
// file's extension (.js .h .wgsl .glsl: whether '#' lines are directives) and the request (a name,
// DATA; a size, 2 x 2; a table of two slices, each half its rows); the rest is the file's text. It
// must return a whole table or throw bad_input naming the file, each slice whole and the table's
// values; integers must be exact and read as binary16 (or be refused).
#include <cmath>
#include <cstdint>
#include <string>

#include "lut_formats/source_array.hpp"
#include "lut_formats/texels.hpp"
#include "lut_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const char* ext[] = {".js", ".h", ".wgsl", ".glsl"};
    const std::string path = std::string("fuzz") + ext[data[0] & 3];
    verify::array_request request;
    if (data[0] & 4) request.name = "DATA";
    if (data[0] & 8) request.width = request.height = 2;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    verify::decoded_lut d;
    try {
        d = verify::read_source_array(path, text, request);
    } catch (const verify::bad_input& e) {
        lut_fuzz::check_refusal(e, path);
        return 0;
    }
    lut_fuzz::check_decoded(d);
    lut_fuzz::expect(request.name.empty() || d.array_name == request.name, "an array other than the one named");
    if (d.format.rfind("base64-png", 0) == 0) return 0;
    lut_fuzz::expect(!request.width || (d.image.width == 2 && d.image.height == 2), "a size other than the one given");
    lut_fuzz::expect(d.shaped || (d.image.height == 1 && d.image.channels == 1), "an unshaped array that is not one row");
    // a table of slices, as size=WxHxD reads it (lut_layout.hpp): two slices of half the rows each
    if (d.shaped && d.image.height % 2 == 0 && (data[0] & 16))
        for (std::size_t k = 0; k < 2; ++k) {
            const verify::decoded_lut s = verify::decoded_slice(d, d.image.width, d.image.height / 2, k);
            lut_fuzz::check_decoded(s);
            const std::size_t n = s.image.data.size();
            for (std::size_t v = 0; v < n; ++v)
                lut_fuzz::expect(s.image.data[v] == d.image.data[k * n + v] || std::isnan(s.image.data[v]), "a slice's value not the table's");
        }
    if (d.format == "array-decimal") {
        lut_fuzz::expect(d.precision.size() == d.image.data.size(), "decimals without their precision");
        for (const double v : d.image.data) lut_fuzz::expect(std::isfinite(v), "a decimal that is not finite");
        return 0;
    }
    if (d.format != "array-hex") lut_fuzz::finding("a format not among those read: " + d.format);
    for (const double v : d.image.data) lut_fuzz::expect(v >= 0 && v <= 4294967295.0 && v == std::floor(v), "an integer that is not one");
    try {
        verify::interpret_hex(path, d, verify::hex_meaning::binary16);
    } catch (const verify::bad_input& e) {
        lut_fuzz::check_refusal(e, path);
    }
    return 0;
}
