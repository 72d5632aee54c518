#include "toml_text.hpp"

#include <algorithm>
#include <sstream>

#include "args.hpp"

namespace verify {

toml::table parse_ascii_toml(const std::string& text, const std::string& path, const std::string& what) {
    if (const auto at = std::find_if(text.begin(), text.end(), [](char c) { return (c & 0x80) != 0; });
        at != text.end()) {
        std::ostringstream os;
        os << path << ":" << 1 + std::count(text.begin(), at, '\n') << ": byte 0x" << std::hex
           << (static_cast<unsigned>(*at) & 0xffu) << " is not ASCII: " << what
           << " is plain ASCII (names and comments too)";
        throw bad_input(os.str());
    }
    try {
        return toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        throw bad_input(path + ":" + std::to_string(e.source().begin.line) + ": malformed TOML: " +
                        std::string(e.description()));
    }
}

}  // namespace verify
