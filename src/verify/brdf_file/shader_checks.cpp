// The refusals of shader_analysis.hpp: uniforms against the header, the BRDF's signature, and
// recursion (docs/brdf-code.md#what-is-supported).
#include <algorithm>
#include <map>

#include "../args.hpp"
#include "shader_analysis.hpp"

namespace verify {

namespace {

[[noreturn]] void refuse(const shader_source& s, int line, const std::string& what) { throw bad_input(s.place(line) + ": " + what); }

bool explorer(const shader_source& s) { return s.path.size() > 5 && s.path.substr(s.path.size() - 5) == ".brdf"; }

// The header's kind of parameter a shading type declares, or none.
enum class kind_of { real, color, boolean, none };
kind_of kind(const std::string& type) {
    if (type == "float" || type == "half" || type == "min16float" || type == "min10float" || type == "float1" || type == "half1")
        return kind_of::real;
    if (type == "vec3" || type == "float3" || type == "half3" || type == "min16float3" || type == "min10float3") return kind_of::color;
    if (type == "bool") return kind_of::boolean;
    return kind_of::none;
}

kind_of kind(const shader_parameter& p) {
    return p.type == shader_parameter::kind::real ? kind_of::real : p.type == shader_parameter::kind::color ? kind_of::color : kind_of::boolean;
}

const char* kind_name(kind_of k) { return k == kind_of::real ? "float" : k == kind_of::color ? "color (a vec3)" : "bool"; }

bool opaque(const std::string& type) {
    for (const char* p : {"sampler", "isampler", "usampler", "Texture", "RWTexture", "Sampler", "image", "Buffer", "StructuredBuffer"})
        if (type.rfind(p, 0) == 0) return true;
    return false;
}

// The lines that declare `name` in the file's header, in its format.
std::string header_lines(const shader_source& s, const std::string& name, kind_of k) {
    if (explorer(s))
        return "add it to the ::begin parameters block, e.g.\n  " +
               std::string(k == kind_of::real ? "float " + name + " 0 1 0.5" : k == kind_of::color ? "color " + name + " 1 1 1" : "bool " + name + " 0");
    std::string lines = "add it to the file's TOML header, e.g.\n// [parameters." + name + "]\n";
    if (k == kind_of::real) lines += "// type = \"float\"\n// range = [0, 1]\n// default = 0.5";
    if (k == kind_of::color) lines += "// type = \"color\"\n// default = [1, 1, 1]";
    if (k == kind_of::boolean) lines += "// type = \"bool\"\n// default = false";
    return lines;
}

// A 2D texture a --texture may bind: GLSL's sampler2D, HLSL's Texture2D (of a float type).
bool texture_2d(const shader_declared& u) {
    if (u.type == "sampler2D") return u.element.empty();
    if (u.type != "Texture2D") return false;
    return u.element.empty() || kind(u.element) != kind_of::none || u.element == "float2" || u.element == "float4" ||
           u.element == "half2" || u.element == "half4" || u.element == "vec2" || u.element == "vec4";
}

// The textures: each one the code samples bound by a --texture, and each --texture naming one
// (docs/brdf-code.md#textures). HLSL's SamplerState is taken whatever it sets: the texture is
// sampled as the filter described there.
bool check_texture(const shader_source& s, const shader_declared& u) {
    if (u.type == "SamplerState" && !u.array) return true;
    if (!texture_2d(u) || u.array) return false;
    if (std::find(s.textures.begin(), s.textures.end(), u.name) == s.textures.end())
        refuse(s, u.line, u.type + (u.element.empty() ? "" : "<" + u.element + ">") + " " + u.name +
                              " is not bound to a table: --texture " + u.name + "=FILE binds it (docs/brdf-code.md#textures)");
    return true;
}

void check_bound_textures(const shader_source& s, const shader_analysis& a) {
    for (const auto& name : s.textures)
        if (std::none_of(a.uniforms.begin(), a.uniforms.end(), [&](const shader_declared& u) { return u.name == name && texture_2d(u) && !u.array; }))
            throw bad_input("--texture " + name + ": " + s.path + " declares no texture " + name +
                            " (uniform sampler2D " + name + "; in GLSL, Texture2D " + name + "; in HLSL) that it could bind");
}

void check_uniforms(const shader_source& s, const shader_analysis& a) {
    for (const auto& u : a.uniforms) {
        if (check_texture(s, u)) continue;
        const auto p = std::find_if(s.parameters.begin(), s.parameters.end(), [&](const shader_parameter& q) { return q.name == u.name; });
        const std::string what = "uniform " + u.name + " (a " + u.type + (u.array ? " array" : "") + ")";
        if (opaque(u.type))
            refuse(s, u.line, what + ": of the textures and samplers, normzoo binds a sampler2D or a Texture2D, with SamplerState "
                                     "(docs/brdf-code.md#textures)");
        if (kind(u.type) == kind_of::none || u.array)
            refuse(s, u.line, what + ": the header's parameters are a float, a bool or a color (a vec3), so normzoo cannot bind it");
        if (p == s.parameters.end())
            refuse(s, u.line, "uniform " + u.name + " is not a parameter of the file; " + header_lines(s, u.name, kind(u.type)));
        if (kind(u.type) != kind(*p))
            refuse(s, u.line, "uniform " + u.name + " is a " + u.type + " here, but the header declares a " + kind_name(kind(*p)) + " (" +
                                  s.path + ":" + std::to_string(p->line) + "): the two must agree");
    }
}

void check_entry(const shader_source& s, const shader_analysis& a, const token_list& t) {
    const std::string shape = s.function + "(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)";
    std::vector<const shader_function*> defs;
    for (const auto& f : a.functions)
        if (f.name == s.function) defs.push_back(&f);
    if (defs.empty()) {
        // a definition the reading above cannot see (one a macro writes) is left to the compilers
        for (std::size_t i = 0; i < t.size(); ++i)
            if (t.is_word(i) && t[i].text == s.function) return;
        refuse(s, 0, "no function " + shape + " (docs/brdf-code.md#files)");
    }
    const auto five = std::find_if(defs.begin(), defs.end(), [](const shader_function* f) { return f->params.size() == 5; });
    const shader_function& f = five == defs.end() ? *defs.front() : **five;
    std::string given;
    for (const auto& p : f.params) given += (given.empty() ? "" : ", ") + p.type + (p.name.empty() ? "" : " " + p.name);
    bool vectors = f.params.size() == 5;
    for (const auto& p : f.params) vectors = vectors && kind(p.type) == kind_of::color && !p.array && p.dir == shader_declared::direction::in;
    if (!vectors)
        refuse(s, f.line, s.function + " takes (" + given + "); normzoo calls it with five vectors, " + shape + " (docs/brdf-code.md#files)");
    const kind_of r = kind(f.return_type);
    if (r != kind_of::real && r != kind_of::color)
        refuse(s, f.line, s.function + " returns " + f.return_type + "; normzoo takes a BRDF that returns a float or a vec3 (float3 in HLSL)" +
                              (f.return_type.find('4') != std::string::npos ? ": return its .rgb" : "") + " (docs/brdf-code.md#files)");
}

// Recursion through the calls that name one function unambiguously (by name and number of
// arguments); an overloaded call is left to glslangValidator's own check, which resolves it.
void check_recursion(const shader_source& s, const shader_analysis& a) {
    const std::size_t n = a.functions.size();
    std::vector<std::vector<std::pair<std::size_t, int>>> edges(n);  // callee, line of the call
    for (std::size_t i = 0; i < n; ++i)
        for (const auto& c : a.functions[i].calls) {
            std::vector<std::size_t> callee;
            for (std::size_t j = 0; j < n; ++j)
                if (a.functions[j].name == c.name && a.functions[j].params.size() == c.arity) callee.push_back(j);
            if (callee.size() == 1) edges[i].push_back({callee[0], c.line});
        }
    std::vector<int> state(n, 0);  // 0 unvisited, 1 on the path, 2 done
    std::vector<std::pair<std::size_t, int>> path;  // function, the line of its call to the next
    auto report = [&](std::size_t back_to, int line) {
        auto from = std::find_if(path.begin(), path.end(), [&](const auto& p) { return p.first == back_to; });
        std::vector<std::pair<std::size_t, int>> cycle(from, path.end());
        cycle.back().second = line;
        const auto& f = a.functions[cycle.front().first];
        std::string chain = f.name;
        for (std::size_t k = 0; k < cycle.size(); ++k) {
            const auto& callee = a.functions[cycle[(k + 1) % cycle.size()].first];
            chain += std::string(k == 0 ? " calls " : ", which calls ") + callee.name + " (" + s.place(cycle[k].second) + ")";
        }
        if (cycle.size() == 1) chain = f.name + " calls itself (" + s.place(line) + ")";
        refuse(s, f.line, "recursion: " + chain + ". A shader's functions may not call themselves, directly or through others: GPU "
                                                  "compilers refuse it (GLSL 4.60, section 6.1; HLSL's compilers alike)");
    };
    // depth first, on a stack of its own: a long chain of calls must not exhaust the process's stack
    for (std::size_t root = 0; root < n; ++root) {
        if (state[root] != 0) continue;
        std::vector<std::pair<std::size_t, std::size_t>> stack{{root, 0}};  // function, next edge
        state[root] = 1;
        while (!stack.empty()) {
            auto& [i, e] = stack.back();
            if (e == edges[i].size()) {
                state[i] = 2;
                stack.pop_back();
                if (!path.empty()) path.pop_back();
                continue;
            }
            const auto [j, line] = edges[i][e++];
            if (state[j] == 1) {
                path.push_back({i, line});
                report(j, line);
            }
            if (state[j] == 0) {
                path.push_back({i, line});
                state[j] = 1;
                stack.push_back({j, 0});
            }
        }
    }
}

}  // namespace

void check_shader(const shader_source& s, const shader_analysis& a, const token_list& t) {
    check_uniforms(s, a);
    check_bound_textures(s, a);
    check_entry(s, a, t);
    check_recursion(s, a);
}

}  // namespace verify
