// A scene's material given as shader code (docs/reference.md, "[[materials]]"): its file and
// parameters, and how it is built, sampled and held, as --brdf's options take them. Apart from
// scene.cpp, which reads the other kinds of material.
#include <filesystem>
#include <string>
#include <vector>

#include "brdf_file/shader_screen.hpp"
#include "brdf_textures.hpp"
#include "scene.hpp"
#include "scene_keys.hpp"

namespace verify {

using namespace scene_keys;

// textures = { NAME = "FILE" }: each sampler's table, relative to the scene's folder, as
// --texture NAME=FILE binds it (docs/brdf-code.md#textures).
static void read_textures(const toml::node& n, const place& p, const std::filesystem::path& base, scene_material& mat) {
    const auto* table = n.as_table();
    if (!table) p.fail("must be a table of sampler names and files, { dfgLut = \"dfg.png\" }");
    for (const auto& [key, node] : *table) {
        const place q = p.at(std::string(key.str()), &node);
        const std::filesystem::path f(text(node, q));
        const auto resolved = f.is_absolute() ? f : base / f;
        std::error_code ec;
        if (f.empty() || !std::filesystem::is_regular_file(resolved, ec)) q.fail("no such file: " + resolved.string());
        const std::string option = std::string(key.str()) + "=" + resolved.string();
        try {
            (void)parse_texture_option(option);
        } catch (const bad_input& e) {
            q.fail(e.what());
        }
        mat.brdf_textures.push_back(option);
    }
}

// How a material given as code is built and held, as --define, --include-dir (relative to the
// scene's folder) and --fixed take it (docs/brdf-code.md#the-preprocessor).
static void read_brdf_build(const toml::table& t, const place& p, const std::filesystem::path& base, scene_material& mat) {
    if (const auto* d = t.get("defines")) {
        const place q = p.at("defines", d);
        mat.brdf_defines = string_list(*d, q);
        for (const auto& def : mat.brdf_defines) {
            try {
                check_define(def);
            } catch (const bad_input& e) {
                q.fail(e.what());
            }
        }
    }
    if (const auto* d = t.get("include_dirs")) {
        const place q = p.at("include_dirs", d);
        for (const auto& dir : string_list(*d, q)) {
            const std::filesystem::path f(dir);
            const auto resolved = f.is_absolute() ? f : base / f;
            std::error_code ec;
            if (dir.empty() || !std::filesystem::is_directory(resolved, ec)) q.fail("no such folder: " + resolved.string());
            mat.brdf_include_dirs.push_back(resolved.string());
        }
    }
    if (const auto* x = t.get("textures")) read_textures(*x, p.at("textures", x), base, mat);
    if (const auto* l = t.get("texture_layout")) {
        const place q = p.at("texture_layout", l);
        if (!t.get("textures")) q.fail("a layout without textures: it says how their files are read");
        mat.brdf_layout = text(*l, q);
        try {
            (void)parse_texture_layout(mat.brdf_layout);
        } catch (const bad_input& e) {
            q.fail(e.what());
        }
    }
    if (const auto* f = t.get("fixed")) {
        const place q = p.at("fixed", f);
        const std::string d = text(*f, q);
        if (d != "light" && d != "view") q.fail("'" + d + "' is not light or view (the direction the albedo holds)");
        mat.brdf_fixed_view = d == "view";
    }
}

// A material given as shader code: brdf = "file" and params = { NAME = value | [LO, HI] | [R, G, B] }.
void read_brdf_material(const toml::table& t, const place& p, const toml::node* b, const std::string& path,
                               scene_material& mat) {
    const place q = p.at("brdf", b);
    mat.brdf_written = text(*b, q);
    if (mat.brdf_written.empty()) q.fail("the path is empty");
    const std::filesystem::path base = std::filesystem::path(path).parent_path();
    const std::filesystem::path file(mat.brdf_written);
    mat.brdf_path = (file.is_absolute() ? file : base / file).string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(mat.brdf_path, ec)) q.fail("no such file: " + mat.brdf_path);
    mat.model = "brdf";
    read_brdf_build(t, p, base, mat);
    const auto* params = t.get("params");
    if (!params) return;
    const auto* table = params->as_table();
    if (!table) p.at("params", params).fail("must be a table of parameter values");
    for (const auto& [key, node] : *table) {
        const std::string name(key.str());
        const place k = p.at("params." + name, &node);
        auto num = [&](const toml::node& n) {
            if (!(n.is_integer() || n.is_floating_point())) k.fail("must be a number, a bool, [LO, HI] or [R, G, B]");
            return exact_number(n, k).text();
        };
        if (const auto* flag = node.as_boolean()) {
            mat.brdf_params.push_back(name + "=" + (flag->get() ? "1" : "0"));
        } else if (const auto* a = node.as_array()) {
            if (a->size() == 2) mat.brdf_params.push_back(name + "=" + num(*a->get(0)) + ".." + num(*a->get(1)));
            else if (a->size() == 3) mat.brdf_params.push_back(name + "=" + num(*a->get(0)) + "," + num(*a->get(1)) + "," + num(*a->get(2)));
            else k.fail("an array is [LO, HI] (a range) or [R, G, B] (a color)");
        } else {
            mat.brdf_params.push_back(name + "=" + num(node));
        }
    }
}

}  // namespace verify
