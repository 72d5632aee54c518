// The command end to end: --check against edited and moved tables, what runs on custom grids
// leave alone, progress lines, tables' heads, and decimals taken as typed.
#include "cli_helpers.hpp"

using namespace cli_test;

TEST_CASE("check: a number or a word edited in the Markdown, the CSV or the JSON's head fails, naming the file") {
    struct edit {
        const char* file;
        const char* from;
        const char* to;
    };
    const auto e = GENERATE(values<edit>({
        // phong at n = 8, 7 % off: the file people cite, and the one programs read
        {"zoo.md", "| 1.432394487827058021919953870352630e+00 |", "| 1.532394487827058021919953870352630e+00 |"},
        {"zoo.csv", ",1.432394487827058021919953870352630e+00,", ",1.532394487827058021919953870352630e+00,"},
        {"zoo.csv", "phong,8.0,", "phong,8,"},  // the same number written otherwise
        {"zoo.md", "| phong | 8 |", "| Phong | 8 |"},
        {"zoo.csv", "# 1D: reduced integrand", "# 1D: reduced integral"},
        {"zoo-constants.md", "Produced by normzoo", "Made by normzoo"},
        {"gloss-8bit.csv", "\ngloss-8bit,", "\ngloss-8-bit,"},
        {"zoo.json", "\"title\": \"The normalization zoo", "\"title\": \"The normalisation zoo"},
    }));
    CAPTURE(e.file, e.from);
    const auto dir = fresh_dir("check-formats");
    REQUIRE(run("zoo --n 1,8 --out " + dir.string()).status == 0);
    REQUIRE(run("zoo --n 1,8 --check --out " + dir.string()).status == 0);
    std::string text = slurp(dir / e.file);
    const std::size_t at = text.find(e.from);
    REQUIRE(at != std::string::npos);
    text.replace(at, std::string(e.from).size(), e.to);
    std::ofstream(dir / e.file, std::ios::binary) << text;
    const auto r = run_with_stderr("zoo --n 1,8 --check --out " + dir.string());
    CAPTURE(r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find("DIFFERS") != std::string::npos);
    CHECK(r.out.find((dir / e.file).string() + ":") != std::string::npos);  // FILE:LINE:COLUMN
    fs::remove_all(dir);
}

TEST_CASE("check: a value moved within its error bound in every file alike still matches") {
    // What another platform may compute: phong at n = 8 one unit off in its 34th digit (bound ~6e-33).
    const auto dir = fresh_dir("check-within");
    REQUIRE(run("zoo --n 1,8 --out " + dir.string()).status == 0);
    for (const char* file : {"zoo.json", "zoo.md", "zoo.csv"}) {
        std::string text = slurp(dir / file);
        const std::string from = "1.432394487827058021919953870352630e+00";
        const std::size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), "1.432394487827058021919953870352631e+00");
        std::ofstream(dir / file, std::ios::binary) << text;
    }
    const auto r = run_with_stderr("zoo --n 1,8 --check --out " + dir.string());
    CAPTURE(r.out);
    CHECK(r.status == 0);
    CHECK(r.out.find("zoo: matches") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("check: the figures a checked table draws are compared byte for byte") {
    const auto dir = fresh_dir("check-figure");
    REQUIRE(run("bounds --n 1,1e7 --out " + dir.string()).status == 0);
    if (!fs::exists(dir / "bounds.svg")) {
        WARN("gnuplot is missing: no figure to compare");
        return;
    }
    const auto ok = run_with_stderr("bounds --n 1,1e7 --check --out " + dir.string());
    CAPTURE(ok.out);
    REQUIRE(ok.status == 0);
    CHECK(ok.out.find("bounds.svg") != std::string::npos);  // named among the files compared
    std::string svg = slurp(dir / "bounds.svg");
    const std::size_t at = svg.find("<title>Gnuplot</title>");
    REQUIRE(at != std::string::npos);
    svg.replace(at, 22, "<title>gnuplot</title>");
    std::ofstream(dir / "bounds.svg", std::ios::binary) << svg;
    const auto r = run_with_stderr("bounds --n 1,1e7 --check --out " + dir.string());
    CAPTURE(r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find((dir / "bounds.svg").string() + ":") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("runs on custom grids and --json leave results/ and the docs alone, a canonical run writes them") {
    // A copy of the project's results and docs: ./verify names its results/ by NORMZOO_RESULTS_DIR
    // and refreshes the docs beside it.
    const auto root = fresh_dir("project");
    const fs::path source(NORMZOO_SOURCE_DIR);
    fs::copy(source / "results", root / "results", fs::copy_options::recursive);
    fs::copy(source / "docs", root / "docs", fs::copy_options::recursive);
    fs::copy_file(source / "README.md", root / "README.md");
    const auto results = root / "results";
    const auto before = tree(root);
    for (const char* args : {"zoo --n 3,0.37", "zoo --n 3 --json", "zoo --json", "bounds --n 2",
                             "energy --model lambert --theta 0,45", "audit --cases 40 --seed 3"}) {
        CAPTURE(args);
        const auto r = run_with_stderr(args, results);
        CAPTURE(r.out);
        CHECK(r.status == 0);
        CHECK(r.out.find("nothing written") != std::string::npos);
        CHECK(r.out.find("--out DIR") != std::string::npos);
        CHECK(changed(before, tree(root)).empty());
    }
    // Named as --out, the project's results/ still takes no custom grid: exit 2 before any work.
    const auto refused = run_with_stderr("zoo --n 3 --out " + results.string(), results);
    CAPTURE(refused.out);
    CHECK(refused.status == 2);
    CHECK(refused.out.find("--n") != std::string::npos);
    CHECK(changed(before, tree(root)).empty());
    // On its canonical grid a table is written to results/.
    fs::remove(results / "zoo.csv");
    CHECK(run_with_stderr("zoo", results).status == 0);
    CHECK(fs::exists(results / "zoo.csv"));
    fs::remove_all(root);
}

TEST_CASE("progress: a line rewritten on a terminal's stderr, nothing of it in a pipe or a file or with --json") {
    // Long enough (with one thread) that a terminal shows the line: it appears after a second.
    const std::string audit = std::string(NORMZOO_VERIFY_BIN) + " audit --cases 5000 --jobs 1";
    const auto dir = fresh_dir("progress");
    const auto err = dir / "stderr.txt";
    // stderr a file, stdout a pipe: no carriage return, no progress text.
    const auto r = run_shell(audit + " 2>'" + err.string() + "'");
    CHECK(r.status == 0);
    const std::string text = slurp(err);
    CHECK(text.find('\r') == std::string::npos);
    CHECK(text.find(" left") == std::string::npos);
    CHECK(text.find("verify: audit ") == std::string::npos);
    CHECK(r.out.find('\r') == std::string::npos);
    // A terminal, through script(1) (util-linux), when it is there: the line shows, counting cases,
    // and is cleared; with --json it does not.
    if (run_shell("command -v script >/dev/null 2>&1").status == 0) {
        const auto pty = run_shell("script -qec '" + audit + "' /dev/null");
        CHECK(pty.status == 0);
        CHECK(pty.out.find("\rverify: audit ") != std::string::npos);
        CHECK(pty.out.find(" cases") != std::string::npos);
        CHECK(pty.out.find("/5,0") != std::string::npos);  // "1,234/5,0xx cases": thousands separated
        const auto json = run_shell("script -qec '" + audit + " --json' /dev/null");
        CHECK(json.status == 0);
        CHECK(json.out.find("\rverify: audit ") == std::string::npos);
        CHECK(json.out.find(" left") == std::string::npos);
    } else {
        WARN("script(1) is not installed: the terminal half of this test is skipped");
    }
    fs::remove_all(dir);
}

TEST_CASE("a table's head: the command as typed, and nothing that changes with a commit alone") {
    const auto dir = fresh_dir("head");
    REQUIRE(run("zoo --n 1,8 --out " + dir.string()).status == 0);
    const std::string md = slurp(dir / "zoo.md");
    CHECK(md.find("Produced by normzoo " + std::string(NORMZOO_VERSION) + ", `./verify zoo --n 1,8`, n = 1,8.") !=
          std::string::npos);
    CHECK(md.find("- `phong`: (R.V)^n (an RDF, V = N); normalization (n+1)/(2 pi)") != std::string::npos);
    // A commit that moves no value leaves the committed tables byte-identical (docs/reference.md,
    // "The head of a table"): no head names the source commit.
    CHECK(md.find("ommit") == std::string::npos);
    CHECK(slurp(dir / "zoo.csv").find("ommit") == std::string::npos);
    const auto doc = nlohmann::json::parse(slurp(dir / "zoo.json"));
    CHECK(!doc.contains("commit"));
    CHECK(run("zoo --n 1,8 --check --out " + dir.string()).status == 0);
    // An edit of the head is an edit of that file.
    std::string md_text = slurp(dir / "zoo.md");
    md_text.replace(md_text.find("Produced by"), 11, "Made by");
    std::ofstream(dir / "zoo.md", std::ios::binary) << md_text;
    CHECK(run("zoo --n 1,8 --check --out " + dir.string()).status == 1);
    fs::remove_all(dir);
}

TEST_CASE("inputs are the decimals typed, end to end: the command line and a scene") {
    using normzoo::wide;
    const wide pi = boost::math::constants::pi<wide>();
    // The relative difference of a record's decimal string from a value in 50 digits.
    auto off = [](const nlohmann::json& text, const wide& truth) {
        return static_cast<double>(abs(wide(text.get<std::string>()) - truth) / truth);
    };
    {
        const auto r = run("zoo --json --n 0.37,2.000000000000000001");
        REQUIRE(r.status == 0);
        int phong = 0;
        const auto doc = nlohmann::json::parse(r.out);
        for (const auto& rec : doc["records"]) {
            if (rec["table"] != "zoo" || rec["row"] != "phong") continue;
            ++phong;
            const std::string typed = rec["n_input"];
            CAPTURE(typed);
            CHECK((typed == "0.37" || typed == "2.000000000000000001"));
            // (n + 1) / (2 pi) at the decimal typed, in 50 digits: within the record's own estimate
            CHECK(off(rec["norm_quadrature"], (wide(typed) + 1) / (2 * pi)) <= rec["error_estimate"].get<double>());
        }
        CHECK(phong == 2);
    }
    {
        const auto r = run("irradiance --json --light sphere --ratio 0.1,3e-4 --tilt 0 --model lambert");
        REQUIRE(r.status == 0);
        int irradiance = 0;
        const auto doc = nlohmann::json::parse(r.out);
        for (const auto& rec : doc["records"]) {
            if (rec["table"] != "irradiance") continue;
            ++irradiance;
            const wide ratio(rec["ratio_input"].get<std::string>());
            CHECK(off(rec["E_quadrature"], pi * ratio * ratio) <= rec["error_estimate"].get<double>());
        }
        CHECK(irradiance == 2);
    }
    {
        const auto dir = fresh_dir("scene-decimals");
        const auto scene = dir / "decimals.toml";
        std::ofstream(scene) << "[[materials]]\nname = \"m\"\nmodel = \"phong-modified\"\nexponent = [0.37, 0.37]\n"
                             << "[[lights]]\nname = \"l\"\ntype = \"sphere\"\nradius = 0.1\ndistance = 3\n";
        const auto r = run("--scene " + scene.string() + " --json --out " + (dir / "out").string());
        REQUIRE(r.status == 0);
        int zoo = 0, irradiance = 0;
        const auto doc = nlohmann::json::parse(r.out);
        for (const auto& rec : doc["records"]) {
            if (rec["table"] == "zoo" && rec["row"] == "phong-modified") {
                ++zoo;
                CHECK(rec["n_input"] == "0.37");
                CHECK(off(rec["norm_quadrature"], (wide("0.37") + 2) / (2 * pi)) <= rec["error_estimate"].get<double>());
            }
            if (rec["table"] == "irradiance") {
                ++irradiance;
                CHECK(rec["ratio_input"] == "0.1/3");
                // E = pi (r0/r)^2 with r0/r = 1/30 exactly, which no binary type holds
                CHECK(off(rec["E_quadrature"], pi / 900) <= rec["error_estimate"].get<double>());
            }
        }
        CHECK(zoo == 1);
        CHECK(irradiance == 1);
        fs::remove_all(dir);
    }
}
