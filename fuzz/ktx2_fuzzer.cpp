// libFuzzer harness of the KTX2 reader (src/verify/lut_formats/ktx2.cpp): bytes = a file. It
// must return a whole table or throw bad_input naming the file; a table read must come back
// unchanged through normzoo's KTX2 writer (in its format, uncompressed and Zstandard).
#include <cstdint>
#include <string>

#include "lut_formats/ktx2.hpp"
#include "lut_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size), path = "fuzz.ktx2";
    verify::decoded_lut d;
    try {
        d = verify::read_ktx2(path, bytes);
    } catch (const verify::bad_input& e) {
        lut_fuzz::check_refusal(e, path);
        return 0;
    }
    lut_fuzz::check_decoded(d);
    lut_fuzz::expect(d.format.rfind("ktx2-", 0) == 0 && d.precision.empty(), "a KTX2 table's format or precision");
    lut_fuzz::expect(d.orientation.size() == 2, "a KTX2 table without its orientation");
    // every vkFormat the reader knows (those of tables end below 200)
    for (std::uint32_t vk = 0; vk < 200; ++vk) {
        const verify::ktx2_format* f = verify::ktx2_format_of(vk);
        if (!f || d.format != std::string("ktx2-") + f->name) continue;
        lut_fuzz::expect(d.image.channels == f->channels && d.encoding == f->encoding, "channels or encoding not the format's");
        for (const bool zstd : {false, true})
            lut_fuzz::expect(lut_fuzz::same_values(verify::read_ktx2(path, verify::encode_ktx2(d.image, vk, zstd)).image, d.image),
                             "a table that does not come back through the writer");
        return 0;
    }
    lut_fuzz::finding("a format not among those read: " + d.format);
}
