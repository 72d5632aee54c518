// The baked tables as images (lut_image.hpp): PNG through libpng, OpenEXR through the OpenEXR
// library, both in memory, and a C header as text.
#include "lut_image.hpp"

#include <png.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/Iex.h>
#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <set>
#include <stdexcept>

#include "args.hpp"

namespace verify {
namespace {

// read: the largest table `verify lut --size` makes; bounds what a bad file can make us allocate
// and compute (a 4097^2 image, every texel an albedo, ran past a minute)
constexpr std::size_t max_side = 4096;

// The encoders' precondition: a whole image of 1 to 4 channels, of a size both formats can hold
// (which also keeps width * height * channels from overflowing).
void check_image(const lut_image& im) {
    constexpr std::size_t max_int = std::numeric_limits<int>::max();
    if (im.channels < 1 || im.channels > 4 || im.width == 0 || im.height == 0 || im.width > max_int ||
        im.height > max_int || im.data.size() != im.width * im.height * im.channels)
        throw std::invalid_argument("lut image: " + std::to_string(im.width) + " x " + std::to_string(im.height) + " x " +
                                    std::to_string(im.channels) + " with " + std::to_string(im.data.size()) +
                                    " values is not an image of 1 to 4 channels");
}

// ---- PNG -------------------------------------------------------------------------------------
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

bool write_png(png_structp png, png_infop info, png_uint_32 w, png_uint_32 h, int color, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, w, h, 16, color, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
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
    return d;
}

// ---- OpenEXR ---------------------------------------------------------------------------------

struct memory_ostream : Imf::OStream {
    std::string bytes;
    std::uint64_t pos = 0;
    memory_ostream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {  // the line offset table is written over its placeholder at the end
        if (pos + std::uint64_t(n) > bytes.size()) bytes.resize(pos + std::uint64_t(n));
        std::memcpy(&bytes[pos], c, std::size_t(n));
        pos += std::uint64_t(n);
    }
    std::uint64_t tellp() override { return pos; }
    void seekp(std::uint64_t p) override { pos = p; }
};

struct memory_istream : Imf::IStream {
    const std::string& bytes;
    std::uint64_t pos = 0;
    explicit memory_istream(const std::string& b, const std::string& name) : Imf::IStream(name.c_str()), bytes(b) {}
    bool read(char c[], int n) override {
        if (n < 0 || pos > bytes.size() || std::uint64_t(n) > bytes.size() - pos)
            throw Iex::InputExc("unexpected end of file");
        std::memcpy(c, bytes.data() + pos, std::size_t(n));
        pos += std::uint64_t(n);
        return pos < bytes.size();
    }
    std::uint64_t tellg() override { return pos; }
    void seekg(std::uint64_t p) override { pos = p; }  // reading past the end fails in read()
};

const char* const exr_names[4][4] = {{"Y"}, {"R", "G"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};

template <class T>
void write_exr(memory_ostream& os, const lut_image& im, Imf::PixelType type) {
    const std::vector<T> values(im.data.begin(), im.data.end());
    Imf::Header header(int(im.width), int(im.height));
    header.compression() = Imf::NO_COMPRESSION;
    Imf::FrameBuffer fb;
    for (std::size_t c = 0; c < im.channels; ++c) {
        const char* name = exr_names[im.channels - 1][c];
        header.channels().insert(name, Imf::Channel(type));
        fb.insert(name, Imf::Slice(type, const_cast<char*>(reinterpret_cast<const char*>(values.data() + c)),
                                   sizeof(T) * im.channels, sizeof(T) * im.channels * im.width));
    }
    Imf::OutputFile file(os, header);  // INCREASING_Y by default: row 0 is the first scanline
    file.setFrameBuffer(fb);
    file.writePixels(int(im.height));
}

// Which of exr_names the file's channels are; throws bad_input for anything else.
std::size_t exr_channels(const std::string& path, const Imf::ChannelList& list) {
    std::set<std::string> names;
    const Imf::Channel* first = nullptr;
    for (auto it = list.begin(); it != list.end(); ++it) {
        const Imf::Channel& ch = it.channel();
        const std::string name = it.name();
        if (ch.type != Imf::HALF && ch.type != Imf::FLOAT)
            throw bad_input(path + ": OpenEXR channel " + name + " holds integers; a table needs half or float");
        if (first && ch.type != first->type)
            throw bad_input(path + ": OpenEXR channel " + name + " is not of the same pixel type (half or float) as channel " +
                            list.begin().name());
        if (ch.xSampling != 1 || ch.ySampling != 1) throw bad_input(path + ": OpenEXR channel " + name + " is subsampled");
        if (!first) first = &ch;
        names.insert(name);
    }
    for (std::size_t n = 1; n <= 4; ++n)
        if (names == std::set<std::string>(exr_names[n - 1], exr_names[n - 1] + n)) return n;
    std::string got;
    for (const auto& n : names) got += (got.empty() ? "" : ", ") + n;
    throw bad_input(path + ": OpenEXR channels {" + got + "}; a table has Y, R G, R G B or R G B A");
}

decoded_lut read_exr(const std::string& path, const std::string& bytes) {
    try {
        memory_istream is(bytes, path);
        Imf::InputFile file(is);
        const Imath::Box2i dw = file.header().dataWindow();
        const std::int64_t w = std::int64_t(dw.max.x) - dw.min.x + 1, h = std::int64_t(dw.max.y) - dw.min.y + 1;
        if (w <= 0 || h <= 0 || w > std::int64_t(max_side) || h > std::int64_t(max_side))
            throw bad_input(path + ": a " + std::to_string(std::max<std::int64_t>(w, 0)) + " x " +
                            std::to_string(std::max<std::int64_t>(h, 0)) + " image; a table is 1 to " +
                            std::to_string(max_side) + " texels a side");
        const std::size_t channels = exr_channels(path, file.header().channels());
        const bool half = file.header().channels().begin().channel().type == Imf::HALF;
        // OpenEXR 3.1 reads an uncompressed scanline shorter than the data window says past its
        // end (uninitialised memory, no error): check their sizes first
        if (file.header().compression() == Imf::NO_COMPRESSION && !file.header().hasTileDescription())
            for (int y = dw.min.y; y <= dw.max.y; ++y) {
                const char* p = nullptr;
                int size = 0;
                file.rawPixelData(y, p, size);
                if (std::int64_t(size) < w * std::int64_t(channels * (half ? 2 : 4)))
                    throw bad_input(path + ": truncated or corrupt OpenEXR (scanline " + std::to_string(y) + " holds " +
                                    std::to_string(size) + " bytes, too few for " + std::to_string(w) + " texels)");
            }

        // read in strips, so that a file cut short fails before the whole image is allocated
        decoded_lut d;
        d.image.width = std::size_t(w), d.image.height = std::size_t(h), d.image.channels = channels;
        const std::size_t strip = 64, row = std::size_t(w) * channels;
        std::vector<float> buf(strip * row);
        for (std::int64_t y0 = 0; y0 < h; y0 += std::int64_t(strip)) {
            const std::int64_t n = std::min<std::int64_t>(std::int64_t(strip), h - y0);
            Imf::FrameBuffer fb;
            for (std::size_t c = 0; c < channels; ++c)
                fb.insert(exr_names[channels - 1][c],
                          Imf::Slice::Make(Imf::FLOAT, buf.data() + c, Imath::V2i(dw.min.x, dw.min.y + int(y0)), w, n,
                                           sizeof(float) * channels, sizeof(float) * row));
            file.setFrameBuffer(fb);
            file.readPixels(dw.min.y + int(y0), dw.min.y + int(y0 + n - 1));
            d.image.data.insert(d.image.data.end(), buf.begin(), buf.begin() + n * std::int64_t(row));
        }
        d.format = half ? "exr-half" : "exr-float";
        // half: 11 significant bits, and below the normal range a spacing of 2^-24 (half of it absolute)
        d.relative = half ? std::ldexp(1.0, -11) : std::ldexp(1.0, -24);
        d.absolute = half ? std::ldexp(1.0, -25) : 1e-45;
        return d;
    } catch (const bad_input&) {
        throw;
    } catch (const std::exception& e) {  // Iex::BaseExc is a std::exception
        throw bad_input(path + ": truncated or corrupt OpenEXR (" + e.what() + ")");
    }
}

bool is_c_identifier(const std::string& s) {
    static const std::set<std::string> keywords = {
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum", "extern",
        "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return", "short", "signed",
        "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void", "volatile", "while", "_Alignas",
        "_Alignof", "_Atomic", "_Bool", "_Complex", "_Generic", "_Imaginary", "_Noreturn", "_Static_assert", "_Thread_local"};
    const auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (s.empty() || !alpha(s[0]) || keywords.count(s)) return false;
    return std::all_of(s.begin(), s.end(), [&](char c) { return alpha(c) || (c >= '0' && c <= '9'); });
}

}  // namespace

std::string encode_png16(const lut_image& im) {
    check_image(im);
    const std::size_t out_ch = im.channels == 2 ? 3 : im.channels;  // (A, B) goes to R, G with B = 0
    const int color = out_ch == 1 ? PNG_COLOR_TYPE_GRAY : out_ch == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA;
    const std::size_t row_bytes = im.width * out_ch * 2;
    std::vector<png_byte> pixels(im.height * row_bytes, 0);
    for (std::size_t t = 0; t < im.width * im.height; ++t)
        for (std::size_t c = 0; c < im.channels; ++c) {
            const double v = im.data[t * im.channels + c];
            const long q = std::isnan(v) ? 0 : std::lround(std::clamp(v, 0.0, 1.0) * 65535);
            png_byte* p = &pixels[(t * out_ch + c) * 2];
            p[0] = png_byte(q >> 8), p[1] = png_byte(q & 0xff);
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
    const bool ok = write_png(png, info, png_uint_32(im.width), png_uint_32(im.height), color, rows.data());
    png_destroy_write_struct(&png, &info);
    if (!ok) throw std::runtime_error(std::string("libpng: ") + io.message);
    return out;
}

std::string encode_exr(const lut_image& im, bool half) {
    check_image(im);
    memory_ostream os;
    if (half) write_exr<Imath::half>(os, im, Imf::HALF);
    else write_exr<float>(os, im, Imf::FLOAT);
    return std::move(os.bytes);  // the OutputFile is closed: its offset table is written
}

std::string encode_c_header(const lut_image& im, const std::string& name, const std::string& comment) {
    check_image(im);
    if (!is_c_identifier(name)) throw std::invalid_argument("C header: \"" + name + "\" is not a C identifier");
    std::string s = "#pragma once\n";
    for (std::size_t b = 0; b < comment.size();) {
        const std::size_t e = std::min(comment.find('\n', b), comment.size());
        std::string line = comment.substr(b, e - b);
        line.erase(line.find_last_not_of(" \t") + 1);
        if (!line.empty() && line.back() == '\\') line += '.';  // a backslash would join the next line to the comment
        s += line.empty() ? "//\n" : "// " + line + "\n";
        b = e + 1;
    }
    s += "static const float " + name + "[" + std::to_string(im.height) + "][" + std::to_string(im.width) + "][" +
         std::to_string(im.channels) + "] = {\n";
    char buf[48];
    for (std::size_t j = 0; j < im.height; ++j) {
        s += "    {";
        for (std::size_t i = 0; i < im.width; ++i) {
            s += i ? ", {" : "{";
            for (std::size_t c = 0; c < im.channels; ++c) {
                // the float's own value to 9 digits reads back as that float
                const float v = float(im.at(j, i, c));
                if (!std::isfinite(v))
                    throw std::invalid_argument("C header: value " + std::to_string(im.at(j, i, c)) + " is not a finite float");
                std::snprintf(buf, sizeof buf, "%.9g", double(v));
                s += (c ? ", " : "") + std::string(buf);
                if (!std::strpbrk(buf, ".e")) s += ".";  // "1f" is no C literal; "1.f" is
                s += "f";
            }
            s += "}";
        }
        s += j + 1 < im.height ? "},\n" : "}\n";
    }
    return s + "};\n";
}

decoded_lut read_lut_image(const std::string& path) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) throw bad_input(path + ": cannot be read");
    // the signature first, so that a device or a large file of another kind is not read whole
    std::string bytes(8, '\0');
    bytes.resize(std::fread(&bytes[0], 1, 8, f.get()));
    static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char exr_sig[4] = {0x76, 0x2f, 0x31, 0x01};
    const bool png = bytes.size() == 8 && std::memcmp(bytes.data(), png_sig, 8) == 0;
    const bool exr = bytes.size() >= 4 && std::memcmp(bytes.data(), exr_sig, 4) == 0;
    if (png || exr) {
        char buf[1 << 16];
        while (std::size_t n = std::fread(buf, 1, sizeof buf, f.get())) bytes.append(buf, n);
    }
    if (std::ferror(f.get())) throw bad_input(path + ": cannot be read");  // a folder, an I/O error
    if (png) return read_png(path, bytes);
    if (exr) return read_exr(path, bytes);
    throw bad_input(path + ": not a PNG or OpenEXR image, nor a CSV table (a file named .csv): the LUT formats normzoo reads");
}

}  // namespace verify
