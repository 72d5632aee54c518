// What source_array.cpp finds in a source file and source_values.cpp reads: an initialiser's
// numbers or string, and the shape the file gives it.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "decoded.hpp"
#include "source_array.hpp"
#include "source_tokens.hpp"

namespace verify {

// A number of an array as written: its text (into the file's), the sign before it, its line.
struct number_ref {
    std::string_view text;
    char sign;  // '-', '+' or 0
    std::size_t line;
    std::string written() const { return (sign ? std::string(1, sign) : std::string()) + std::string(text); }
};

// An initialiser found: a number array or a string.
struct found_array {
    std::string name, element_type;
    std::vector<std::string> dims;  // declared, [H][W][C] as written: a number, a name, or "" (none, or an expression)
    std::vector<number_ref> numbers;
    std::string text;                // a string's contents (strings joined by + or side by side)
    std::size_t line = 0;            // the declaration's
    bool is_string = false;
};

// The PNG a string holds in base64 (RFC 4648, section 4: the standard alphabet, padded), plain
// or as a data: URI (RFC 2397) marked ;base64; nothing if the string is not one.
std::optional<std::string> base64_png(const std::string& text);

// The array's values (decimals, or integers where a hex is among them) in the shape the request,
// its declaration or the file gives it (source_array.hpp, read_source_array).
decoded_lut array_values(const std::string& path, const std::vector<source_token>& tokens, const found_array& a,
                         const array_request& request);

}  // namespace verify
