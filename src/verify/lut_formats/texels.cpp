// Packed texels and their numbers (texels.hpp).
#include "texels.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace verify {

const char* encoding_name(value_encoding e) {
    switch (e) {
        case value_encoding::unorm8: return "unorm8";
        case value_encoding::unorm16: return "unorm16";
        case value_encoding::half: return "half";
        case value_encoding::float32: return "float";
        case value_encoding::rgbe: return "rgbe";
        case value_encoding::decimal_text: return "decimal-text";
        case value_encoding::hex_integer: return "hex-integer";
    }
    return "?";
}

const char* colour_name(colour_declaration::kind k) {
    switch (k) {
        case colour_declaration::kind::none: return "none";
        case colour_declaration::kind::srgb: return "srgb";
        case colour_declaration::kind::gamma: return "gamma";
        case colour_declaration::kind::icc: return "icc";
        case colour_declaration::kind::linear: return "linear";
    }
    return "?";
}

double half_to_double(std::uint16_t bits) {
    const double sign = bits & 0x8000 ? -1.0 : 1.0;
    const int exponent = bits >> 10 & 0x1f, mantissa = bits & 0x3ff;
    if (exponent == 0x1f) return mantissa ? std::numeric_limits<double>::quiet_NaN() : sign * HUGE_VAL;
    if (exponent == 0) return sign * std::ldexp(double(mantissa), -24);
    return sign * std::ldexp(double(mantissa | 0x400), exponent - 25);
}

std::uint16_t double_to_half(double v) {
    const std::uint16_t sign = std::signbit(v) ? 0x8000 : 0;
    if (std::isnan(v)) return 0x7e00;
    const double a = std::abs(v);
    if (a == 0) return sign;
    if (a >= 65520) return sign | 0x7c00;  // at and beyond the midpoint to 2^16: infinity
    // spacing 2^(e-10) for a in [2^e, 2^(e+1)), e >= -14; 2^-24 below (subnormals)
    int e = 0;
    std::frexp(a, &e);                       // a in [2^(e-1), 2^e)
    const int scale = std::max(e - 1, -14) - 10;
    const double q = std::nearbyint(std::ldexp(a, -scale));  // the current mode: to nearest, ties to even
    // q steps of 2^scale: subnormal (q < 1024 at scale -24) or normal, q in [1024, 2048]
    if (scale == -24 && q < 1024) return sign | std::uint16_t(q);
    const int biased = scale + 25 + (q == 2048 ? 1 : 0);
    const std::uint16_t m = std::uint16_t(q == 2048 ? 0 : int(q) - 1024);
    if (biased >= 31) return sign | 0x7c00;
    return std::uint16_t(sign | biased << 10 | m);
}

double float_to_double(std::uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, 4);
    return double(f);
}

std::uint32_t double_to_float(double v) {
    // beyond the largest float a conversion is undefined: the rounding there, done here (values up
    // to half a float ulp past it round down to it, the others to infinity)
    constexpr double largest = std::numeric_limits<float>::max(), past = largest + 0x1p103;
    if (std::abs(v) > largest) v = std::abs(v) < past ? std::copysign(largest, v) : std::copysign(HUGE_VAL, v);
    const float f = float(v);
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    return bits;
}

std::size_t value_bytes(value_encoding e) {
    return e == value_encoding::unorm8 ? 1 : e == value_encoding::float32 ? 4 : 2;
}

void decode_values(const char* p, std::size_t count, value_encoding e, std::vector<double>& out) {
    const auto byte = [&](std::size_t k) { return std::uint32_t(std::uint8_t(p[k])); };
    for (std::size_t k = 0; k < count; ++k) {
        if (e == value_encoding::unorm8) out.push_back(byte(k) / 255.0);
        else if (e == value_encoding::unorm16) out.push_back((byte(2 * k) | byte(2 * k + 1) << 8) / 65535.0);
        else if (e == value_encoding::half) out.push_back(half_to_double(std::uint16_t(byte(2 * k) | byte(2 * k + 1) << 8)));
        else out.push_back(float_to_double(byte(4 * k) | byte(4 * k + 1) << 8 | byte(4 * k + 2) << 16 | byte(4 * k + 3) << 24));
    }
}

void encode_values(const std::vector<double>& values, value_encoding e, std::string& out) {
    for (const double v : values) {
        const double unit = std::isnan(v) ? 0 : std::clamp(v, 0.0, 1.0);
        if (e == value_encoding::unorm8) out += char(std::lround(unit * 255));
        else if (e == value_encoding::unorm16) put16(out, std::uint32_t(std::lround(unit * 65535)));
        else if (e == value_encoding::half) put16(out, double_to_half(v));
        else put32(out, double_to_float(v));
    }
}

void check_image(const lut_image& im) {
    constexpr std::size_t max_int = std::numeric_limits<int>::max();
    if (im.channels < 1 || im.channels > 4 || im.width == 0 || im.height == 0 || im.width > max_int ||
        im.height > max_int || im.data.size() != im.width * im.height * im.channels)
        throw std::invalid_argument("lut image: " + std::to_string(im.width) + " x " + std::to_string(im.height) + " x " +
                                    std::to_string(im.channels) + " with " + std::to_string(im.data.size()) +
                                    " values is not an image of 1 to 4 channels");
}

void set_storage_tolerance(decoded_lut& d, value_encoding e) {
    d.encoding = e;
    d.relative = 0;
    if (e == value_encoding::unorm8) d.absolute = 0.5 / 255;
    else if (e == value_encoding::unorm16) d.absolute = 0.5 / 65535;
    else if (e == value_encoding::half) d.relative = std::ldexp(1.0, -11), d.absolute = std::ldexp(1.0, -25);
    else d.relative = std::ldexp(1.0, -24), d.absolute = 1e-45;
}

decoded_lut decoded_slice(const decoded_lut& d, std::size_t width, std::size_t height, std::size_t k) {
    decoded_lut s = d;
    const std::size_t values = width * height * d.image.channels;
    const auto from = std::ptrdiff_t(k * values), to = std::ptrdiff_t((k + 1) * values);
    s.image.width = width, s.image.height = height;
    s.image.data.assign(d.image.data.begin() + from, d.image.data.begin() + to);
    if (!d.precision.empty()) s.precision.assign(d.precision.begin() + from, d.precision.begin() + to);
    return s;
}

}  // namespace verify
