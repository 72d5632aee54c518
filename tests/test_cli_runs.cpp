// The command end to end: proofs, options that name options or unwritable paths, a scene's bounds,
// what a failing check prints, and JUnit names.
#include "cli_helpers.hpp"

using namespace cli_test;

TEST_CASE("verify proofs enclosures --json: the claims proved, the controls refuted, the enclosures hold") {
    const auto dir = fresh_dir("certify");
    const auto r = run("proofs enclosures --n 0.5,2048 --json --out " + dir.string());
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    std::size_t proofs = 0, enclosures = 0;
    for (const auto& rec : doc["records"]) {
        CHECK(rec["pass"] == true);
        CHECK(rec["seconds"].is_number());
        if (rec["table"] == "proofs") {
            ++proofs;
            for (const char* k : {"claim", "method", "boxes", "max_depth", "smallest_box", "result"}) CHECK(rec.contains(k));
            CHECK(rec["result"].get<std::string>().rfind(rec["expected"].get<std::string>(), 0) == 0);
        } else {
            REQUIRE(rec["table"] == "enclosures");
            ++enclosures;
            CHECK(rec["enclosure_mid"].is_string());
            CHECK(rec["closed_form_inside"] == true);
            CHECK(rec["quadrature_inside"] == true);
        }
    }
    CHECK(proofs == 8);
    CHECK(enclosures == 1 + 6 * 2);  // lambert once, the six rows with an exponent at two n
    for (const char* f : {"proofs.md", "proofs.csv", "proofs.json", "enclosures.md", "enclosures.csv", "enclosures.json"})
        CHECK(fs::exists(dir / f));
    fs::remove_all(dir);
}

TEST_CASE("an option's value that is itself an option is refused: exit 2, both named, nothing written") {
    struct bad {
        const char* args;
        const char* named;
    };
    const auto b = GENERATE(values<bad>({
        {"zoo --n 1 --out --json", "--out: missing its value ('--json'"},
        {"--out --json", "--out: missing its value ('--json'"},
        {"zoo --n 1 --out -h", "--out: missing its value ('-h'"},
        {"zoo --n 1 --out --check", "--out: missing its value ('--check'"},
        {"zoo --n 1 --out results --junit --json", "--junit: missing its value ('--json'"},
        {"zoo --n 1 --out results --junit --out", "--junit: missing its value ('--out'"},
        {"audit --seed --json --out results", "--seed: missing its value ('--json'"},
    }));
    const auto dir = fresh_dir("option-value");
    const auto r = run_in(dir, b.args);
    CAPTURE(b.args, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.rfind("verify: ", 0) == 0);
    CHECK(r.out.find(b.named) != std::string::npos);
    CHECK(fs::is_empty(dir));  // no folder named "--json", no results/
    fs::remove_all(dir);
}

TEST_CASE("an output path that cannot be written is bad input: exit 2, the path named, nothing written") {
    const auto dir = fresh_dir("unwritable");
    std::ofstream(dir / "file") << "not a folder\n";
    const std::string out = " --out " + (dir / "out").string();
    struct bad {
        std::string args, named;
    };
    const auto b = GENERATE_COPY(values<bad>({
        {"zoo --n 1 --out /proc/normzoo-out", "--out: '/proc/normzoo-out'"},
        {"zoo --n 1 --out " + (dir / "file" / "sub").string(), "--out: '" + (dir / "file" / "sub").string() + "'"},
        {"zoo --n 1 --out " + (dir / "file").string(), "is not a folder"},
        {"zoo --n 1 --junit /proc/normzoo-out/j.xml" + out, "--junit: '/proc/normzoo-out/j.xml'"},
        {"zoo --n 1 --junit " + (dir / "nosuch" / "j.xml").string() + out, (dir / "nosuch" / "j.xml").string()},
        {"zoo --n 1 --junit " + dir.string() + out, "--junit: '" + dir.string() + "' is a folder"},
    }));
    const auto r = run_in(dir, b.args);
    CAPTURE(b.args, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.rfind("verify: ", 0) == 0);
    CHECK(r.out.find(b.named) != std::string::npos);
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);  // only "file"
    CHECK(slurp(dir / "file") == "not a folder\n");
    CHECK(!fs::exists("/proc/normzoo-out"));
    fs::remove_all(dir);
}

TEST_CASE("verify --scene: the bounds of the Blinn-Phong rows its materials use, and no other") {
    const auto dir = fresh_dir("scene-bounds");
    // rtr-approximation.toml: one material, blinn-phong-modified over [1, 256]
    const auto r = run("--scene " + std::string(NORMZOO_SOURCE_DIR) + "/scenes/rtr-approximation.toml --json --out " +
                       dir.string());
    REQUIRE(r.status == 1);
    const auto doc = nlohmann::json::parse(r.out);
    std::size_t bounds = 0;
    for (const auto& rec : doc["records"])
        if (rec["table"] == "bounds") {
            ++bounds;
            CHECK(rec["row"] == "blinn-phong-modified");
            CHECK(rec["n"].get<double>() >= 1);
            CHECK(rec["n"].get<double>() <= 256);
        }
    CHECK(bounds > 2);
    bool skipped = false;
    for (const auto& k : doc["skipped"]) skipped = skipped || k["table"] == "bounds: blinn-phong";
    CHECK(skipped);
    fs::remove_all(dir);
}

TEST_CASE("a failing check says why on the console: one line per record, at most 20 per table") {
    const auto dir = fresh_dir("verdicts");
    const auto r = run("--scene " + std::string(NORMZOO_SOURCE_DIR) + "/scenes/rtr-approximation.toml --out " + dir.string());
    CHECK(r.status == 1);
    const auto lines = lines_starting(r.out, "  shader-normalization: ");
    REQUIRE(lines.size() == 1);
    CAPTURE(lines[0]);
    CHECK(lines[0].find("material \"plastic\" (blinn-phong-modified, n in [1, 256], (n+8)/(8*pi))") != std::string::npos);
    CHECK(lines[0].find("relative error") != std::string::npos);
    CHECK(lines[0].find("above the tolerance 0.001") != std::string::npos);
    CHECK(lines[0].find("gains energy") != std::string::npos);

    // Two forms that gain energy at every exponent: 28 failing summaries, 20 lines and the count of the rest.
    const fs::path scene = dir / "gains.toml";
    std::ofstream(scene) << "[[materials]]\nname = 'p'\nmodel = 'phong'\nexponent = [1.0, 1e5]\n"
                            "[[materials]]\nname = 'm'\nmodel = 'minimalist-cook-torrance'\nexponent = [1.0, 1e5]\n";
    const auto g = run("--scene " + scene.string() + " --out " + (dir / "out").string());
    CHECK(g.status == 1);
    const auto head = lines_starting(g.out, "energy-summary: ");
    REQUIRE(head.size() == 1);
    const std::size_t failing = std::stoul(head[0].substr(head[0].find("records, ") + 9));
    CAPTURE(g.out);
    REQUIRE(failing > 20);
    const auto shown = lines_starting(g.out, "  energy-summary: material ");
    CHECK(shown.size() == 20);
    for (const auto& l : shown) CHECK(l.find("gains energy, which the scene does not allow") != std::string::npos);
    CHECK(lines_starting(g.out, "  ... and " + std::to_string(failing - 20) + " more failing energy-summary").size() == 1);
    fs::remove_all(dir);
}

TEST_CASE("junit: test names from ids and inputs only, a failure keeps its whole verdict, the scene names its suites") {
    const auto dir = fresh_dir("junit-names");
    REQUIRE(run("zoo --n 1,8 --junit " + (dir / "j.xml").string() + " --out " + dir.string()).status == 0);
    const std::string xml = slurp(dir / "j.xml");
    std::set<std::string> names;
    for (std::size_t p = xml.find("<testcase"); p != std::string::npos; p = xml.find("<testcase", p + 1))
        if (xml_attribute(xml, "classname", p) == "normzoo.zoo") names.insert(xml_attribute(xml, "name", p));
    std::set<std::string> expected{"row = lambert, n = 0"};
    for (const char* row : {"phong", "phong-modified", "blinn-phong", "blinn-phong-modified", "blinn-phong-heightfield",
                            "blinn-phong-ndf"})
        for (const char* n : {"1", "8"}) expected.insert(std::string("row = ") + row + ", n = " + n);
    CAPTURE(xml.substr(0, 2000));
    CHECK(names == expected);  // no computed value in a name

    // compositions (the white furnace of a compensated one is a check): named by their inputs as
    // typed, one name per (model, roughness, incidence)
    REQUIRE(run("energy --model ggx/smith-height-correlated/one/turquin --alpha 0.3,0.5 --mu 0.5,1 --json --junit " +
                (dir / "c.xml").string()).status == 0);
    const std::string cx = slurp(dir / "c.xml");
    std::set<std::string> composition_names;
    for (std::size_t p = cx.find("<testcase"); p != std::string::npos; p = cx.find("<testcase", p + 1))
        composition_names.insert(xml_attribute(cx, "name", p));
    std::set<std::string> composition_expected;
    for (const char* alpha : {"0.3", "0.5"})
        for (const char* mu : {"0.5", "1"})
            composition_expected.insert(std::string("model = ggx/smith-height-correlated/one/turquin, alpha_input = ") + alpha +
                                        ", mu_input = " + mu);  // no f0: no part of it reads one
    CAPTURE(cx.substr(0, 2000));
    CHECK(composition_names == composition_expected);

    const auto r = run("--scene " + std::string(NORMZOO_SOURCE_DIR) + "/scenes/rtr-approximation.toml --junit " +
                       (dir / "scene.xml").string() + " --out " + (dir / "scene").string());
    REQUIRE(r.status == 1);
    const auto lines = lines_starting(r.out, "  shader-normalization: ");
    REQUIRE(lines.size() == 1);
    const std::string verdict = lines[0].substr(2);
    const std::string sx = slurp(dir / "scene.xml");
    CAPTURE(sx);
    CHECK(sx.find("<testsuite name=\"normzoo.(n+8)/(8 pi) shader.shader-normalization\"") != std::string::npos);
    const std::size_t f = sx.find("<failure");
    REQUIRE(f != std::string::npos);
    const std::string message = xml_attribute(sx, "message", f);
    const std::size_t body = sx.find('>', f) + 1;
    CHECK(xml_unescaped(sx.substr(body, sx.find("</failure>", f) - body)).find(verdict) != std::string::npos);
    // The message is the verdict, or its start cut between words.
    if (message != verdict) {
        REQUIRE(message.size() > 4);
        REQUIRE(message.compare(message.size() - 4, 4, " ...") == 0);
        const std::string kept = message.substr(0, message.size() - 4);
        CHECK(verdict.rfind(kept, 0) == 0);
        CHECK(verdict[kept.size()] == ' ');
    }
    fs::remove_all(dir);
}
