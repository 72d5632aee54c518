// Strict parsing of the comma-separated parameter lists (docs/command-line.md, "Command reference").
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>

namespace verify {

// Bad input: the message names the option and the bad value; the run exits 2.
struct bad_input : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "0,2.5,1e6" -> the decimals 0, 2.5 and 1e6, each exactly as written (docs/conventions.md,
// "Inputs are decimals"). Every item must be a real in [min, max] (open at max with max_open, at
// min with min_open),
// compared exactly, written in full (no empty items, no trailing junk, no nan/inf), and neither
// overflow nor underflow a double (the records carry it as a number too).
std::vector<normzoo::decimal> parse_decimal_list(const std::string& option, const std::string& text,
                                                 const std::string& min, const std::string& max, bool max_open = false,
                                                 bool min_open = false);

// "a,b" -> {"a", "b"}, each one of `known` (the message lists them).
std::vector<std::string> parse_name_list(const std::string& option, const std::string& text,
                                         const std::vector<std::string>& known);

// "12345" -> 12345: decimal digits only (no sign, no space, no exponent), in [min, max].
std::uint64_t parse_count(const std::string& option, const std::string& text, std::uint64_t min, std::uint64_t max);

// "a,,b" -> {"a", "", "b"}: every item between separators, empty ones (and a trailing one) kept.
std::vector<std::string> split(const std::string& text, char sep);

}  // namespace verify
