#include "scene.hpp"

#include <muParser.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <normzoo/microfacet/composition.hpp>
#include <normzoo/registry.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

#include "args.hpp"
#include "scene_keys.hpp"
#include "toml_text.hpp"

namespace verify {

using namespace scene_keys;  // place and the readers of a key's value

namespace {

// 2^(10 g + 1) for a gloss g written as a decimal, in 50 digits, kept to 40 significant digits.
// (cpp_bin_float itself, not normzoo's wide: that header brings binary128, which the scene
// fuzzer's clang build does without.)
normzoo::decimal exponent_of_gloss(const normzoo::decimal& g) {
    using fifty = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>, boost::multiprecision::et_off>;
    const fifty n = boost::multiprecision::exp2(10 * g.to<fifty>() + 1);
    return normzoo::decimal(n.str(40, std::ios_base::scientific));
}

// The shader's expression in n, compiled once; evaluated under a lock (muparser parsers are
// not thread-safe), which costs nothing next to the quadrature.
std::function<double(double)> compile(const std::string& expression, const place& p) {
    struct compiled {
        mu::Parser parser;
        double n = 1;
        std::mutex lock;
    };
    auto c = std::make_shared<compiled>();
    try {
        c->parser.DefineVar("n", &c->n);
        c->parser.DefineConst("pi", 3.14159265358979323846);
        c->parser.SetExpr(expression);
        c->parser.Eval();  // parses now: syntax errors and unknown names surface here
    } catch (const mu::Parser::exception_type& e) {
        p.fail("the expression '" + expression + "' does not parse: " + e.GetMsg());
    }
    return [c](double n) {
        std::lock_guard<std::mutex> g(c->lock);
        c->n = n;
        return c->parser.Eval();
    };
}

}  // namespace

// A composition's roughness: exactly one of alpha and r, a range within the bounds of its kind.
static void read_roughness_range(const toml::table& t, const place& p, scene_material& mat) {
    const auto* alpha = t.get("alpha");
    const auto* r = t.get("r");
    if (!alpha == !r) p.fail("a composition takes exactly one of 'alpha' and 'r' (a range [lo, hi])");
    const place q = alpha ? p.at("alpha", alpha) : p.at("r", r);
    const auto [lo, hi] = exact_range(alpha ? *alpha : *r, q);
    const roughness_range range = roughness_range_of(!alpha);
    if (lo < normzoo::decimal(range.min) || hi > normzoo::decimal(range.max))
        q.fail(std::string("must be in [") + range.min + ", " + range.max + "]");
    mat.rough_lo = lo, mat.rough_hi = hi, mat.rough_is_r = r != nullptr;
    mat.range_text = std::string(alpha ? "alpha" : "r") + " [" + lo.text() + ", " + hi.text() + "]";
}

// A composition's f0 and its parts' parameters, each in its range, then checked against the
// parts that read them (docs/reference.md, "[[materials]]").
static void read_part_values(const toml::table& t, const place& p, scene_material& mat) {
    if (const auto* v = t.get("f0")) {
        const place fq = p.at("f0", v);
        const auto f0 = exact_number(*v, fq);
        if (f0 < normzoo::decimal("0") || !(f0 < normzoo::decimal("1"))) fq.fail("must be in [0, 1)");
        mat.parts.f0 = f0;
    }
    for (const auto& q : part_parameters()) {
        const auto* v = t.get(q.name);
        if (!v) continue;
        const place vq = p.at(q.name, v);
        const auto x = exact_number(*v, vq);
        const normzoo::decimal lo(q.min), hi(q.max);
        if ((q.min_open ? !(x > lo) : x < lo) || x > hi) vq.fail(std::string("must be in ") + (q.min_open ? "(" : "[") + q.min + ", " + q.max + "]");
        mat.parts.*q.input = x;
    }
    try {
        check_part_inputs({mat.model}, mat.parts, "");
    } catch (const bad_input& e) {
        // at the line of the key the message is about ("f0 = 0.04: ..."), where there is one
        const std::string what = e.what();
        const std::string key = what.substr(0, what.find_first_of(" =:"));
        if (const auto* v = t.get(key)) p.at(key, v).fail(what);
        p.fail(what);
    }
}

// A composition's baked table (docs/lut.md): `lut`, resolved against the scene's folder, and
// what it holds (`lut_kind`) and indexes (`lut_map`), which need it.
static void read_lut(const toml::table& t, const place& p, const std::string& path, scene_material& mat) {
    if (const auto* v = t.get("lut")) {
        const place lq = p.at("lut", v);
        mat.lut_place = lq.file + ":" + std::to_string(lq.line) + ": " + lq.key;
        const std::string file = text(*v, lq);
        if (file.empty()) lq.fail("the path is empty");
        const std::filesystem::path base = std::filesystem::path(path).parent_path();
        mat.lut_path = (std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : base / file).string();
        std::error_code ec;
        if (!std::filesystem::is_regular_file(mat.lut_path, ec) || !std::ifstream(mat.lut_path, std::ios::binary))
            lq.fail("'" + mat.lut_path + "' is not a file that can be read");
    }
    if (const auto* v = t.get("lut_kind")) {
        mat.lut_kind = text(*v, p.at("lut_kind", v));
        if (mat.lut_kind != "dfg" && mat.lut_kind != "E" && mat.lut_kind != "Eavg")
            p.at("lut_kind", v).fail("'" + mat.lut_kind + "' is not dfg, E or Eavg");
    }
    if (const auto* v = t.get("lut_map")) {
        const std::string m = text(*v, p.at("lut_map", v));
        if (m != "r" && m != "alpha") p.at("lut_map", v).fail("'" + m + "' is not r or alpha");
        mat.lut_map_r = m == "r";
    }
    for (const char* key : {"lut_kind", "lut_map"})  // they describe the table of `lut`
        if (const auto* v = t.get(key); v && mat.lut_path.empty())
            p.at(key, v).fail("it describes the table of 'lut', which is not given");
    if (const auto* v = t.get("lut_map"); v && std::filesystem::path(mat.lut_path).extension() == ".csv")
        p.at("lut_map", v).fail("it is for an image; a CSV names its roughness in its header (alpha or r)");
}

// A material whose model is a composition D/G/F: alpha or r as a range, f0 and the parts'
// parameters, and a baked table.
static void read_composition(const toml::table& t, const place& p, const toml::node* model, const std::string& path,
                      scene_material& mat) {
    try {
        if (normzoo::microfacet::composition::parse(mat.model).transmission)
            p.at("model", model).fail("a scene lights the reflection; '" + mat.model + "' is an albedo for `energy` and `lut`");
    } catch (const std::invalid_argument& e) {
        p.at("model", model).fail(e.what());
    }
    mat.composition = true;
    for (const char* key : {"exponent", "gloss", "normalization", "specular"})
        if (const auto* v = t.get(key))
            p.at(key, v).fail("does not apply to a composition: give its roughness as 'alpha' or 'r' and its F0 as 'f0'");
    read_roughness_range(t, p, mat);
    read_part_values(t, p, mat);
    read_lut(t, p, path, mat);
}

// A BRDF form's or zoo row's exponent range: from `exponent`, or from `gloss` with n = 2^(10 g + 1).
static void read_exponent_range(const toml::table& t, const place& p, scene_material& mat) {
    const auto* exponent = t.get("exponent");
    const auto* gloss = t.get("gloss");
    if (!exponent == !gloss) p.fail("give exactly one of 'exponent' and 'gloss'");
    if (exponent) {
        const place q = p.at("exponent", exponent);
        const auto [lo, hi] = exact_range(*exponent, q);
        if (lo < normzoo::decimal("0") || hi > normzoo::decimal("1e9")) q.fail("exponents must be in [0, 1e9]");
        mat.n_lo = lo, mat.n_hi = hi;
        mat.range_text = "exponent [" + lo.text() + ", " + hi.text() + "]";
    } else {
        const place q = p.at("gloss", gloss);
        const auto [lo, hi] = exact_range(*gloss, q);
        if (lo < normzoo::decimal("0") || hi > normzoo::decimal("1")) q.fail("gloss must be in [0, 1]");
        mat.n_lo = exponent_of_gloss(lo), mat.n_hi = exponent_of_gloss(hi);
        mat.range_text = "gloss [" + lo.text() + ", " + hi.text() + "], n = 2^(10 g + 1)";
    }
    mat.n_min = mat.n_lo.to<double>(), mat.n_max = mat.n_hi.to<double>();
}

// The shader's normalization expression, compiled and sampled over the material's exponent range.
static void read_normalization(const toml::node& v, const place& q, scene_material& mat) {
    mat.normalization = text(v, q);
    mat.shader = compile(*mat.normalization, q);
    // A factor that is inf or NaN makes the run's verdict meaningless: sample the range
    // (both ends and 64 log-spaced exponents; the run then reports any other point).
    const double a = std::log(std::max(mat.n_min, 1e-6)), b = std::log(std::max(mat.n_max, 1e-6));
    std::vector<double> samples{mat.n_min, mat.n_max};
    for (int k = 0; k <= 64 && b > a; ++k) samples.push_back(std::exp(a + (b - a) * k / 64));
    for (double n : samples)
        if (const double f = mat.shader(n); !std::isfinite(f)) {
            std::ostringstream os;
            os << "the expression '" << *mat.normalization << "' is " << f << " at n = " << n
               << ": a normalization must be finite over the range";
            q.fail(os.str());
        }
}

// A material whose model is a BRDF form or a zoo row: none of a composition's keys, a known
// model, its exponent range, its specular and the shader's normalization.
static void read_form_material(const toml::table& t, const place& p, const toml::node* model,
                               const std::vector<std::string>& model_ids, scene_material& mat) {
    std::vector<std::string> composition_keys = {"alpha", "r", "f0", "lut", "lut_kind", "lut_map"};
    for (const auto& q : part_parameters()) composition_keys.emplace_back(q.name);
    for (const auto& key : composition_keys)
        if (const auto* v = t.get(key.c_str()))
            p.at(key, v).fail("applies to a microfacet composition (model = \"D/G/F\"), not to " + mat.model);
    if (std::find(model_ids.begin(), model_ids.end(), mat.model) == model_ids.end()) {
        std::string list_text;
        for (const auto& id : model_ids) list_text += (list_text.empty() ? "" : ", ") + id;
        p.at("model", model).fail("unknown model '" + mat.model + "' (known: " + list_text + ")");
    }
    read_exponent_range(t, p, mat);
    if (const auto* v = t.get("specular")) {
        mat.specular = number(*v, p.at("specular", v));
        if (!(mat.specular >= 0 && mat.specular <= 1)) p.at("specular", v).fail("must be in [0, 1]");
    }
    if (const auto* v = t.get("normalization")) read_normalization(*v, p.at("normalization", v), mat);
}

// One [[materials]] table (docs/reference.md, "[[materials]]"): shader code (`brdf`), a
// composition D/G/F, or a BRDF form or zoo row. Its name is unique among `others`.
static scene_material read_material(const toml::table& t, const place& p, const std::string& path,
                                    const std::vector<scene_material>& others, const std::vector<std::string>& model_ids) {
    scene_material mat;
    const auto* name = t.get("name");
    if (t.get("brdf")) {
        only_keys(t, p, {"name", "brdf", "params", "defines", "include_dirs", "fixed", "textures", "texture_layout"});
    } else {
        std::set<std::string> keys = {"name", "model", "exponent", "gloss", "normalization", "specular", "alpha", "r", "f0", "lut",
                                 "lut_kind", "lut_map"};
        for (const auto& q : part_parameters()) keys.insert(q.name);
        only_keys(t, p, keys);
    }
    if (!name) p.fail("missing key 'name'");
    mat.name = name_text(*name, p.at("name", name));
    for (const auto& other : others)
        if (other.name == mat.name) p.at("name", name).fail("'" + mat.name + "' names two materials");
    if (const auto* b = t.get("brdf")) {
        read_brdf_material(t, p, b, path, mat);
        return mat;
    }
    const auto* model = t.get("model");
    if (!model) p.fail("missing key 'model'");
    mat.model = text(*model, p.at("model", model));
    if (mat.model.find('/') != std::string::npos) read_composition(t, p, model, path, mat);
    else read_form_material(t, p, model, model_ids, mat);
    return mat;
}

// One [[lights]] table (docs/reference.md, "[[lights]]"); its name is unique among `others`.
static scene_light read_light(const toml::table& t, const place& p, const std::vector<scene_light>& others) {
    only_keys(t, p, {"name", "type", "radius", "distance", "tilt_deg"});
    scene_light light;
    const auto* name = t.get("name");
    if (!name) p.fail("missing key 'name'");
    light.name = name_text(*name, p.at("name", name));
    for (const auto& other : others)
        if (other.name == light.name) p.at("name", name).fail("'" + light.name + "' names two lights");
    const auto* type = t.get("type");
    if (!type) p.fail("missing key 'type'");
    light.type = text(*type, p.at("type", type));
    if (light.type != "sphere" && light.type != "disk") p.at("type", type).fail("must be sphere or disk");
    const auto* radius = t.get("radius");
    const auto* distance = t.get("distance");
    if (!radius || !distance) p.fail("missing key '" + std::string(radius ? "distance" : "radius") + "'");
    light.radius_input = exact_number(*radius, p.at("radius", radius));
    light.distance_input = exact_number(*distance, p.at("distance", distance));
    light.radius = light.radius_input.to<double>();
    light.distance = light.distance_input.to<double>();
    if (!(light.radius > 0)) p.at("radius", radius).fail("must be > 0");
    if (!(light.distance > 0)) p.at("distance", distance).fail("must be > 0");
    if (light.type == "sphere" && !(light.radius < light.distance))
        p.at("radius", radius).fail("a sphere's radius must be less than its distance");
    // The tables take r0/r: it must neither overflow nor underflow (the bounds of --ratio).
    if (const double ratio = light.radius / light.distance; !(std::isnormal(ratio) && ratio <= 1e100)) {
        std::ostringstream os;
        os << "radius / distance = " << ratio << " is out of range: r0/r must be from 2.2e-308 (no underflow) to 1e100";
        p.at("radius", radius).fail(os.str());
    }
    if (const auto* v = t.get("tilt_deg")) {
        const place q = p.at("tilt_deg", v);
        light.tilt_input = exact_range(*v, q);
        if (light.tilt_input->first < normzoo::decimal("0") || light.tilt_input->second > normzoo::decimal("180"))
            q.fail("tilts must be in [0, 180]");
        light.tilt_deg = {light.tilt_input->first.to<double>(), light.tilt_input->second.to<double>()};
    }
    return light;
}

// [scene]: its name.
static void read_scene_table(const toml::table& doc, const place& root, scene& s) {
    if (const auto* t = doc.get("scene")) {
        const place p = root.at("scene", t);
        if (!t->is_table()) p.fail("must be a table");
        only_keys(*t->as_table(), p, {"name"});
        if (const auto* n = t->as_table()->get("name")) s.name = name_text(*n, p.at("name", n));
    }
}

// [tolerance] (docs/reference.md, "[tolerance]"): each key in its range.
static void read_tolerance(const toml::table& doc, const place& root, scene& s) {
    if (const auto* t = doc.get("tolerance")) {
        const place p = root.at("tolerance", t);
        if (!t->is_table()) p.fail("must be a table");
        const auto& tt = *t->as_table();
        only_keys(tt, p, {"digits", "albedo", "normalization", "allow_energy_gain"});
        if (const auto* v = tt.get("digits")) {
            s.digits = number(*v, p.at("digits", v));
            if (!(s.digits > 0 && s.digits <= 33)) p.at("digits", v).fail("must be in (0, 33]");
        }
        if (const auto* v = tt.get("albedo")) {
            s.albedo = number(*v, p.at("albedo", v));
            if (!(s.albedo >= 1e-12 && s.albedo <= 1e-2)) p.at("albedo", v).fail("must be in [1e-12, 1e-2]");
        }
        if (const auto* v = tt.get("normalization")) {
            s.normalization = number(*v, p.at("normalization", v));
            if (!(s.normalization > 0)) p.at("normalization", v).fail("must be > 0");
        }
        if (const auto* v = tt.get("allow_energy_gain")) {
            if (!v->is_boolean()) p.at("allow_energy_gain", v).fail("must be true or false");
            s.allow_energy_gain = *v->value<bool>();
        }
    }
}

// Each table of the array `key` ([[materials]], [[lights]]) in order, with its place ("materials[2]").
template <class Read>
static void each_table(const toml::table& doc, const place& root, const std::string& key, Read read) {
    if (const auto* a = doc.get(key)) {
        const auto* list = a->as_array();
        if (!list) root.at(key, a).fail("must be an array of tables, [[" + key + "]]");
        for (std::size_t i = 0; i < list->size(); ++i) {
            const toml::node& node = *list->get(i);
            const place p = root.at(key + "[" + std::to_string(i + 1) + "]", &node);
            if (!node.is_table()) p.fail("must be a table");
            read(*node.as_table(), p);
        }
    }
}

std::vector<std::string> scene_model_ids() {
    std::vector<std::string> ids;
    for (auto id : normzoo::brdf_ids()) ids.emplace_back(id);
    for (auto id : normzoo::zoo_row_ids())
        if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.emplace_back(id);
    return ids;
}

scene load_scene(const std::string& path, const std::vector<std::string>& model_ids) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw bad_input(path + ": cannot read the scene: it is a folder");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw bad_input(path + ": cannot read the scene: " + std::strerror(errno));
    const std::string toml_text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw bad_input(path + ": cannot read the scene: read error");
    return load_scene_text(toml_text, path, model_ids);
}

scene load_scene_text(const std::string& toml_text, const std::string& path, const std::vector<std::string>& model_ids) {
    const toml::table doc = parse_ascii_toml(toml_text, path, "a scene file");
    const written_numbers written(toml_text);
    const place root{path, "", 1};
    only_keys(doc, root, {"scene", "materials", "lights", "tolerance"});
    scene s;
    s.path = path;
    read_scene_table(doc, root, s);
    read_tolerance(doc, root, s);
    each_table(doc, root, "materials", [&](const toml::table& t, const place& p) {
        s.materials.push_back(read_material(t, p, path, s.materials, model_ids));
    });
    each_table(doc, root, "lights", [&](const toml::table& t, const place& p) { s.lights.push_back(read_light(t, p, s.lights)); });
    if (s.materials.empty() && s.lights.empty()) root.fail("the scene has no materials and no lights");
    if (s.name.empty()) s.name = path;
    return s;
}

}  // namespace verify
