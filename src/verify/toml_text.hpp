// TOML text (scene files, the headers of plain shader files) parsed with toml++, safely.
#pragma once
#include <string>

#include <toml++/toml.h>

namespace verify {

// Parses `text` (read from `path`) or throws bad_input "PATH:LINE: what is wrong", the line that of
// `path` (a header that starts at the file's first line keeps them). Non-ASCII bytes are refused
// before toml++ sees the text: Debian 12's toml++ 3.3.0 reaches __builtin_unreachable (undefined
// behaviour) on some non-ASCII characters, in bare text and in strings alike (upstream
// marzer/tomlplusplus issues 190 and 295, fixed after 3.3.0), and our inputs need none.
toml::table parse_ascii_toml(const std::string& text, const std::string& path, const std::string& what);

}  // namespace verify
