// The keys of a scene file (docs/reference.md, "Scene files"): where each is, and its value read
// from toml++ and checked. A bad value throws bad_input "FILE:LINE: key: what is wrong" (exit 2).
// Apart from scene.cpp, which reads the sections and their rules, to keep that file to one subject.
#pragma once
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include <normzoo/decimal.hpp>

#include "args.hpp"

namespace verify::scene_keys {

// Where a node is, for messages: "FILE:LINE: key".
struct place {
    const std::string& file;
    std::string key;
    int line;
    [[noreturn]] void fail(const std::string& what) const {
        throw bad_input(file + ":" + std::to_string(line) + ": " + (key.empty() ? "" : key + ": ") + what);
    }
    place at(const std::string& sub, const toml::node* n) const {
        return {file, key.empty() ? sub : key + "." + sub, n ? static_cast<int>(n->source().begin.line) : line};
    }
};

// While one lives, exact_number reads a number of `toml_text` as the decimal written there, not
// as the double toml++ reads (docs/conventions.md, "Inputs are decimals"). One scene at a time
// per thread.
class written_numbers {
public:
    explicit written_numbers(const std::string& toml_text);
    ~written_numbers();
    written_numbers(const written_numbers&) = delete;
    written_numbers& operator=(const written_numbers&) = delete;

private:
    std::vector<std::string> lines_;
};

// Fails at the first key of t not in `allowed`, listing them.
void only_keys(const toml::table& t, const place& p, const std::set<std::string>& allowed);

double number(const toml::node& n, const place& p);  // finite
normzoo::decimal exact_number(const toml::node& n, const place& p);
std::string text(const toml::node& n, const place& p);
std::string name_text(const toml::node& n, const place& p);  // not empty, one line
std::vector<std::string> string_list(const toml::node& n, const place& p);  // ["A", "B=2"]
std::pair<normzoo::decimal, normzoo::decimal> exact_range(const toml::node& n, const place& p);  // [a, b], a <= b

}  // namespace verify::scene_keys

namespace verify {

struct scene_material;

// A material given as shader code (scene_code.cpp): brdf = "FILE", its params, and how it is
// built, sampled and held (defines, include_dirs, textures, texture_layout, fixed).
void read_brdf_material(const toml::table& t, const scene_keys::place& p, const toml::node* b, const std::string& path,
                        scene_material& mat);

}  // namespace verify
