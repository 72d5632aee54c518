// A table's file, told apart and read (read.hpp).
#include "read.hpp"

#include <cstdio>
#include <cstring>
#include <memory>

#include "../args.hpp"
#include "dds.hpp"
#include "exr.hpp"
#include "hdr.hpp"
#include "ktx2.hpp"
#include "png.hpp"

namespace verify {
namespace {

enum class file_kind { png, exr, ktx2, dds, hdr, source, unknown };

file_kind kind_of(const std::string& head, const std::string& path) {
    const auto starts = [&](const char* sig, std::size_t n) { return head.size() >= n && std::memcmp(head.data(), sig, n) == 0; };
    if (starts("\x89PNG\r\n\x1a\n", 8)) return file_kind::png;
    if (starts("\x76\x2f\x31\x01", 4)) return file_kind::exr;
    if (starts("\xABKTX 20\xBB\r\n\x1A\n", 12)) return file_kind::ktx2;
    if (starts("DDS ", 4)) return file_kind::dds;
    if (starts("#?", 2)) return file_kind::hdr;
    return is_source_file_name(path) ? file_kind::source : file_kind::unknown;
}

}  // namespace

decoded_lut read_lut_file(const std::string& path, const array_request& request) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) throw bad_input(path + ": cannot be read");
    // the signature first, so that a device or a large file of another kind is not read whole
    std::string bytes(12, '\0');
    bytes.resize(std::fread(&bytes[0], 1, 12, f.get()));
    const file_kind kind = kind_of(bytes, path);
    if (kind != file_kind::unknown) {
        char buf[1 << 16];
        while (std::size_t n = std::fread(buf, 1, sizeof buf, f.get())) {
            bytes.append(buf, n);
            if (bytes.size() > max_file_bytes) throw bad_input(path + ": more than 1 GiB; a table's file is smaller");
        }
    }
    if (std::ferror(f.get())) throw bad_input(path + ": cannot be read");  // a folder, an I/O error
    switch (kind) {
        case file_kind::png: return read_png(path, bytes);
        case file_kind::exr: return read_exr(path, bytes);
        case file_kind::ktx2: return read_ktx2(path, bytes);
        case file_kind::dds: return read_dds(path, bytes);
        case file_kind::hdr: return read_hdr(path, bytes);
        case file_kind::source: return read_source_array(path, bytes, request);
        case file_kind::unknown: break;
    }
    throw bad_input(path + ": not a PNG or OpenEXR image, nor a KTX2, DDS or Radiance HDR file, nor a CSV table (a file named "
                    ".csv) or a source file's array (.h, .hpp, .inc, .c, .cpp, .js, .ts, .wgsl, .glsl): the LUT formats normzoo reads");
}

}  // namespace verify
