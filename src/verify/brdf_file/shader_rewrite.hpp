// The translation's passes over a shader's tokens (docs/brdf-code.md#how-the-shader-runs): each
// token's C++ text, then the rewrites that need more than one token (swizzles, arrays, structs,
// HLSL's casts). Every pass keeps each token's newlines, so the file's lines are the C++'s.
#pragma once
#include <set>
#include <string>
#include <vector>

#include "shader_analysis.hpp"

namespace verify {

struct shader_rewriter {
    const shader_source& s;
    const token_list& t;
    const shader_analysis& a;
    std::set<std::string>& swizzles;  // the swizzles written, whose tags the translation declares

    std::vector<std::string> out;  // each token's C++
    std::vector<bool> reference;   // an out or inout parameter's type: & after it

    shader_rewriter(const shader_source& src, const token_list& tokens, const shader_analysis& an, std::set<std::string>& sw);
    // All the passes, then the tokens' C++ joined.
    std::string run();

private:
    bool hlsl() const { return s.lang == shader_source::language::hlsl; }
    bool is_type(std::size_t i) const;
    [[noreturn]] void refuse(std::size_t i, const std::string& what) const;
    void words();
    void remove();
    void arrays();
    void declaration(std::size_t type);
    std::vector<std::string> dims(std::size_t first_bracket, std::size_t& after);
    void sized(std::vector<std::string>& d, std::size_t name, std::size_t after) const;
    std::size_t count_initializer(std::size_t equals) const;
    void swizzle_pass();
    bool written(std::size_t dot, std::size_t word, std::size_t start) const;
    bool out_argument(std::size_t start, std::size_t last) const;
    std::size_t operand_start(std::size_t j) const;
    void structs();
    void casts();
    void precision();  // shader_rewrite_precision.cpp
};

// A shader's name as the C++ names it: new, and, real (the translation's own type), which C++
// reserves, become normzoo_id_new, ...; not (GLSL's function) normzoo_not.
std::string cpp_name(const std::string& w);

// The swizzle a member name is (v.xy, c.rgb, t.st), as its letters' set (0 xyzw, 1 rgba, 2 stpq)
// and components; -1 if the name is not one.
int swizzle_set(const std::string& w);
std::vector<int> swizzle_components(const std::string& w);

}  // namespace verify
