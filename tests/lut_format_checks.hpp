// Shared by the tests of the table files (test_lut_formats.cpp, test_lut_arrays.cpp): a sample
// image and the message a bad file gets.
#pragma once
#include <cmath>
#include <string>

#include "args.hpp"
#include "lut_formats/read.hpp"
#include "lut_image.hpp"

namespace lut_format_checks {

// A w x h image of `channels` whose values run over [0, 1], 0 and 1 included.
inline verify::lut_image sample(std::size_t w, std::size_t h, std::size_t channels) {
    verify::lut_image im{w, h, channels, {}};
    for (std::size_t k = 0; k < w * h * channels; ++k)
        im.data.push_back(k == 0 ? 0.0 : k == 1 ? 1.0 : std::fmod(0.123456789 * double(k * k), 1.0));
    return im;
}

inline std::string message_of(const std::string& path) {
    try {
        verify::read_lut_file(path, {});
    } catch (const verify::bad_input& e) {
        return e.what();
    }
    return "(no bad_input)";
}

}  // namespace lut_format_checks
