// Radiance HDR read (hdr.hpp), as Radiance's own readers define it: getheader() ends the header at
// its first empty line, fgetsresolu() reads the resolution line, freadscan() the run-length
// encoded scanlines and colr_color() the values.
#include "hdr.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "../args.hpp"

namespace verify {
namespace {

constexpr std::size_t max_header_bytes = 1 << 20;

// A header line's numbers: `count` finite reals after NAME=, positive where `positive`.
std::vector<double> numbers_of(const std::string& path, const std::string& line, std::size_t at, std::size_t count,
                               bool positive) {
    std::istringstream in(line.substr(at));
    std::vector<double> v;
    std::string word;
    while (in >> word) {
        char* end = nullptr;
        const double x = std::strtod(word.c_str(), &end);
        if (*end != '\0' || !std::isfinite(x) || (positive && !(x > 0)))
            throw bad_input(path + ": Radiance HDR header line '" + line + "': '" + word + "' is not a " +
                            (positive ? "positive " : "") + "number");
        v.push_back(x);
    }
    if (v.size() != count)
        throw bad_input(path + ": Radiance HDR header line '" + line + "' gives " + std::to_string(v.size()) + " numbers, not " +
                        std::to_string(count));
    return v;
}

// One line of the header (after "#?"): FORMAT, EXPOSURE, GAMMA, PRIMARIES and COLORCORR are read;
// comments and the other variables (SOFTWARE=, VIEW=, commands) say nothing about the values.
void header_line(const std::string& path, const std::string& line, decoded_lut& d) {
    const auto starts = [&](const char* key) { return line.rfind(key, 0) == 0; };
    if (starts("FORMAT=")) {
        const std::string f = line.substr(7, line.find_last_not_of(" \t") - 6);
        if (f == "32-bit_rle_xyze") throw bad_input(path + ": Radiance HDR FORMAT=32-bit_rle_xyze (CIE XYZ) is not read; a table is RGBE");
        if (f != "32-bit_rle_rgbe") throw bad_input(path + ": Radiance HDR FORMAT=" + f + " is not 32-bit_rle_rgbe");
    } else if (starts("EXPOSURE=")) {
        d.exposure *= numbers_of(path, line, 9, 1, true)[0];
    } else if (starts("GAMMA=")) {
        d.colour.gamma = 1 / numbers_of(path, line, 6, 1, true)[0];
        d.colour.declared = colour_declaration::kind::gamma;
    } else if (starts("PRIMARIES=")) {
        const auto p = numbers_of(path, line, 10, 8, false);  // red, green, blue, white x y
        d.colour.chromaticities = std::array<double, 8>{p[6], p[7], p[0], p[1], p[2], p[3], p[4], p[5]};
    } else if (starts("COLORCORR=")) {
        for (const double c : numbers_of(path, line, 10, 3, true))
            if (c != 1) throw bad_input(path + ": Radiance HDR header line '" + line + "': a colour correction of its channels is not read");
    }
}

// The header from "#?" to its first empty line; returns where the resolution line starts.
std::size_t read_header(const std::string& path, const std::string& b, decoded_lut& d) {
    if (b.compare(0, 2, "#?") != 0) throw bad_input(path + ": not a Radiance HDR file (its first line starts with #?)");
    for (std::size_t at = b.find('\n');;) {  // at: the end of the line before
        const std::size_t next = at == std::string::npos ? at : b.find('\n', at + 1);
        if (next == std::string::npos || next > max_header_bytes)
            throw bad_input(path + ": Radiance HDR truncated: its header has no end (an empty line)");
        std::string line = b.substr(at + 1, next - at - 1);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) return next + 1;
        header_line(path, line, d);
        at = next;
    }
}

// The resolution line: "-Y H +X W", H and W decimal, 1 to max_side.
std::size_t read_resolution(const std::string& path, const std::string& b, std::size_t at, std::size_t& w, std::size_t& h) {
    const std::size_t end = b.find('\n', at);
    if (end == std::string::npos || end - at > 64) throw bad_input(path + ": Radiance HDR truncated: no resolution line");
    std::string line = b.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // four words, one space apart: a sign and an axis, a count, a sign and the other axis, a count
    std::vector<std::string> words;
    for (std::size_t k = 0; k <= line.size();) {
        const std::size_t e = std::min(line.find(' ', k), line.size());
        words.push_back(line.substr(k, e - k));
        k = e + 1;
    }
    const auto axis = [](const std::string& a) { return a.size() == 2 && (a[0] == '-' || a[0] == '+') && (a[1] == 'X' || a[1] == 'Y'); };
    const auto count = [](const std::string& n) {
        return !n.empty() && n.size() <= 9 && n.find_first_not_of("0123456789") == std::string::npos;
    };
    if (words.size() != 4 || !axis(words[0]) || !count(words[1]) || !axis(words[2]) || !count(words[3]) || words[0][1] == words[2][1])
        throw bad_input(path + ": Radiance HDR resolution line '" + line + "' is not of the form -Y H +X W");
    if (words[0] != "-Y" || words[2] != "+X")
        throw bad_input(path + ": Radiance HDR resolution line '" + line + "' orders its pixels otherwise than -Y H +X W "
                        "(rows top to bottom, pixels left to right), the only order read");
    const std::size_t n1 = std::stoul(words[1]), n2 = std::stoul(words[3]);
    if (n1 == 0 || n2 == 0 || n1 > max_side || n2 > max_side)
        throw bad_input(path + ": Radiance HDR image of " + std::to_string(n2) + " x " + std::to_string(n1) + "; a table is 1 to " +
                        std::to_string(max_side) + " texels a side");
    h = n1, w = n2;
    return end + 1;
}

// Radiance's old run-length encoding: a pixel 1 1 1 n repeats the one before (oldreadcolrs()).
bool old_rle(const std::string& b, std::size_t at) { return b[at] == 1 && b[at + 1] == 1 && b[at + 2] == 1; }
const char* const old_rle_refused =
    "the old run-length encoding (a pixel 1 1 1 n repeating the one before) is not read; Radiance's ra_rgbe "
    "rewrites the file in the current one";

// One scanline's 4 w bytes (R, G, B, E per pixel) into scan; returns where the next starts.
std::size_t read_scanline(const std::string& path, const std::string& b, std::size_t at, std::size_t w, std::size_t y,
                          std::vector<std::uint8_t>& scan) {
    const auto bad = [&](const std::string& what) {
        return bad_input(path + ": Radiance HDR scanline " + std::to_string(y) + ": " + what);
    };
    const auto u = [&](std::size_t k) { return std::uint8_t(b[k]); };
    if (w >= 8 && w <= 0x7fff && b.size() - at >= 4 && u(at) == 2 && u(at + 1) == 2 && !(u(at + 2) & 0x80)) {
        const std::size_t length = std::size_t(u(at + 2)) << 8 | u(at + 3);
        if (length != w) throw bad("run-length encoded for " + std::to_string(length) + " pixels, the width is " + std::to_string(w));
        at += 4;
        for (std::size_t c = 0; c < 4; ++c)  // four planes: R, G, B, E
            for (std::size_t x = 0; x < w;) {
                if (at >= b.size()) throw bad("truncated");
                const std::size_t code = u(at++);
                const bool run = code > 128;
                const std::size_t n = run ? code & 127 : code;  // a literal of 0 is nothing, as in Radiance
                if (n > w - x) throw bad("a run of " + std::to_string(n) + " at pixel " + std::to_string(x) + " overruns the width");
                if ((run ? 1 : n) > b.size() - at) throw bad("truncated");
                for (std::size_t k = 0; k < n; ++k, ++x) scan[4 * x + c] = run ? u(at) : u(at + k);
                at += run ? 1 : n;
            }
        return at;
    }
    for (std::size_t x = 0; x < w; ++x, at += 4) {  // flat: 4 bytes a pixel
        if (b.size() - at < 4) throw bad("truncated");
        if (old_rle(b, at)) throw bad(old_rle_refused);
        for (std::size_t c = 0; c < 4; ++c) scan[4 * x + c] = u(at + c);
    }
    return at;
}

// The fewest bytes a scanline of w pixels takes: flat, or run-length encoded in runs of 127.
std::size_t least_scanline_bytes(std::size_t w) {
    return w >= 8 && w <= 0x7fff ? std::min(4 * w, 4 + 4 * 2 * ((w + 126) / 127)) : 4 * w;
}

}  // namespace

decoded_lut read_hdr(const std::string& path, const std::string& b) {
    decoded_lut d;
    d.colour.declared = colour_declaration::kind::linear;  // radiance, unless GAMMA= says otherwise
    std::size_t at = read_header(path, b, d), w = 0, h = 0;
    at = read_resolution(path, b, at, w, h);
    if (h * least_scanline_bytes(w) > b.size() - at) {
        // an old run-length encoded file is shorter than a flat one: say so rather than "truncated"
        const bool rle = w >= 8 && w <= 0x7fff && b.size() - at >= 2 && b[at] == 2 && b[at + 1] == 2;
        for (std::size_t p = at; !rle && p + 4 <= b.size(); p += 4)
            if (old_rle(b, p)) throw bad_input(path + ": Radiance HDR: " + old_rle_refused);
        throw bad_input(path + ": Radiance HDR truncated: " + std::to_string(w) + " x " + std::to_string(h) + " pixels cannot fit in " +
                        std::to_string(b.size() - at) + " bytes");
    }
    d.image.width = w, d.image.height = h, d.image.channels = 3;
    d.image.data.reserve(w * h * 3);
    d.precision.reserve(w * h * 3);
    std::vector<std::uint8_t> scan(4 * w);
    for (std::size_t y = 0; y < h; ++y) {
        at = read_scanline(path, b, at, w, y, scan);
        for (std::size_t x = 0; x < w; ++x) {
            const int e = scan[4 * x + 3];
            // colr_color(): (c + 0.5) 2^(E - 136); E = 0 is 0, which writers store for values below
            // 1e-32 (setcolr())
            const double step = e ? std::ldexp(1.0, e - 136) : 0;
            for (std::size_t c = 0; c < 3; ++c) {
                d.image.data.push_back(e ? (scan[4 * x + c] + 0.5) * step : 0.0);
                d.precision.push_back(e ? step : 1e-32);
            }
        }
    }
    if (at != b.size())
        throw bad_input(path + ": Radiance HDR: " + std::to_string(b.size() - at) + " bytes follow the last scanline");
    d.format = "hdr";
    d.encoding = value_encoding::rgbe;
    d.orientation = "-Y H +X W";
    return d;
}

}  // namespace verify
