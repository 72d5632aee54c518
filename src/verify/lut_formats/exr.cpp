// OpenEXR through the OpenEXR library, in memory (exr.hpp).
#include "exr.hpp"

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
#include <cstdint>
#include <cstring>
#include <set>
#include <vector>

#include "../args.hpp"
#include "texels.hpp"

namespace verify {
namespace {

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

}  // namespace

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
        d.encoding = half ? value_encoding::half : value_encoding::float32;
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

std::string encode_exr(const lut_image& im, bool half) {
    check_image(im);
    memory_ostream os;
    if (half) write_exr<Imath::half>(os, im, Imf::HALF);
    else write_exr<float>(os, im, Imf::FLOAT);
    return std::move(os.bytes);  // the OutputFile is closed: its offset table is written
}

}  // namespace verify
