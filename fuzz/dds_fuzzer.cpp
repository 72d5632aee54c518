// libFuzzer harness of the DDS reader (src/verify/lut_formats/dds.cpp): bytes = a file. It must
// return a whole table or throw bad_input naming the file; a table read in a DXGI format must
// come back unchanged through normzoo's DDS writer.
#include <cstdint>
#include <string>

#include "lut_formats/dds.hpp"
#include "lut_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size), path = "fuzz.dds";
    verify::decoded_lut d;
    try {
        d = verify::read_dds(path, bytes);
    } catch (const verify::bad_input& e) {
        lut_fuzz::check_refusal(e, path);
        return 0;
    }
    lut_fuzz::check_decoded(d);
    lut_fuzz::expect(d.format.rfind("dds-", 0) == 0 && d.precision.empty(), "a DDS table's format or precision");
    // every DXGI format the reader knows (the enumeration ends below 200), float ones among them
    for (std::uint32_t dxgi = 0; dxgi < 200; ++dxgi) {
        const verify::dds_format* f = verify::dds_format_of(dxgi);
        if (!f || d.format != std::string("dds-") + f->name) continue;
        lut_fuzz::expect(d.image.channels == f->channels && d.encoding == f->encoding, "channels or encoding not the format's");
        lut_fuzz::expect(lut_fuzz::same_values(verify::read_dds(path, verify::encode_dds(d.image, dxgi)).image, d.image),
                         "a table that does not come back through the writer");
        return 0;
    }
    // bit masks: unorm values in [0, 1]
    for (const double v : d.image.data) lut_fuzz::expect(v >= 0 && v <= 1, "a unorm value out of [0, 1]");
    return 0;
}
