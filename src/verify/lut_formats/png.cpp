// PNG through libpng, in memory (png.hpp): the 16- and 8-bit writer, and the reader of 8- and 16-bit
// images with the colour chunks they carry.
#include "png.hpp"

#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <vector>

#include "../args.hpp"
#include "texels.hpp"

namespace verify {
namespace {

// libpng reports errors by longjmp. The frames it jumps over (libpng's, our callbacks', and the
// functions below that call setjmp) hold nothing with a destructor, so the jump is safe in C++;
// the callers turn a failure into an exception once libpng has returned.

struct png_io {  // the callbacks' state; trivially destructible
    std::string* out = nullptr;
    const std::string* in = nullptr;
    std::size_t pos = 0;
    char message[200] = "";
};

[[noreturn]] void on_error(png_structp png, png_const_charp msg) {
    auto* io = static_cast<png_io*>(png_get_error_ptr(png));
    std::snprintf(io->message, sizeof io->message, "%s", msg);
    png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}  // warnings are not failures: keep stderr quiet

void on_write(png_structp png, png_bytep data, png_size_t n) {
    bool failed = false;
    try {
        static_cast<png_io*>(png_get_io_ptr(png))->out->append(reinterpret_cast<const char*>(data), n);
    } catch (...) {
        failed = true;  // no longjmp from inside a handler: the exception would never be destroyed
    }
    if (failed) png_error(png, "out of memory");
}
void on_flush(png_structp) {}

void on_read(png_structp png, png_bytep data, png_size_t n) {
    auto* io = static_cast<png_io*>(png_get_io_ptr(png));
    if (n > io->in->size() - io->pos) png_error(png, "read beyond the end of the data");
    std::memcpy(data, io->in->data() + io->pos, n);
    io->pos += n;
}

bool write_png(png_structp png, png_infop info, png_uint_32 w, png_uint_32 h, int depth, int color, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, w, h, depth, color, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    return true;
}

bool read_png_header(png_structp png, png_infop info, png_uint_32* w, png_uint_32* h, int* depth, int* color) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    png_get_IHDR(png, info, w, h, depth, color, nullptr, nullptr, nullptr);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    return true;
}

bool read_png_rows(png_structp png, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return true;
}

// Frees libpng's read state on every path.
struct png_reader {
    png_structp png = nullptr;
    png_infop info = nullptr;
    explicit png_reader(png_io* io) {
        png = png_create_read_struct(PNG_LIBPNG_VER_STRING, io, on_error, on_warning);
        if (png) info = png_create_info_struct(png);
        if (!info) {
            png_destroy_read_struct(&png, nullptr, nullptr);
            throw std::bad_alloc();
        }
        png_set_read_fn(png, io, on_read);
    }
    ~png_reader() { png_destroy_read_struct(&png, &info, nullptr); }
    png_reader(const png_reader&) = delete;
    png_reader& operator=(const png_reader&) = delete;
};

std::uint32_t be32(const std::string& b, std::size_t at) {
    return std::uint32_t(std::uint8_t(b[at])) << 24 | std::uint32_t(std::uint8_t(b[at + 1])) << 16 |
           std::uint32_t(std::uint8_t(b[at + 2])) << 8 | std::uint32_t(std::uint8_t(b[at + 3]));
}

// The colour chunks as the file has them, before its image data (where the PNG specification puts
// them; the first of each counts). Read from the bytes, not from libpng's flags: libpng 1.6 also
// marks gAMA and cHRM valid when it derives them from an sRGB chunk or a profile
// (png_colorspace_sync_info), and a table's check needs what the file says.
colour_declaration scan_colour_chunks(const std::string& b) {
    colour_declaration c;
    bool iccp = false;
    for (std::size_t at = 8; at + 12 <= b.size();) {
        const std::uint32_t len = be32(b, at);
        if (len > b.size() - at - 12) break;  // libpng refuses the file
        const std::string type = b.substr(at + 4, 4);
        const std::size_t data = at + 8;
        if (type == "IDAT" || type == "IEND") break;
        if (type == "sRGB" && len == 1 && !c.srgb_intent) c.srgb_intent = int(std::uint8_t(b[data]));
        if (type == "gAMA" && len == 4 && !c.gamma && be32(b, data) != 0) c.gamma = be32(b, data) / 100000.0;
        if (type == "cHRM" && len == 32 && !c.chromaticities) {
            std::array<double, 8> xy{};
            for (std::size_t k = 0; k < 8; ++k) xy[k] = be32(b, data + 4 * k) / 100000.0;
            c.chromaticities = xy;
        }
        if (type == "iCCP" && !iccp) {
            iccp = true;
            const std::size_t name_end = b.find('\0', data);
            if (name_end < data + len) c.icc_name = b.substr(data, name_end - data);
        }
        at = data + len + 4;
    }
    using k = colour_declaration::kind;
    c.declared = iccp ? k::icc : c.srgb_intent ? k::srgb : c.gamma ? k::gamma : k::none;
    return c;
}

// The profile of an iCCP chunk, decompressed by libpng, where it kept it (it drops one it finds
// malformed: the file still declares a profile, named, without its bytes).
void add_icc_profile(png_structp png, png_infop info, colour_declaration& c) {
    png_charp name = nullptr;
    int compression = 0;
    png_bytep profile = nullptr;
    png_uint_32 length = 0;
    if (c.declared == colour_declaration::kind::icc && png_get_iCCP(png, info, &name, &compression, &profile, &length) &&
        profile)
        c.icc_profile.assign(reinterpret_cast<const char*>(profile), length);
}

}  // namespace

decoded_lut read_png(const std::string& path, const std::string& bytes) {
    png_io io;
    io.in = &bytes;
    png_reader r(&io);
    const auto corrupt = [&] { return bad_input(path + ": truncated or corrupt PNG (" + io.message + ")"); };
    png_uint_32 w = 0, h = 0;
    int depth = 0, color = 0;
    if (!read_png_header(r.png, r.info, &w, &h, &depth, &color)) throw corrupt();
    if (color == PNG_COLOR_TYPE_PALETTE) throw bad_input(path + ": a palette PNG; a table needs gray, gray+alpha, RGB or RGBA");
    if (depth != 8 && depth != 16)
        throw bad_input(path + ": a " + std::to_string(depth) + "-bit PNG; a table needs 8 or 16 bits per channel");
    const std::size_t channels = color == PNG_COLOR_TYPE_GRAY ? 1 : color == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                 : color == PNG_COLOR_TYPE_RGB ? 3 : color == PNG_COLOR_TYPE_RGB_ALPHA ? 4 : 0;
    if (channels == 0) throw bad_input(path + ": PNG color type " + std::to_string(color) + " is not gray, gray+alpha, RGB or RGBA");
    if (w == 0 || h == 0 || w > max_side || h > max_side)
        throw bad_input(path + ": a " + std::to_string(w) + " x " + std::to_string(h) + " image; a table is 1 to " +
                        std::to_string(max_side) + " texels a side");
    const std::size_t bps = std::size_t(depth) / 8, row_bytes = std::size_t(w) * channels * bps;
    // deflate expands at most 1032-fold: a short file claiming a large image is cut off, and is
    // refused before its pixels are allocated
    if (h * (row_bytes + 1) / 1032 > bytes.size())
        throw bad_input(path + ": truncated or corrupt PNG (" + std::to_string(w) + " x " + std::to_string(h) +
                        " texels cannot fit in " + std::to_string(bytes.size()) + " bytes)");
    std::vector<png_byte> pixels(h * row_bytes);
    std::vector<png_bytep> rows(h);
    for (std::size_t j = 0; j < h; ++j) rows[j] = pixels.data() + j * row_bytes;
    if (!read_png_rows(r.png, rows.data())) throw corrupt();

    decoded_lut d;
    d.image.width = w, d.image.height = h, d.image.channels = channels;
    d.image.data.resize(pixels.size() / bps);
    for (std::size_t k = 0; k < d.image.data.size(); ++k)  // 16-bit samples are big-endian
        d.image.data[k] = bps == 1 ? pixels[k] / 255.0 : (pixels[2 * k] << 8 | pixels[2 * k + 1]) / 65535.0;
    d.format = bps == 1 ? "png8" : "png16";
    d.absolute = bps == 1 ? 0.5 / 255 : 0.5 / 65535;
    d.relative = 0;
    d.encoding = bps == 1 ? value_encoding::unorm8 : value_encoding::unorm16;
    d.colour = scan_colour_chunks(bytes);
    add_icc_profile(r.png, r.info, d.colour);
    return d;
}

namespace {

// 8 or 16 bits a sample (16-bit samples big-endian); 2 channels go to R, G with B = 0.
std::string encode_png(const lut_image& im, int depth) {
    check_image(im);
    const std::size_t out_ch = im.channels == 2 ? 3 : im.channels;  // (A, B) goes to R, G with B = 0
    const int color = out_ch == 1 ? PNG_COLOR_TYPE_GRAY : out_ch == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA;
    const std::size_t bps = std::size_t(depth) / 8, row_bytes = im.width * out_ch * bps;
    const double most = depth == 8 ? 255 : 65535;
    std::vector<png_byte> pixels(im.height * row_bytes, 0);
    for (std::size_t t = 0; t < im.width * im.height; ++t)
        for (std::size_t c = 0; c < im.channels; ++c) {
            const double v = im.data[t * im.channels + c];
            const long q = std::isnan(v) ? 0 : std::lround(std::clamp(v, 0.0, 1.0) * most);
            png_byte* p = &pixels[(t * out_ch + c) * bps];
            if (bps == 1) p[0] = png_byte(q);
            else p[0] = png_byte(q >> 8), p[1] = png_byte(q & 0xff);
        }
    std::vector<png_bytep> rows(im.height);
    for (std::size_t j = 0; j < im.height; ++j) rows[j] = pixels.data() + j * row_bytes;

    std::string out;
    png_io io;
    io.out = &out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &io, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        throw std::bad_alloc();
    }
    png_set_write_fn(png, &io, on_write, on_flush);
    const bool ok = write_png(png, info, png_uint_32(im.width), png_uint_32(im.height), depth, color, rows.data());
    png_destroy_write_struct(&png, &info);
    if (!ok) throw std::runtime_error(std::string("libpng: ") + io.message);
    return out;
}

}  // namespace

std::string encode_png16(const lut_image& im) { return encode_png(im, 16); }

std::string encode_png8(const lut_image& im) { return encode_png(im, 8); }

}  // namespace verify
