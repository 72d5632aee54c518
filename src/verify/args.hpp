// Strict parsing of the comma-separated parameter lists (README, "Command reference").
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace verify {

// Bad input: the message names the option and the bad value; the run exits 2.
struct bad_input : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "0,2.5,1e6" -> {0, 2.5, 1e6}. Every item must be a finite real in [min, max] (or [min, max)
// with max_open) written in full (no empty items, no trailing junk, no nan/inf, nothing that
// overflows a double).
std::vector<double> parse_real_list(const std::string& option, const std::string& text, double min, double max,
                                    bool max_open = false);

// "a,b" -> {"a", "b"}, each one of `known` (the message lists them).
std::vector<std::string> parse_name_list(const std::string& option, const std::string& text,
                                         const std::vector<std::string>& known);

// "12345" -> 12345: decimal digits only (no sign, no space, no exponent), in [min, max].
std::uint64_t parse_count(const std::string& option, const std::string& text, std::uint64_t min, std::uint64_t max);

}  // namespace verify
