// The command end to end: microfacet compositions D/G/F and their parts' parameters.
#include "cli_helpers.hpp"

using namespace cli_test;

TEST_CASE("microfacet compositions: energy --model D/G/F records, and bad input naming the value") {
    const auto r = run("energy --model ggx/smith-height-correlated/one --alpha 1 --mu 0.1,0.5,1 --json");
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    REQUIRE(doc["records"].size() == 3);
    for (const auto& rec : doc["records"]) {
        for (const char* key : {"model", "alpha", "mu", "albedo", "error_estimate"}) CHECK(rec.contains(key));
        const double mu = rec["mu"].get<double>();
        const double exact = 1 - mu * std::log1p(1 / mu);  // docs/microfacet.md, alpha = 1
        CHECK(std::abs(rec["albedo"].get<double>() - exact) <= rec["error_estimate"].get<double>());
    }
    // --r: alpha = r^2; --theta instead of --mu
    const auto by_r = nlohmann::json::parse(run("energy --model ggx/smith-separable/one --r 0.5 --theta 60 --json").out);
    REQUIRE(by_r["records"].size() == 1);
    CHECK(by_r["records"][0]["alpha"].get<double>() == 0.25);
    // F0 = 1 (the default) is an infinite index for the exact Fresnel parts: F = 1, their limit,
    // not NaN, so their albedo is the white furnace's
    for (const char* f : {"dielectric", "conductor"}) {
        const auto exact_f = nlohmann::json::parse(
            run(std::string("energy --model ggx/smith-height-correlated/") + f + " --alpha 0.5 --mu 0.5 --json").out);
        const auto one = nlohmann::json::parse(run("energy --model ggx/smith-height-correlated/one --alpha 0.5 --mu 0.5 --json").out);
        CAPTURE(f);
        REQUIRE(exact_f["records"][0]["albedo"].is_number());
        CHECK(exact_f["records"][0]["albedo"].get<double>() == one["records"][0]["albedo"].get<double>());
        CHECK(exact_f["records"][0]["conserving"].get<bool>());
    }
    const std::pair<const char*, const char*> bad[] = {
        {"energy --model ggx/smith-separable/one --alpha 0.3 --mu 1e-9", "1e-9"},
        {"energy --model beckmann/smith-separable/one --alpha 0.3 --theta 89.99999999", "89.99999999"},
        {"lut --kind E --alpha 0.3 --mu 1e-160", "1e-160"},
        {"energy --model ggx/smith/one --alpha 0.5", "'smith'"},
        {"energy --model ggx/smith-separable/one --alpha 0", "'0'"},
        {"energy --model ggx/smith-separable/one --alpha nan", "'nan'"},
        // below the smallest roughness taken (alpha 1e-8, r 1e-4): at 1e-100 GGX's integral gave NaN
        {"energy --model ggx/smith-height-correlated/one --alpha 1e-100 --mu 1", "'1e-100'"},
        {"lut --kind E --r 1e-5 --mu 1", "'1e-5'"},
        {"lut --kind dfg --alpha 1e-9 --mu 0.5", "'1e-9'"},
        {"lut --kind E --alpha --mu 1", "--alpha: missing its value"},
        {"energy --model ggx/smith-separable/one --mu 1.5", "'1.5'"},
        {"energy --model ggx/smith-separable/one --f0 -1", "'-1'"},
        {"energy --model ggx/implicit/one/multiple", "'multiple'"},
        {"energy --model ward --alpha 0.3", "--alpha"},
        {"lut --kind dfg --size 4 --model ggx/smith-separable/fresnel", "'fresnel'"},
        {"lut --kind XYZ --size 4", "'XYZ'"},
        {"energy --model ggx/smith-separable/one --alpha 0.3 --mu 0.5 --n 5", "--n is the exponent of the BRDF forms"},
        {"energy --model ggx/smith-separable/one,ggx --alpha 0.3 --mu 0.5", "unknown name 'ggx'"},
        {"energy --model ggx/smith-separable/one,ward --alpha 0.3 --mu 0.5", "'ward' is a BRDF form and the others are compositions"}};
    for (const auto& [args, named] : bad) check_refused(args, named);
    // scenes: a composition's keys checked, the file and line named, exit 2
    const auto dir = normzoo_test::fresh_dir("composition-scenes");
    const std::pair<const char*, const char*> scenes[] = {
        {"model = \"ggx/smith-height-correlated/one\"\nr = [0.1, 0.5]\nf0 = 1.5\n", "f0"},
        {"model = \"ggx/smith-height-correlated/one\"\nalpha = [0, 0.5]\n", "alpha"},
        {"model = \"ggx/smith-height-correlated/one\"\nalpha = [1e-9, 0.5]\n", "alpha: must be in [1e-8, 100]"},
        {"model = \"ggx/smith-height-correlated/one\"\nalpha = [1e-400, 0.5]\n", "s.toml:4: materials[1].alpha: '1e-400' is too small to hold in a double"},
        {"model = \"ggx/smith/one\"\nr = [0.1, 0.5]\n", "'smith'"},
        {"model = \"ggx/smith-separable/one\"\nexponent = [1, 2]\n", "exponent"},
        {"model = \"ggx/smith-separable/one\"\nr = [0.1, 0.5]\nlut = \"missing.png\"\n", "s.toml:5: materials[1].lut: '"},
        {"model = \"ggx/smith-separable/one\"\nr = [0.1, 0.5]\nlut_kind = \"E\"\n", "lut_kind: it describes the table of 'lut'"},
        {"model = \"ggx/smith-separable/one\"\nr = [0.1, 0.5]\nlut_map = \"alpha\"\n", "lut_map: it describes the table of 'lut'"},
        // a part parameter the composition does not read: at its own line, not the material's
        {"model = \"ggx/smith-height-correlated/one\"\nr = [0.2, 1.0]\nf0 = 0.04\n", "s.toml:5: materials[1].f0: f0"},
        // the table's own complaint, at the scene's line that names it
        {"model = \"ggx/smith-separable/one\"\nr = [0.1, 0.5]\nlut = \"text.png\"\n", "s.toml:5: materials[1].lut: "}};
    std::ofstream(dir / "text.png") << "not an image\n";
    for (const auto& [body, named] : scenes) check_scene_refused(dir, body, named, "microfacet-energy.md");
    fs::remove_all(dir);
}

TEST_CASE("microfacet compositions: the parts' own parameters from the command line and scenes, and bad ones named") {
    auto albedo = [](const std::string& args) {
        const auto r = run("energy " + args + " --json");
        CAPTURE(args);
        REQUIRE(r.status == 0);
        const auto rec = nlohmann::json::parse(r.out)["records"][0];
        return std::make_pair(rec["albedo"].get<double>(), rec["error_estimate"].get<double>());
    };
    auto same = [](std::pair<double, double> a, std::pair<double, double> b) { return std::abs(a.first - b.first) <= a.second + b.second; };
    const std::string at = " --alpha 0.3 --mu 0.5";
    // F90 = F0 makes schlick-f90 the constant F0: F0 times the white furnace's albedo
    const auto one = albedo("--model ggx/smith-height-correlated/one" + at);
    const auto flat = albedo("--model ggx/smith-height-correlated/schlick-f90 --f0 0.25 --f90 0.25" + at);
    CHECK(std::abs(flat.first - 0.25 * one.first) <= flat.second + 0.25 * one.second);
    CHECK(!same(flat, albedo("--model ggx/smith-height-correlated/schlick --f0 0.25" + at)));
    // eta = 1.5 is F0 = 0.04 exactly ((1.5 - 1)/(1.5 + 1))^2; a conductor with k = 0 is that dielectric
    const auto glass = albedo("--model ggx/smith-height-correlated/dielectric --eta 1.5" + at);
    CHECK(same(glass, albedo("--model ggx/smith-height-correlated/dielectric --f0 0.04" + at)));
    CHECK(same(glass, albedo("--model ggx/smith-height-correlated/conductor --eta 1.5 --k 0" + at)));
    const auto metal = run("energy --model ggx/smith-height-correlated/conductor --eta 0.18 --k 3.42" + at + " --json");
    REQUIRE(metal.status == 0);
    const auto m = nlohmann::json::parse(metal.out)["records"][0];
    CHECK(m["eta"].get<double>() == 0.18);
    CHECK(m["k"].get<double>() == 3.42);
    CHECK(!m.contains("f90"));
    // the inputs as typed beside the doubles; no F0 where eta replaces it, nor where no part reads it
    CHECK((m["eta_input"] == "0.18" && m["k_input"] == "3.42"));
    CHECK(!m.contains("f0"));
    const auto white = nlohmann::json::parse(run("energy --model ggx/smith-height-correlated/one" + at + " --json").out)["records"][0];
    CHECK(!white.contains("f0"));
    const auto schlick = nlohmann::json::parse(run("energy --model ggx/smith-height-correlated/schlick --f0 .040" + at + " --json").out)["records"][0];
    CHECK((schlick["f0"] == 0.04 && schlick["f0_input"] == ".040"));
    // a sweep that mixes them: the CSV's f0 columns stay among the inputs, before the results
    const auto mixed = normzoo_test::fresh_dir("mixed-f0");
    REQUIRE(run("energy --model ggx/smith-height-correlated/one,ggx/smith-height-correlated/schlick --f0 0.04" + at + " --out '" +
                mixed.string() + "'").status == 0);
    const std::string table = normzoo_test::slurp(mixed / "energy.csv");
    const auto head = table.find("\ntable,");
    REQUIRE(head != std::string::npos);
    const std::string columns = table.substr(head + 1, table.find('\n', head + 1) - head - 1);
    CAPTURE(columns);
    CHECK(columns.find(",mu_input,f0,f0_input,albedo,") != std::string::npos);
    fs::remove_all(mixed);
    CHECK(m["albedo"].get<double>() > glass.first + 0.5);  // gold-like: most of what one bounce keeps
    CHECK(m["albedo"].get<double>() < one.first);
    // an anisotropic D with aspect 1 is the isotropic one; at normal incidence its axes can swap
    CHECK(same(albedo("--model ggx-aniso/smith-height-correlated/one --aspect 1" + at), one));
    const auto wide = albedo("--model ggx-aniso/smith-height-correlated/one --aspect 4 --alpha 0.2 --mu 1");
    CHECK(same(wide, albedo("--model ggx-aniso/smith-height-correlated/one --aspect 0.25 --alpha 0.8 --mu 1")));
    CHECK(!same(wide, albedo("--model ggx/smith-height-correlated/one --alpha 0.2 --mu 1")));
    // the compensations read the index too: Turquin's F0 is F(1), Kulla-Conty's F_avg the part's
    for (const char* compensation : {"turquin", "kulla-conty"}) {
        CAPTURE(compensation);
        CHECK(same(albedo(std::string("--model ggx/smith-height-correlated/dielectric/") + compensation + " --eta 1.5" + at),
                   albedo(std::string("--model ggx/smith-height-correlated/dielectric/") + compensation + " --f0 0.04" + at)));
    }
    // GTR near gamma = 1 is continuous (its constant's 1 - a^(2 (1 - gamma)) is not left to cancel)
    const auto berry = albedo("--model gtr/implicit/one --gamma 1" + at);
    const auto near_berry = albedo("--model gtr/implicit/one --gamma 1.000000000001" + at);
    CHECK(std::abs(berry.first - near_berry.first) <= berry.second + near_berry.second + 1e-11);
    // GTR at gamma = 2 is GGX
    const auto ggx = albedo("--model ggx/implicit/one" + at);
    CHECK(same(albedo("--model gtr/implicit/one --gamma 2" + at), ggx));
    CHECK(!same(albedo("--model gtr/implicit/one --gamma 1.5" + at), ggx));
    const std::pair<const char*, const char*> bad[] = {
        {"energy --model ggx/smith-separable/dielectric --eta 0", "'0'"},
        {"energy --model ggx/smith-separable/dielectric --eta -1.5", "'-1.5'"},
        {"energy --model ggx/smith-separable/dielectric --eta nan", "'nan'"},
        {"energy --model ggx/smith-separable/dielectric --eta 1.5,2", "one value"},
        {"energy --model ggx/smith-separable/conductor --k -1", "'-1'"},
        {"energy --model ggx/smith-separable/schlick-f90 --f90 1.5", "'1.5'"},
        {"energy --model ggx-aniso/smith-separable/one --aspect 0.001", "'0.001'"},
        {"energy --model gtr/implicit/one --gamma 11", "'11'"},
        {"energy --model ggx/smith-separable/schlick --eta 1.5", "eta = 1.5: no part of 'ggx/smith-separable/schlick' reads it (the parts that do: dielectric, conductor)"},
        {"energy --model ggx/smith-separable/dielectric --k 2", "k = 2"},
        {"energy --model ggx/smith-separable/conductor --k 3.42", "k = 3.42: a conductor's k goes with its index, --eta"},
        {"energy --model ggx/smith-separable/one --f0 0.5", "f0 = 0.5: no part of 'ggx/smith-separable/one' reads it"},
        {"energy --model ggx/smith-separable/dielectric --f0 0.04 --eta 1.5", "f0 and --eta"},
        {"energy --model ward --eta 1.5", "--eta applies to microfacet compositions"},
        {"lut --kind dfg --size 4 --eta 1.5", "--eta is for --kind E and Eavg"},
        {"lut --kind E --size 4 --aspect 2", "aspect = 2: no part"},
        {"lut --kind dfg --size 4 --out --json", "--out: missing its value"},
        {"lut --kind dfg --size 4 --out ''", "--out: the path is empty"},
        {"lut --kind dfg --check --json", "--check: missing its value"}};
    for (const auto& [args, named] : bad) check_refused(args, named);
    const auto dir = normzoo_test::fresh_dir("part-parameter-scenes");
    const std::pair<const char*, const char*> scenes[] = {
        {"model = \"ggx/smith-height-correlated/dielectric\"\nr = [0.1, 0.5]\neta = 0\n", "s.toml:5"},
        {"model = \"ggx/smith-height-correlated/schlick\"\nr = [0.1, 0.5]\neta = 1.5\n", "eta = 1.5: no part"},
        {"model = \"ggx/smith-height-correlated/one\"\nr = [0.1, 0.5]\nf90 = 0.5\n", "f90 = 0.5"},
        {"model = \"blinn-phong\"\nexponent = [1, 2]\ngamma = 1.5\n", "gamma"}};
    for (const auto& [body, named] : scenes) check_scene_refused(dir, body, named, "");
    // a scene's parameters reach the sweep: the records carry them
    std::ofstream(dir / "s.toml") << "[[materials]]\nname = \"gold\"\nmodel = \"ggx/smith-height-correlated/conductor\"\n"
                                     "alpha = [0.3, 0.3]\neta = 0.18\nk = 3.42\n";
    const auto g = run_shell(std::string(NORMZOO_VERIFY_BIN) + " --scene '" + (dir / "s.toml").string() + "' --json");
    REQUIRE(g.status == 0);
    const auto gold = nlohmann::json::parse(g.out);
    std::size_t swept = 0;
    for (const auto& rec : gold["records"])
        if (rec["table"] == "microfacet-energy") {
            CHECK((rec["eta"].get<double>() == 0.18 && rec["k"].get<double>() == 3.42));
            ++swept;
        }
    CHECK(swept == 8);  // one alpha, eight mu
    // a scene's E table is checked at the material's F0
    REQUIRE(run("lut --kind E --model ggx/smith-height-correlated/schlick --f0 0.04 --size 4 --map alpha --out '" + dir.string() + "'").status == 0);
    std::ofstream(dir / "s.toml") << "[[materials]]\nname = \"plastic\"\nmodel = \"ggx/smith-height-correlated/schlick\"\n"
                                     "alpha = [0.3, 0.3]\nf0 = 0.04\nlut = \"lut-E-4.csv\"\nlut_kind = \"E\"\n";
    const auto e = run_shell(std::string(NORMZOO_VERIFY_BIN) + " --scene '" + (dir / "s.toml").string() + "' --json");
    CHECK(e.status == 0);
    std::size_t checked = 0;
    const auto plastic = nlohmann::json::parse(e.out);
    for (const auto& rec : plastic["records"])
        if (rec["table"] == "lut-check") {
            CHECK(rec["max_abs_error"].get<double>() < 1e-12);
            ++checked;
        }
    CHECK(checked == 1);
    // a CSV's header names its roughness: lut_map beside one is refused, as --map is
    check_scene_refused(dir, "model = \"ggx/smith-height-correlated/schlick\"\nalpha = [0.3, 0.3]\nlut = \"lut-E-4.csv\"\n"
                             "lut_kind = \"E\"\nlut_map = \"alpha\"\n", "s.toml:7: materials[1].lut_map: it is for an image", "");
    check_refused("lut --kind E --check '" + (dir / "lut-E-4.csv").string() + "' --map alpha", "lut: --map is for an image");
    fs::remove_all(dir);
}
