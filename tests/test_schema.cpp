// The JSON Schemas of docs/schema/ against what they describe: the command's real --json output
// (a few quick runs, every scene of scenes/) and the committed results/*.json, and the scene
// files as their TOML data model; a broken record fails. The validator is tests/schema_validator.hpp
// (docs/reference.md).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "temp_files.hpp"
#include <toml++/toml.h>
#include <vector>

#include "record_keys.hpp"
#include "schema_enums.hpp"
#include "schema_tables.hpp"
#include "schema_validator.hpp"
#include <normzoo/microfacet/composition.hpp>
#include <cstdlib>
#include <stdexcept>
#include <tuple>

namespace fs = std::filesystem;
using normzoo_test::schema_validator;

namespace {

const fs::path source_dir = NORMZOO_SOURCE_DIR;

nlohmann::json read_json(const fs::path& p) {
    std::ifstream in(p);
    REQUIRE(in);
    return nlohmann::json::parse(in);
}

// The command's stdout and exit status (stderr dropped: notes, and failing records' lines).
std::pair<int, std::string> run_verify(const std::string& args) {
    const auto r = normzoo_test::run_shell(std::string(NORMZOO_VERIFY_BIN) + " " + args + " 2>/dev/null");
    return {r.status, r.out};
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (std::size_t i = 0; i < lines.size() && i < 10; ++i) s += lines[i] + "\n";
    return s;
}

const schema_validator& output_schema() {
    static const schema_validator v(read_json(source_dir / "docs/schema/output.schema.json"));
    return v;
}

std::vector<fs::path> files_in(const fs::path& dir, const std::string& extension) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == extension) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// A --brdf run against a composition (docs/materials.md), which adds the table brdf-conformance.
std::string against_run() {
    return "--brdf '" NORMZOO_SOURCE_DIR "/examples/brdfs/ggx-smith-schlick.brdf' --param roughness=0.5 --param f0=0.04 "
           "--theta 30 --against ggx/smith-height-correlated/schlick --map roughness=r --json";
}

// The records a run makes, for the generated key lists (tests/record_keys.hpp): the committed
// results/*.json (the default and the named runs; --check holds them to what a run makes), every
// scene of scenes/ (the keys a scene adds: material, light_name, specular), two BRDF files' (one
// declaring reduced precision: the fp16 keys), one against a composition and two materials'.
// A --brdf run with a texture (docs/brdf-code.md#textures), which adds texture_storage_bound: the
// example that samples a DFG table, bound to one `verify lut` bakes into a folder of its own.
std::string texture_run() {
    static const normzoo_test::temp_dir dir("schema-texture");
    static const bool baked = normzoo_test::run_shell(std::string(NORMZOO_VERIFY_BIN) + " lut --kind dfg --size 8 --format exr --out '" +
                                                      dir.path.string() + "' >/dev/null 2>&1").status == 0;
    REQUIRE(baked);
    return "--brdf '" NORMZOO_SOURCE_DIR "/examples/brdfs/energy-compensated-ggx.glsl' --texture 'dfg=" +
           (dir.path / "lut-dfg-8.exr").string() + "' --fixed view --theta 30 --json";
}

// energy --material (docs/materials.md): a plain material (preserving null) and a compensated white
// metal (preserving true).
std::vector<std::string> material_runs() {
    return {"energy --material gltf --param baseColor=0.8,0.4,0.2 --param metallic=0.5 --param roughness=0.5 --mu 0.5,1 --json",
            "energy --material gltf/kulla-conty --param roughness=0.5 --mu 0.5 --json"};
}

// `seen`, where given, sees each run's arguments, exit status and output.
using run_visitor = std::function<void(const std::string& args, int status, const nlohmann::ordered_json& doc)>;

std::vector<nlohmann::ordered_json> made_records(const run_visitor& seen = {}) {
    std::vector<nlohmann::ordered_json> records;
    auto add = [&](const nlohmann::ordered_json& doc) {
        for (const auto& r : doc.at("records")) records.push_back(r);
    };
    for (const auto& file : files_in(source_dir / "results", ".json")) {
        std::ifstream in(file);
        add(nlohmann::ordered_json::parse(in));
    }
    std::vector<std::string> runs;
    for (const auto& scene : files_in(source_dir / "scenes", ".toml")) runs.push_back("--scene '" + scene.string() + "' --json");
    runs.push_back("--brdf '" NORMZOO_SOURCE_DIR "/examples/brdfs/ward.brdf' --param alpha=0.1..0.5 --steps 2 --theta 30 --json");
    // a file that declares reduced precision: the keys of its binary16 program
    runs.push_back("--brdf '" NORMZOO_SOURCE_DIR "/tests/shaders/ggx-mediump.glsl' --param roughness=0.5 --theta 30 --json");
    runs.push_back(texture_run());
    runs.push_back(against_run());
    for (const auto& m : material_runs()) runs.push_back(m);
    for (const auto& args : runs) {
        const auto [status, out] = run_verify(args);
        INFO(args);
        REQUIRE((status == 0 || status == 1));
        const auto doc = nlohmann::ordered_json::parse(out);
        if (seen) seen(args, status, doc);
        add(doc);
    }
    return records;
}

// The schema's generated key lists, as {JSON pointer: value}: each table's `required` and its
// `properties` in the records' order, where the schema has a $def of the table's name.
nlohmann::ordered_json generated_schema_keys(const nlohmann::ordered_json& schema,
                                             const std::map<std::string, normzoo_test::table_keys>& keys) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const auto& [table, k] : keys) {
        if (normzoo_test::keys_by_options(table) || !schema.at("$defs").contains(table)) continue;
        const auto& def = schema.at("$defs").at(table);
        std::vector<std::string> required = k.required;
        required.erase(std::remove(required.begin(), required.end(), "param_NAME"), required.end());
        out["/$defs/" + table + "/required"] = required;
        out["/$defs/" + table + "/properties"] = normzoo_test::generated_properties(def, k.keys);
    }
    return out;
}

// The key lists of docs/records.md and of the schema against those `records` hold.
void check_key_lists(const std::vector<nlohmann::ordered_json>& records) {
    const auto keys = normzoo_test::keys_by_table(records);
    std::ifstream in(source_dir / "docs/schema/output.schema.json");
    const auto schema = nlohmann::ordered_json::parse(in);
    const auto parts = normzoo_test::generated_table_parts(schema, keys);
    for (const auto& [pointer, value] : parts.items()) {
        const nlohmann::ordered_json::json_pointer at(pointer);
        INFO("output.schema.json " << pointer << " (tools/update-schemas writes the generated one)");
        CHECK((schema.contains(at) && schema.at(at) == value));
    }
    const auto md = normzoo_test::marked_key_tables(normzoo_test::slurp(source_dir / "docs/records.md"));
    for (const auto& [table, k] : keys) {
        if (normzoo_test::keys_by_options(table)) continue;
        INFO("docs/records.md, table " << table << " (tools/update-schemas writes the generated list)");
        REQUIRE(md.count(table));
        std::vector<std::string> listed = k.keys;
        listed.erase(std::remove(listed.begin(), listed.end(), "table"), listed.end());
        CHECK(normzoo_test::key_list_difference(normzoo_test::keys_of_rows(md.at(table)), listed) == "");
    }
    for (const auto& [table, rows] : md) {
        INFO("docs/records.md lists the keys of " << table << ", which no run makes");
        CHECK(keys.count(table));
    }
    const auto generated = generated_schema_keys(schema, keys);
    for (const auto& [pointer, value] : generated.items()) {
        INFO("output.schema.json " << pointer << " (tools/update-schemas writes the generated list)");
        const auto& committed = schema.at(nlohmann::ordered_json::json_pointer(pointer));
        const bool properties = pointer.size() > 11 && pointer.compare(pointer.size() - 11, 11, "/properties") == 0;
        const auto listed = properties ? normzoo_test::member_names(committed) : committed.get<std::vector<std::string>>();
        const auto made = properties ? normzoo_test::member_names(value) : value.get<std::vector<std::string>>();
        CHECK(normzoo_test::key_list_difference(listed, made) == "");
    }
}

}  // namespace

// One test for both, since they need the same runs (a few seconds each, every scene): the output
// conforms to the schema, and the tables' key lists in records.md and the schema are those the
// records hold.
TEST_CASE("the command's --json output conforms to docs/schema/output.schema.json, its tables' key lists are the generated ones") {
    const char* runs[] = {"zoo --n 0,3,0.37,1e7 --json",
                          "bounds --n 0,1,1e7 --json",
                          "energy --n 4 --theta 0,60,89.9 --json",
                          "irradiance --ratio 1e-3,1e-300 --tilt 0,89.9,95 --model lambert,phong --json",
                          "ndf --n 2,100 --json",
                          "shader-precision --json",
                          "audit --cases 300 --json"};
    for (const std::string args : runs) {
        CAPTURE(args);
        const auto [status, out] = run_verify(args);
        REQUIRE(status == 0);
        const auto errors = output_schema().errors(nlohmann::json::parse(out));
        INFO(joined(errors));
        CHECK(errors.empty());
    }
    // the runs the key lists read (BRDF files, a texture, a conformance, materials, every scene):
    // a scene's records carry its material and light names, and a failing scene is output too;
    // a --brdf run with a texture fails its verdict (not reciprocal), which is exit 1
    const auto records = made_records([](const std::string& args, int status, const nlohmann::ordered_json& doc) {
        CAPTURE(args);
        const bool scene = args.rfind("--scene", 0) == 0;
        CHECK((status == 0 || scene || args.find("--texture") != std::string::npos));
        if (scene) CHECK(!doc["skipped"].empty());
        const auto errors = output_schema().errors(nlohmann::json::parse(doc.dump()));
        INFO(joined(errors));
        CHECK(errors.empty());
    });
    check_key_lists(records);
}

// [plain-only]: not run under the sanitizers (tests/CMakeLists.txt)
TEST_CASE("every committed results/*.json's records conform, table by table", "[plain-only]") {
    for (const auto& file : files_in(source_dir / "results", ".json")) {
        CAPTURE(file.string());
        const auto doc = read_json(file);
        const auto errors = output_schema().errors({{"records", doc.at("records")}, {"skipped", nlohmann::json::array()}});
        INFO(joined(errors));
        CHECK(errors.empty());
    }
}

TEST_CASE("a broken record fails, naming the key") {
    const auto [status, out] = run_verify("zoo --n 8 --json");
    REQUIRE(status == 0);
    const auto good = nlohmann::json::parse(out);
    REQUIRE(output_schema().errors(good).empty());
    auto contains = [](const std::vector<std::string>& errors, const std::string& what) {
        for (const auto& e : errors)
            if (e.find(what) != std::string::npos) return true;
        return false;
    };
    auto broken = good;
    broken["records"][0].erase("norm_quadrature");  // a required key gone
    CHECK(contains(output_schema().errors(broken), "'norm_quadrature' is missing"));
    broken = good;
    broken["records"][0]["digits"] = "many";  // a number as text
    CHECK(contains(output_schema().errors(broken), "digits"));
    broken = good;
    broken["records"][0]["colour"] = "red";  // a key no table has
    CHECK(contains(output_schema().errors(broken), "colour"));
    broken = good;
    broken["records"][0]["table"] = "zoo-2";  // no such table
    CHECK(!output_schema().errors(broken).empty());
    broken = good;
    broken.erase("skipped");
    CHECK(contains(output_schema().errors(broken), "'skipped' is missing"));
}

TEST_CASE("the scenes of scenes/ conform to docs/schema/scene.schema.json, and bad scenes do not") {
    const schema_validator scene_schema(read_json(source_dir / "docs/schema/scene.schema.json"));
    auto as_json = [](const std::string& toml_text) {
        std::ostringstream os;
        os << toml::json_formatter{toml::parse(toml_text)};
        return nlohmann::json::parse(os.str());
    };
    const auto scenes = files_in(source_dir / "scenes", ".toml");
    REQUIRE(!scenes.empty());
    for (const auto& scene : scenes) {
        CAPTURE(scene.string());
        std::ifstream in(scene);
        const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const auto errors = scene_schema.errors(as_json(text));
        INFO(joined(errors));
        CHECK(errors.empty());
    }
    const char* bad[] = {
        "[[materials]]\nname = \"a\"\nmodel = \"phong\"\n",                                   // no exponent or gloss
        "[[materials]]\nname = \"a\"\nmodel = \"phong\"\nexponent = [1.0, 2.0]\ngloss = [0.0, 1.0]\n",  // both
        "[[materials]]\nname = \"a\"\nmodel = \"phung\"\nexponent = [1.0, 2.0]\n",            // unknown model
        "[[materials]]\nname = \"a\"\nmodel = \"phong\"\nexponent = [1.0]\n",                 // not a range
        "[[materials]]\nname = \"a\"\nmodel = \"phong\"\nexponent = [1.0, 2.0]\nshiny = 1\n",  // unknown key
        "[[lights]]\nname = \"l\"\ntype = \"tube\"\nradius = 1.0\ndistance = 2.0\n",          // unknown type
        "[[lights]]\nname = \"l\"\ntype = \"disk\"\nradius = 0.0\ndistance = 2.0\n",          // radius 0
        "[tolerance]\ndigits = 40.0\n",                                                       // no materials, and 40 > 33
        "[scene]\nname = \"empty\"\n"};                                                        // neither materials nor lights
    for (const char* text : bad) {
        CAPTURE(text);
        CHECK(!scene_schema.errors(as_json(text)).empty());
    }
}

// The scene schema lists the composition ids a material may name (JSON Schema has no grammar for
// D/G/F): they must be the registry's, all of them, in the parts' order (tests/schema_enums.hpp
// makes them; tools/update-schemas writes them).
TEST_CASE("the scene schema's composition ids are exactly those the part lists compose") {
    const auto ids = normzoo_test::composition_ids();
    const auto schema = read_json(source_dir / "docs/schema/scene.schema.json");
    const auto listed = schema["properties"]["materials"]["items"]["properties"]["model"]["anyOf"][1]["enum"];
    INFO("the ids as the part lists make them: " << nlohmann::json(ids).dump());
    CHECK(listed.get<std::vector<std::string>>() == ids);
}

// Every enum the registry determines (tests/schema_enums.hpp) as the committed schema has it; on
// a difference, tools/update-schemas writes the generated ones.
TEST_CASE("every enum of docs/schema/ that the registry determines is the generated one") {
    for (const auto& e : normzoo_test::registry_enums()) {
        const auto schema = read_json(source_dir / "docs/schema" / e.file);
        const nlohmann::json::json_pointer at(e.pointer);
        INFO(e.file << " " << e.pointer << " (tools/update-schemas writes the generated list)");
        REQUIRE(schema.contains(at));
        CHECK(schema[at].get<std::vector<std::string>>() == e.ids);
    }
}

// Each table's keys in docs/records.md and the schema as the records a run makes them
// (tests/record_keys.hpp), and the schema's tables: every table the records show has its $defs
// entry, the record's oneOf takes every entry, the records' `table` enum lists the tables
// (tests/schema_tables.hpp); on a difference, tools/update-schemas writes the generated ones.
// tools/update-schemas runs this alone: the generated enums, tables' entries and key lists as
// {file: {pointer: value}}, written to $NORMZOO_SCHEMA_ENUMS, and docs/records.md with its
// generated key lists and new tables' sections, written to $NORMZOO_RECORDS_MD.
TEST_CASE("the generated enums and key lists, written for tools/update-schemas", "[.generate]") {
    const char* path = std::getenv("NORMZOO_SCHEMA_ENUMS");
    const char* records_md = std::getenv("NORMZOO_RECORDS_MD");
    REQUIRE(path);
    REQUIRE(records_md);
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    const auto keys = normzoo_test::keys_by_table(made_records());
    std::ifstream in(source_dir / "docs/schema/output.schema.json");
    const auto schema = nlohmann::ordered_json::parse(in);
    const auto parts = normzoo_test::generated_table_parts(schema, keys);
    // a new table's entry first, its key lists generated from it; the properties before the
    // enums: they hold the committed enums, which the generated ones then replace
    for (const auto& [pointer, value] : parts.items()) out["output.schema.json"][pointer] = value;
    const auto generated = generated_schema_keys(normzoo_test::with_table_parts(schema, parts), keys);
    for (const auto& [pointer, value] : generated.items()) out["output.schema.json"][pointer] = value;
    for (const auto& e : normzoo_test::registry_enums()) out[e.file][e.pointer] = e.ids;
    std::ofstream(path) << out.dump(1) << "\n";
    std::ofstream(records_md, std::ios::binary)
        << normzoo_test::generated_records_md(normzoo_test::slurp(source_dir / "docs/records.md"), keys);
    CHECK(std::ifstream(path).good());
}
