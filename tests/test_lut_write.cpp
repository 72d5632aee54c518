// `verify lut` writing a table in an engine's layout (docs/lut.md, "Formats" and "Layouts"):
// every preset's table written in KTX2, DDS and an 8-bit PNG (or refused where the format cannot
// hold its encoding) is read back by `lut --check FILE --preset SAME`, found by --detect, and
// fails under a wrong layout; the older formats under a layout, sizes that are not square, E_avg's
// one axis; and what a format cannot hold, refused before anything is computed. Light: it runs the
// command and reads its JSON (and one file through lut_formats/), nothing of the library.
#include <catch2/catch.hpp>

#include "sanitized.hpp"
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lut_formats/read.hpp"
#include "lut_runs.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;
using normzoo_test::records;
using normzoo_test::run_shell;
using normzoo_test::verify_lut;

namespace {

// A canonical layout's keys (lut-check's `layout`), channels without the skipped ones.
std::map<std::string, std::string> keys_of(const std::string& layout) {
    std::map<std::string, std::string> keys;
    std::string key;
    for (std::size_t at = 0; at <= layout.size();) {
        const std::size_t comma = std::min(layout.find(',', at), layout.size());
        const std::string item = layout.substr(at, comma - at);
        const std::size_t eq = item.find('=');
        if (eq != std::string::npos) key = item.substr(0, eq), keys[key] = item.substr(eq + 1);
        else if (item != "-") keys[key] += "," + item;  // a channel after the first
        at = comma + 1;
    }
    for (auto& [k, v] : keys)
        while (k == "channels" && v.size() > 2 && v.substr(v.size() - 2) == ",-") v.resize(v.size() - 2);
    return keys;
}

// The presets, as an unknown one's refusal lists them, with their kinds.
std::vector<std::pair<std::string, std::string>> presets() {
    const std::string out = verify_lut("--kind dfg --size 4 --preset none").out;
    const std::size_t from = out.find("presets: ") + 9;
    std::vector<std::pair<std::string, std::string>> list;
    for (std::size_t at = from; at < out.size() && out[at] != ')';) {
        const std::size_t end = std::min(out.find_first_of(",)", at), out.size());
        const std::string name = out.substr(at, end - at);
        const std::string said = verify_lut("--kind dfg --size 4 --preset " + name).out;
        const bool eavg = said.find("is a table of --kind Eavg") != std::string::npos;
        const bool e = !eavg && said.find("is a table of --kind E") != std::string::npos;
        list.emplace_back(name, eavg ? "Eavg" : e ? "E" : "dfg");
        at = out[end] == ',' ? end + 2 : end;
    }
    return list;
}

// The one file a run wrote into dir.
std::string written(const fs::path& dir) {
    std::vector<std::string> files;
    for (const auto& f : fs::directory_iterator(dir)) files.push_back(f.path().string());
    REQUIRE(files.size() == 1);
    return files.front();
}

// The table `args` make, written into dir (a folder of its own): its path.
std::string write_table(const std::string& kind, const std::string& args, const fs::path& dir) {
    const auto w = verify_lut("--kind " + kind + " " + args + " --out '" + dir.string() + "'");
    CAPTURE(args, w.out);
    REQUIRE(w.status == 0);
    return written(dir);
}

// The table in path read back as `reading` says, and as --detect finds it (with `detect`); under
// `wrong` it fails. Returns the lut-check records of the reading.
nlohmann::json read_back(const std::string& kind, const std::string& path, const std::string& reading, const std::string& detect,
                         const std::string& wrong) {
    const std::string check = "--check '" + path + "' --kind " + kind;
    const auto same = records(check + " " + reading);
    for (const auto& r : same) CHECK(r["pass"] == true);
    CHECK(verify_lut(check + " " + reading).status == 0);
    // --detect: the same axes, ends, grid, channels and model (encodings that only round are given)
    const auto found = records(check + " --detect " + detect);
    auto expected = keys_of(same[0]["layout"]), got = keys_of(found[0]["layout"]);
    for (const char* key : {"rows", "cols", "row0", "col0", "grid", "channels"}) CHECK(got[key] == expected[key]);
    CHECK(found[0]["model"] == same[0]["model"]);
    for (const auto& r : found) CHECK(r["pass"] == true);
    const auto bad = verify_lut(check + " " + wrong);
    CAPTURE(wrong, bad.out);
    CHECK(bad.status == 1);
    return same;
}

nlohmann::json round_trip(const std::string& kind, const std::string& args, const fs::path& dir, const std::string& reading,
                          const std::string& detect, const std::string& wrong) {
    return read_back(kind, write_table(kind, args, dir), reading, detect, wrong);
}

}  // namespace

TEST_CASE("lut writes each preset's table in KTX2, DDS or png8 in turn: --check --preset reads it, --detect finds it, a wrong layout fails") {
    normzoo_test::temp_dir dir{"lut-write-presets"};
    const auto all = presets();
    REQUIRE(all.size() >= 11);
    const std::map<std::string, std::string> container = {{"ktx2", "ktx2-"}, {"dds", "dds-"}, {"png8", "png8"}};
    // Each preset in one container, the three in turn: the containers' writers and readers do not
    // depend on the preset (test_lut_formats.cpp), the layouts do not depend on the container. Both
    // of png8's paths are taken: an encoding it holds, and one it refuses until given unorm8.
    std::size_t turn = 0, png8_refused = 0, png8_held = 0, sliced = 0;
    for (const auto& [preset, kind] : all) {
        // a table of slices (openpbr-bsdf's dielectrics, opaque and transmitting) is read, not written: its test is below
        if (verify_lut("--kind " + kind + " --size 8 --preset " + preset).out.find("slices (size=WxHxD) are read by --check FILE") !=
            std::string::npos) {
            ++sliced;
            continue;
        }
        // The sheen tables hold E above 1 (docs/lut.md#sheen-tables), which an 8-bit PNG clamps, and
        // --detect tries the models engines bake GGX tables with: it is given theirs.
        const bool cloth = preset == "filament-cloth" || preset == "babylon-sheen", sheen = cloth || preset == "gltf-sample-viewer-sheen";
        const std::string model = !sheen ? "" : cloth ? " --model charlie/ashikhmin/one" : " --model charlie/charlie-sheen/one";
        {
            const char* formats[] = {"ktx2", "dds", "png8"};
            const std::string format = formats[sheen ? turn++ % 2 : turn++ % 3];
            CAPTURE(preset, format);
            const fs::path out = dir.path / (preset + "-" + format);
            // a preset that fixes its size (Cycles' 32 x 32) is written at it; under the sanitizers
            // the sheen's at 4 x 4: at 8 x 8 their exact values take most of the test's time there
            // (glTF's sheen preset: 4 s to check, 10 s to --detect)
            std::string size = sheen && normzoo_test::sanitized ? " --size 4" : " --size 8";
            if (verify_lut("--kind " + kind + size + " --preset " + preset + " --format " + format).out.find("give two sizes") != std::string::npos)
                size = "";
            const std::string args = size + " --preset " + preset + " --format " + format;
            const auto first = verify_lut("--kind " + kind + args + " --out '" + out.string() + "'");
            std::string keys;  // --layout keys given beside the preset, when writing and reading
            if (first.status == 2) {
                // half floats and 10-bit codes in an 8-bit PNG: refused naming the preset's encoding,
                // before anything is written; written with encoding=unorm8, which an 8-bit PNG holds
                CAPTURE(first.out);
                CHECK(format == "png8");
                CHECK(first.out.find("--format png8 cannot hold --preset " + preset + " (encoding=") != std::string::npos);
                CHECK(!fs::exists(out));
                keys = "encoding=unorm8,";
                ++png8_refused;
            } else if (format == "png8") ++png8_held;
            const std::string layout = keys.empty() ? "" : " --layout " + keys.substr(0, keys.size() - 1);
            const std::string path = write_table(kind, args + layout, out);
            // the preset's layout, as the check names it: where its rows start, how it encodes
            const auto as_read = keys_of(records("--check '" + path + "' --kind " + kind + " --preset " + preset + layout)[0]["layout"]);
            const std::string encoding = as_read.at("encoding");
            const bool rounds = encoding != "linear" && encoding != "srgb" && encoding != "rgbd";
            const std::string flipped = std::string("row0=") + (as_read.at("row0") == "low" ? "high" : "low");
            const auto r = read_back(kind, path, "--preset " + preset + layout, (rounds ? "--layout encoding=" + encoding : "") + model,
                                     "--preset " + preset + " --layout " + keys + flipped);
            CHECK(r[0]["format"].get<std::string>().rfind(container.at(format), 0) == 0);
        }
    }
    CHECK(png8_refused > 0);
    CHECK(sliced == 4);
    CHECK(png8_held > 0);
    // Bevy's own container: a Zstandard-supercompressed KTX2 of R16G16_SFLOAT
    const auto z = round_trip("dfg", "--size 16 --preset bevy --format ktx2-zstd", dir.path / "bevy-zstd", "--preset bevy",
                              "--layout encoding=half", "--preset bevy --layout rows=mu,cols=r");
    CHECK(z[0]["format"] == "ktx2-R16G16_SFLOAT");
    CHECK(fs::exists(dir.path / "bevy-zstd" / "lut-dfg-16-zstd.ktx2"));
}

TEST_CASE("lut writes a layout in the older formats, tables that are not square, and E_avg's one axis") {
    normzoo_test::temp_dir dir{"lut-write-layouts"};
    // Godot in a half OpenEXR: four channels (B, A+B, 0, 1), the first row r = 1
    const auto godot = round_trip("dfg", "--size 16 --preset godot --format exr-half", dir.path / "godot", "--preset godot",
                                  "--layout encoding=half", "--preset godot --layout row0=low");
    CHECK(godot[0]["format"] == "exr-half");
    const verify::decoded_lut g = verify::read_lut_file(written(dir.path / "godot"), {});
    REQUIRE(g.image.channels == 4);
    CHECK(g.image.at(0, 15, 1) < g.image.at(15, 15, 1));  // A + B at mu = 31/32: the first row the roughest, the lowest
    for (std::size_t k = 0; k < 16 * 16; ++k) CHECK((g.image.data[4 * k + 2] == 0 && g.image.data[4 * k + 3] == 1));
    // Unity HDRP's 10-bit codes in a 16-bit PNG, corner-aligned in sqrt(mu): every texel compared
    // (the edges at the pair's limits)
    const auto unity = round_trip("dfg", "--size 16 --preset unity-hdrp --format png16", dir.path / "unity", "--preset unity-hdrp",
                                  "--layout encoding=unorm10", "--preset unity-hdrp --layout cols=mu");
    CHECK(unity[0]["texels"] == 256);
    CHECK(!unity[0].contains("not_compared"));
    // Cycles' E as a C header, 32 x 32 floats: its r = 0 column and mu = 0 row are not compared
    const auto cycles = round_trip("E", "--preset cycles --format h", dir.path / "cycles", "--preset cycles", "",
                                   "--preset cycles --layout rows=r,cols=mu");
    CHECK(cycles[0]["texels"] == 961);
    CHECK(normzoo_test::slurp(dir.path / "cycles" / "lut-E-32.h").find("// layout rows=mu,cols=r,row0=low,col0=low,grid=edges,channels=E,"
                                                                        "encoding=linear,size=32x32") != std::string::npos);
    // Babylon's RGBD in a 16-bit PNG, and Filament's shifted rows in a float OpenEXR
    round_trip("dfg", "--size 16 --preset babylon --format png16", dir.path / "babylon", "--preset babylon", "",
               "--preset babylon --layout encoding=srgb");
    round_trip("dfg", "--size 16 --preset filament --format exr", dir.path / "filament", "--preset filament", "--layout encoding=half",
               "--preset filament --layout grid=centres");
    // 32 columns of mu by 8 rows of r, as Unreal's 128 x 32; the records follow the file's rows
    const auto wide = round_trip("dfg", "--preset unreal --layout size=32x8 --format ktx2", dir.path / "wide", "--preset unreal", "",
                                 "--preset unreal --layout row0=high");
    CHECK(wide[0]["texels"] == 256);
    CHECK(fs::exists(dir.path / "wide" / "lut-dfg-32x8.ktx2"));
    const auto made = records("--kind dfg --preset godot --size 4");
    REQUIRE(made.size() == 16);
    CHECK(made[0]["r"] == 0.875);  // row0=high: the first row is the roughest
    CHECK(made[3]["mu"] == 0.875);
    // E_avg, roughest first, in one column of a float OpenEXR
    const auto avg = round_trip("Eavg", "--layout rows=r,row0=high,size=1x16 --format exr", dir.path / "eavg",
                                "--layout row0=high", "", "--layout row0=low");
    CHECK(avg[0]["texels"] == 16);
    // a CSV of the split-sum pair on a corner-aligned grid: its points are its coordinates, read
    // back with the edges at the pair's limits
    const std::string csv = write_table("dfg", "--size 8 --layout grid=edges,cols=sqrt-mu --format csv", dir.path / "csv");
    const auto points = records("--check '" + csv + "' --kind dfg");
    CHECK(points[0]["texels"] == 64);
    CHECK(points[0]["pass"] == true);
    CHECK(normzoo_test::slurp(csv).find("\nlut,dfg,ggx/smith-height-correlated/one,0.0,0.0,0.0,") != std::string::npos);
}

TEST_CASE("lut --monte-carlo bakes in a layout: the engine's noise, read back by its preset and found by --detect") {
    normzoo_test::temp_dir dir{"lut-write-baked"};
    // Babylon's RGBD (B, A+B), 256 samples: off by more than 8 bits hold, and found as baked
    const std::string path = write_table("dfg", "--size 16 --monte-carlo 256 --preset babylon --format png8", dir.path / "babylon");
    const std::string check = "--check '" + path + "' --kind dfg";
    const auto read = records(check + " --preset babylon");
    CHECK(read[0]["channel"] == "B");
    CHECK(read[0]["pass"] == false);
    CHECK(read[0]["max_abs_error"] < 0.05);  // noise, not a wrong reading
    const auto found = records(check + " --detect");
    CHECK(keys_of(found[0]["layout"])["channels"] == "B,A+B");
    CHECK(keys_of(found[0]["layout"])["encoding"] == "rgbd");
    const auto wrong = records(check + " --preset babylon --layout row0=high");
    CHECK(wrong[0]["max_abs_error"] > 4 * read[0]["max_abs_error"].get<double>());
    // a large table's noise hides where its texels sit but next to mu = 0 at small r: there
    // --detect tells centres from edges
    const std::string big = write_table("dfg", "--size 256 --monte-carlo 256 --preset gltf-sample-viewer --format png8", dir.path / "gltf");
    CHECK(keys_of(records("--check '" + big + "' --kind dfg --detect")[0]["layout"])["grid"] == "centres");
    // an edge grid: the baker runs at r, mu = 1e-4 there, and every value is finite
    const std::string edges = write_table("dfg", "--size 8 --monte-carlo 64 --preset unity-hdrp --format png16", dir.path / "unity");
    CHECK(verify_lut("--check '" + edges + "' --kind dfg --preset unity-hdrp").status == 1);
}

// openpbr-bsdf's energy tables: 1 - E as unorm16 codes written in decimal, a bare list that an
// initialiser #includes ([r][mu], corner-aligned). Made here from the exact table, in that form.
TEST_CASE("lut --check reads a bare list of unorm16 codes of 1 - E (openpbr-bsdf's energy tables)") {
    normzoo_test::temp_dir dir{"lut-openpbr-bsdf"};
    const auto exact = nlohmann::json::parse(verify_lut("--kind E --preset openpbr-bsdf-metal --json").out)["records"];
    REQUIRE(exact.size() == 32 * 32);
    auto codes = [&](bool transposed) {
        std::string text = "// clang-format off\n";
        for (std::size_t i = 0; i < 32; ++i)
            for (std::size_t j = 0; j < 32; ++j)
                text += std::to_string(std::lround((1 - exact[transposed ? j * 32 + i : i * 32 + j]["E"].get<double>()) * 65535)) + ", ";
        return text + "\n    // clang-format on\n";
    };
    const fs::path good = dir.path / "metal_energy_complement_data.h", bad = dir.path / "transposed_data.h";
    std::ofstream(good) << codes(false);
    std::ofstream(bad) << codes(true);
    const std::string check = "--check '" + good.string() + "' --kind E";
    const auto read = records(check + " --preset openpbr-bsdf-metal");
    CHECK(read[0]["channel"] == "1-E");
    CHECK(read[0]["pass"] == true);
    const auto found = records(check + " --layout size=32x32,encoding=unorm16 --detect");
    CHECK(keys_of(found[0]["layout"])["channels"] == "1-E");
    CHECK(keys_of(found[0]["layout"])["grid"] == "edges");
    CHECK(found[0]["model"] == "ggx/smith-separable/one");
    CHECK(verify_lut("--check '" + bad.string() + "' --kind E --preset openpbr-bsdf-metal").status == 1);
    // a list with anything but numbers is no table
    std::ofstream(dir.path / "broken_data.h") << "0, 1, two, 3,\n";
    const auto broken = verify_lut("--check '" + (dir.path / "broken_data.h").string() + "' --kind E --preset openpbr-bsdf-metal");
    CHECK(broken.status == 2);
    CHECK(broken.out.find("broken_data.h") != std::string::npos);
}

// A table of slices (docs/lut.md, "Slices"): openpbr-bsdf's 32^3 dielectric tables as their
// [eta][r][mu] arrays hold them. Made here slice by slice from energy's exact E at each index,
// 3 x 3 texels a slice on the edges grid (the preset's size overridden; the texels at r = 0 and
// mu = 0, which are not compared, hold 0), and checked slice by slice at the preset's axis.
TEST_CASE("lut --check reads a table of slices at their indices (openpbr-bsdf's dielectric tables)") {
    normzoo_test::temp_dir dir{"lut-slices"};
    const std::string model = " --model ggx/smith-separable/dielectric";
    auto codes_at = [&](const std::string& eta, const std::string& of = " --model ggx/smith-separable/dielectric") {
        const auto exact = nlohmann::json::parse(
            run_shell(std::string(NORMZOO_VERIFY_BIN) + " energy" + of + " --eta " + eta + " --r 0.5,1 --mu 0.5,1 --json 2>/dev/null").out)["records"];
        std::vector<long> c(9, 0);
        for (const auto& rec : exact)
            c[std::size_t(rec["r"].get<double>() * 2) * 3 + std::size_t(rec["mu"].get<double>() * 2)] =
                std::lround((1 - rec["albedo"].get<double>()) * 65535);
        return c;
    };
    // the preset's axis as --eta would list it: 1/2.5 .. 1/1.1 by 1/eta, 1/1.0001 and 1.0001, 1.1 .. 2.5 by eta
    std::vector<std::string> axis;
    for (int i = 0; i < 32; ++i) {
        std::string v = i == 15 ? "0.99990000999900009999" : i == 16 ? "1.0001" : "";
        if (i < 15) {
            v = "0.";
            for (long num = 10, k = 0; k < 20; ++k, num %= 25 - i) v += char('0' + (num *= 10) / (25 - i));
            v = v.substr(0, v.find_last_not_of('0') + 1);  // 0.4, 0.41666666666666666666
        }
        if (i > 16) v = std::to_string((i - 6) / 10) + "." + std::to_string((i - 6) % 10);
        axis.push_back(v);
    }
    std::vector<std::vector<long>> slices, transmitting;
    for (const auto& eta : axis) {
        slices.push_back(codes_at(eta));
        transmitting.push_back(codes_at(eta, " --model ggx/smith-separable/dielectric/transmission"));
    }
    auto write_of = [&](const std::vector<std::vector<long>>& of, const fs::path& p, std::size_t off_slice, long off) {
        std::ofstream f(p);
        f << "// clang-format off\n";
        for (std::size_t k = 0; k < of.size(); ++k)
            for (std::size_t t = 0; t < of[k].size(); ++t) f << of[k][t] + (k == off_slice && t == 4 ? off : 0) << ", ";
        f << "\n    // clang-format on\n";
    };
    auto write = [&](const fs::path& p, std::size_t off_slice, long off) { write_of(slices, p, off_slice, off); };
    // the transmitting dielectric's table (reflection and refraction, 1 - E of both) passes its
    // preset and fails the opaque one's, whose E is the reflection alone
    write_of(transmitting, dir.path / "ideal_data.h", 99, 0);
    const std::string ideal = "--check '" + (dir.path / "ideal_data.h").string() + "' --kind E --layout size=3x3x32 --preset ";
    CHECK(verify_lut(ideal + "openpbr-bsdf-ideal-dielectric").status == 0);
    CHECK(verify_lut(ideal + "openpbr-bsdf-opaque-dielectric").status == 1);
    const fs::path good = dir.path / "opaque_data.h", bad = dir.path / "off_data.h";
    write(good, 99, 0);
    write(bad, 20, 3);  // slice 20 (eta 1.4), one texel 3 codes off
    const std::string preset = " --kind E --preset openpbr-bsdf-opaque-dielectric --layout size=3x3x32";
    const auto read = records("--check '" + good.string() + "'" + preset);
    REQUIRE(read.size() == 32);
    for (std::size_t k = 0; k < 32; ++k) {
        CAPTURE(k);
        CHECK(read[k]["slice"] == k);
        CHECK(read[k]["eta_input"] == axis[k]);
        CHECK(read[k]["pass"] == true);
        CHECK(read[k]["texels"] == 4);  // r = 0 and mu = 0 not compared
    }
    CHECK(read[0]["layout"] == "rows=r,cols=mu,row0=low,col0=low,grid=edges,channels=1-E,encoding=unorm16,size=3x3x32");
    const auto off = verify_lut("--check '" + bad.string() + "'" + preset + " --json");
    CHECK(off.status == 1);
    const auto failed = nlohmann::json::parse(off.out)["records"];
    for (std::size_t k = 0; k < 32; ++k) CHECK(failed[k]["pass"] == (k != 20));
    // a list of --eta for the slices, and one that is not in their order
    std::string list;
    for (const auto& eta : axis) list += (list.empty() ? "" : ",") + eta;
    const std::string plain = " --kind E" + model + " --layout rows=r,cols=mu,row0=low,col0=low,grid=edges,channels=1-E,encoding=unorm16,size=3x3x32";
    CHECK(verify_lut("--check '" + good.string() + "'" + plain + " --eta " + list).status == 0);
    std::string swapped = list.substr(list.find(',') + 1) + "," + axis[0];
    CHECK(verify_lut("--check '" + good.string() + "'" + plain + " --eta " + swapped).status == 1);
    // E_avg's table of slices, [eta][r] (openpbr-bsdf's average), one column of two texels a slice
    std::string averages = "// clang-format off\n";
    for (const char* eta : {"1.5", "2"}) {
        const auto e = records("--kind Eavg" + model + " --eta " + eta + " --r 1")[0]["E_avg"].get<double>();
        averages += "0, " + std::to_string(std::lround((1 - e) * 65535)) + ", ";
    }
    std::ofstream(dir.path / "average_data.h") << averages << "\n";
    const auto avg = records("--check '" + (dir.path / "average_data.h").string() + "' --kind Eavg" + model +
                             " --layout rows=r,row0=low,grid=edges,channels=1-E_avg,encoding=unorm16,size=1x2x2 --eta 1.5,2");
    REQUIRE(avg.size() == 2);
    CHECK(avg[1]["slice"] == 1);
    CHECK(avg[1]["eta"] == 2);
    CHECK((avg[0]["pass"] == true && avg[1]["pass"] == true));
    CHECK(verify_lut("--check '" + (dir.path / "average_data.h").string() + "' --kind Eavg" + model +
                     " --layout rows=r,row0=low,grid=edges,channels=1-E_avg,encoding=unorm16,size=1x2x2 --eta 2,1.5").status == 1);
    // refused, naming what is wrong: a count of --eta that is not the slices', a size that is not the file's,
    // --detect, a model that does not read eta, slices in a table to make
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"--check '" + good.string() + "'" + plain + " --eta 1.5,1.6", "--eta lists one per slice"},
        {"--check '" + good.string() + "'" + plain, "none given"},
        {"--check '" + good.string() + "' --kind E --preset openpbr-bsdf-opaque-dielectric --layout size=3x3x31", "holds 31 slices"},
        {"--check '" + good.string() + "' --kind E" + model + " --layout size=3x3x31,encoding=unorm16 --eta " + list.substr(0, list.rfind(',')),
         "size=3x3x31: 31 slices of 3 x 3"},
        {"--check '" + good.string() + "' --kind E --preset openpbr-bsdf-opaque-dielectric --model ggx/smith-separable/one --layout size=3x3x32", "does not read"},
        {"--check '" + good.string() + "' --kind E --model ggx/smith-separable/one --layout size=3x3x32,encoding=unorm16 --eta " + list, "no part of"},
        {"--check '" + good.string() + "' --kind E" + model + " --eta 1.5,1.6", "one value, not a list"},
        {"--kind E --size 4 --layout size=4x4x2", "slices (size=WxHxD) are read by --check FILE"},
        {"--check '" + good.string() + "' --kind E --preset openpbr-bsdf-opaque-dielectric --layout size=3x3", "needs its --eta"},
        {"--check '" + good.string() + "' --kind E --preset openpbr-bsdf-opaque-dielectric --layout size=3x3x32 --f0 0.04", "--f0 and --preset"},
        {"--check '" + good.string() + "' --kind dfg --layout size=3x3x32", "a split-sum table's slices"},
        {"--check '" + good.string() + "' --kind E" + model + " --layout size=3x3x32 --detect", "--detect reads a table of one slice"},
        {"--check '" + good.string() + "' --kind E --layout size=3x4096x2", "more than 4096"}};
    for (const auto& [args, says] : refused) {
        CAPTURE(args);
        const auto r = verify_lut(args);
        CHECK(r.status == 2);
        CHECK(r.out.find(says) != std::string::npos);
    }
}

TEST_CASE("lut refuses a layout its format cannot hold, naming the option, before anything is computed") {
    normzoo_test::temp_dir dir{"lut-write-refused"};
    const std::string out = " --out '" + dir.path.string() + "'";
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"--kind dfg --size 4096 --preset babylon --format exr", "--format exr cannot hold --preset babylon (encoding=rgbd)"},
        {"--kind dfg --size 4096 --layout encoding=half --format png16", "--format png16 cannot hold --layout encoding=half"},
        {"--kind dfg --size 4096 --layout encoding=srgb --format h", "--format h cannot hold --layout encoding=srgb"},
        {"--kind dfg --size 4096 --layout encoding=unorm16 --format png8", "--format png8 cannot hold --layout encoding=unorm16"},
        {"--kind dfg --size 4096 --layout encoding=unorm16 --format exr-half", "cannot hold --layout encoding=unorm16"},
        {"--kind dfg --size 4096 --layout encoding=half --format csv", "a csv holds the records"},
        {"--kind dfg --size 4096 --preset filament --layout encoding=linear",
         "--format csv writes the records, whose values are named (A and B): --preset filament (channels=B,A+B,-)"},
        {"--kind dfg --size 4096 --layout channels=B,A+B,-,-,- --format exr", "5 channels; an image holds at most 4"},
        {"--kind E --preset cycles --format csv", "--format csv with --preset cycles (grid=edges)"},
        {"--kind E --size 64 --preset cycles --format h", "--size 64 and --preset cycles (size=32x32) give two sizes"},
        {"--kind Eavg --layout size=16x4 --format exr", "--layout size=16x4: an E_avg table is one row or one column"},
        {"--kind dfg --size 1 --layout grid=edges --format exr", "--layout grid=edges places texel t of n at t/(n - 1)"},
        {"--kind dfg --size 4096 --model beckmann/smith-height-correlated/one --layout grid=edges --format exr",
         "the split-sum pair of beckmann/smith-height-correlated/one has no limit derived"},
        {"--kind E --size 4096 --model ggx/smith-height-correlated/schlick --layout grid=edges --format exr", "E has no limit derived"},
        {"--kind dfg --layout rows=mu,cols=r --format exr", "give --size N (or --layout size=WxH)"},
        {"--kind dfg --size 8 --map alpha --preset unreal", "--map is --layout rows=r or rows=alpha"},
        {"--kind dfg --size 8 --monte-carlo 16 --preset unreal --layout rows=alpha", "--monte-carlo bakes the split-sum pair"},
        {"--kind dfg --r 0.5 --mu 0.5 --preset unreal", "listed values (--alpha or --r with --mu) are points"},
        {"--kind dfg --size 8 --format ktx3", "is not one of csv, json, png8, png16, exr, exr-half, h, ktx2, ktx2-zstd, dds"},
    };
    for (const auto& [args, says] : refused) {
        const auto r = verify_lut(args + out);
        CAPTURE(args, r.out);
        CHECK(r.status == 2);
        CHECK(r.out.find(says) != std::string::npos);
    }
    CHECK(fs::is_empty(dir.path));
    // without --out or --format no file is written: the records at the layout's points print
    CHECK(verify_lut("--kind dfg --size 4 --preset filament --json").status == 0);
}
