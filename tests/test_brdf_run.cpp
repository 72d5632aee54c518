// verify --brdf end to end (docs/brdf-code.md): the direction the albedo holds (--fixed), the
// reciprocity tolerance, the albedo of a shader that is NaN only at isolated directions, and what
// a person reads (the parameters and the reasons in the Markdown, the sweeps' decimals, bool and
// list parameters, the header's default function). Each albedo is held to an integral computed
// here. Two shader files, each compiled once (then cached), serve every case.
#include <catch2/catch.hpp>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "brdf_runs.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;
using normzoo_test::run_shell;

namespace {

const double pi = std::acos(-1.0);

// A diffuse lobe times 1 - k (1 - N.V)^2, a factor of N.V alone: not reciprocal for k != 0, as
// engines' multiple-scattering factors of N.V are not. guard takes N.V / (|N.V| + 1e-5), the
// guard some engines put on N.V; cancel loses N.V's digits in float ((N.V + 1e4) - 1e4), a
// breakdown that double does not see. No function key: the function is BRDF.
const char* factor_shader = R"(// [brdf]
// [parameters.k]
// range = [-1, 1]
// default = 0.5
// [parameters.guard]
// type = "bool"
// default = false
// [parameters.cancel]
// type = "bool"
// default = false
//
const float PI = 3.14159265358979323846;

vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)
{
    float NdotV = dot(N, V);
    float guarded = guard ? abs(NdotV) + 1e-5 : NdotV;
    float m = 1.0 - NdotV;
    float f = (1.0 - k * m * m) / PI * NdotV / guarded;
    if (cancel) f = f * ((NdotV + 1.0e4) - 1.0e4) / NdotV;
    return vec3(f);
}
)";

// Oren and Nayar's qualitative model with the azimuths' cosine from the projections of L and V on
// the surface, as BRDF Explorer's Oren-Nayar takes it: normalize of a zero vector, NaN, at V = N
// only (and everywhere when L = N). The clamp max(cos, 0) is written so that NaN goes through it.
const char* oren_nayar_shader = R"(// [brdf]
// function = "OrenNayar"
// [parameters.sigma]
// range = [0, 1.5]
// default = 0.5
//
const float PI = 3.14159265358979323846;

vec3 OrenNayar(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)
{
    float s2 = sigma * sigma;
    float A = 1.0 - 0.5 * s2 / (s2 + 0.33);
    float B = 0.45 * s2 / (s2 + 0.09);
    float cosPhi = dot(normalize(V - N * dot(N, V)), normalize(L - N * dot(N, L)));
    float ti = acos(dot(N, L));
    float tr = acos(dot(N, V));
    return vec3((A + B * 0.5 * (cosPhi + abs(cosPhi)) * sin(max(ti, tr)) * tan(min(ti, tr))) / PI);
}
)";

struct fixture {
    normzoo_test::temp_dir dir{"brdf-run"};
    std::string factor = dir.file("factor.glsl", factor_shader);
    std::string oren_nayar = dir.file("oren-nayar.glsl", oren_nayar_shader);
};

const fixture& files() {
    static const fixture f;
    return f;
}

using normzoo_test::records_of;
using normzoo_test::run;

double integral(const std::function<double(double)>& g, double a, double b) {
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(g, a, b, 15, 1e-14);
}

// The factor shader's albedos, apart from the command: with L held, 2 int_0^1 f(mu) mu dmu (f
// depends on N.V only); with V held at N.V = c, f(c) times the integral of N.L / pi, which is 1.
double factor_f(double k, bool guard, double mu) {
    const double m = 1 - mu;
    return (1 - k * m * m) / pi * mu / (guard ? mu + 1e-5 : mu);
}
double factor_light(double k, bool guard) {
    return 2 * pi * integral([&](double mu) { return factor_f(k, guard, mu) * mu; }, 0, 1);
}
double factor_view(double k, bool guard, double theta_deg) { return pi * factor_f(k, guard, std::cos(theta_deg * pi / 180)); }

}  // namespace

TEST_CASE("verify --brdf --fixed: a BRDF with a factor of N.V alone has two albedos, each its own integral") {
    const std::string common = "--brdf '" + files().factor + "' --param k=0,0.5 --param guard=false,true --theta 0,60 --json";
    std::map<std::string, double> at_60;  // k = 0.5, no guard: by the direction held
    for (const char* fixed : {"light", "view"}) {
        const auto r = run(common + " --fixed " + fixed);
        REQUIRE((r.status == 0 || r.status == 1));  // not reciprocal at k = 0.5: exit 1
        const auto albedos = records_of(r.out, "brdf");
        REQUIRE(albedos.size() == 8);
        for (const auto& a : albedos) {
            const double k = a["param_k"], theta = a["theta_deg"];
            const bool guard = a["param_guard"];
            const double truth = std::string(fixed) == "light" ? factor_light(k, guard) : factor_view(k, guard, theta);
            CAPTURE(fixed, k, guard, theta, a["albedo"], truth);
            CHECK(a["fixed"] == fixed);
            CHECK(std::abs(a["albedo"].get<double>() - truth) <= a["error_estimate"].get<double>() + 1e-14);
            if (k == 0.5 && !guard && theta == 60) at_60[fixed] = a["albedo"];
        }
    }
    // 1 - 0.5/6 with L held, 1 - 0.5 (1 - cos 60)^2 with V held
    CHECK(std::abs(at_60["light"] - 11.0 / 12) < 1e-12);
    CHECK(std::abs(at_60["view"] - 0.875) < 1e-12);
    // a wrong word is bad input
    const auto bad = run("--brdf '" + files().factor + "' --fixed normal", true);
    CHECK(bad.status == 2);
    CHECK(bad.out.find("--fixed: 'normal' is not light or view") != std::string::npos);
}

TEST_CASE("verify --brdf --reciprocity-tolerance: the 1e-5 guard on N.V fails at 1e-9, passes at 1e-3, with by how much") {
    const std::string guarded = "--brdf '" + files().factor + "' --param k=0 --param guard=true --theta 60 --json";
    const auto strict = run(guarded);
    CHECK(strict.status == 1);
    const auto checks = records_of(strict.out, "brdf-checks");
    REQUIRE(checks.size() == 1);
    const auto& c = checks[0];
    CAPTURE(c.dump());
    CHECK(c["pass"] == false);
    CHECK(c["tolerance"] == 1e-9);
    // 1e-5 (1/N.V - 1/N.L) at most, the grid's lowest N.V being cos 86.25 degrees
    CHECK(c["worst"].get<double>() > 1e-5);
    CHECK(c["worst"].get<double>() < 2e-4);
    CHECK(c["reason"].get<std::string>().find("not reciprocal: f(L, V) = ") != std::string::npos);
    const auto loose = run(guarded + " --reciprocity-tolerance 1e-3");
    CHECK(loose.status == 0);
    CHECK(records_of(loose.out, "brdf-checks")[0]["pass"] == true);
    CHECK(records_of(loose.out, "brdf-checks")[0]["reason"].is_null());
    // without the guard f is 1/pi exactly: reciprocal at a tolerance of 0
    CHECK(run("--brdf '" + files().factor + "' --param k=0 --theta 60 --reciprocity-tolerance 0").status == 0);
    CHECK(run("--brdf '" + files().factor + "' --reciprocity-tolerance -1e-3", true).status == 2);
}

TEST_CASE("verify --brdf: NaN only at V = N is excluded from the albedo, flagged, and NaN everywhere gives none") {
    // The albedo over the finite directions: A + (2 B / pi) int_0^1 sin(max(ti, tr)) tan(min(ti, tr)) mu dmu
    // (the azimuth's max(cos phi, 0) integrates to 2), split at the kink mu = cos ti.
    const double s2 = 0.25, A = 1 - 0.5 * s2 / (s2 + 0.33), B = 0.45 * s2 / (s2 + 0.09), ti = pi / 3;
    auto g = [&](double mu) {
        const double tr = std::acos(mu);
        return std::sin(std::max(ti, tr)) * std::tan(std::min(ti, tr)) * mu;
    };
    const double truth = A + 2 * B / pi * (integral(g, 0, std::cos(ti)) + integral(g, std::cos(ti), 1));
    for (const char* fixed : {"light", "view"}) {
        const auto r = run("--brdf '" + files().oren_nayar + "' --theta 0,60 --json --fixed " + fixed);
        CHECK(r.status == 1);  // not finite: a verdict still
        const auto albedos = records_of(r.out, "brdf");
        REQUIRE(albedos.size() == 2);
        const auto& normal = albedos[0];
        const auto& oblique = albedos[1];
        CAPTURE(fixed, normal.dump(), oblique.dump(), truth);
        // L = N: NaN for every V, no albedo
        CHECK(normal["values"] == "non-finite");
        CHECK(normal["albedo"].is_null());
        CHECK(normal["albedo_excludes_non_finite"] == false);
        // 60 degrees: NaN at V = N only, the albedo over the other directions
        CHECK(oblique["values"] == "non-finite");
        CHECK(oblique["problem_V"] == "0,0,1");
        CHECK(oblique["albedo_excludes_non_finite"] == true);
        REQUIRE(oblique["albedo"].is_number());
        CHECK(std::abs(oblique["albedo"].get<double>() - truth) <= oblique["error_estimate"].get<double>() + 1e-14);
        CHECK(std::abs(oblique["albedo_fp32"].get<double>() - truth) <= 1e-5);
        CHECK(oblique["fp32_breakdown"] == false);  // NaN in both is not float against double
        CHECK(oblique["pass"] == false);
        CHECK(oblique["reason"].get<std::string>().find("only at isolated directions: the albedo excludes them") !=
              std::string::npos);
    }
}

TEST_CASE("verify --brdf: its Markdown shows the swept parameters as typed and why a row fails") {
    const std::string factor = "--brdf '" + files().factor + "'";
    // 0.1..0.5 in 5 values is 0.1, 0.2, 0.3, 0.4, 0.5 (0.1 + 0.4 x 0.5 would be 0.30000000000000004)
    const auto swept = run(factor + " --param k=0.1..0.5 --param guard=false,1 --theta 60 --json");
    std::vector<double> ks;
    std::set<bool> guards;
    for (const auto& a : records_of(swept.out, "brdf")) {
        if (a["param_guard"] == false) ks.push_back(a["param_k"]);
        guards.insert(a["param_guard"].get<bool>());
    }
    CHECK(ks == std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5});
    CHECK(guards == std::set<bool>{false, true});
    // the Markdown: a row per value, its parameters in columns, the head their values
    const auto md = run(factor + " --param k=0.1..0.5 --param guard=false,true --param cancel=0 --theta 60").out;
    CAPTURE(md);
    CHECK(md.find("k = 0.1..0.5 in 5 values; guard = false, true; cancel = false") != std::string::npos);
    CHECK(md.find("| file | param_k | param_guard | theta_deg | albedo |") != std::string::npos);
    CHECK(md.find("| " + files().factor + " | 0.3 | true | 60 | 0.9499") != std::string::npos);
    CHECK(md.find("| not reciprocal: f(L, V) = ") != std::string::npos);
    // the reasons: a gain and by how much; float's loss of N.V's digits, where and by how much
    const auto gain = run(factor + " --param k=-0.5 --theta 60").out;
    CHECK(gain.find("| gains energy: albedo 1.083 = 1 + 0.08333 (bound ") != std::string::npos);
    const auto breakdown = run(factor + " --param cancel=true --param k=0 --theta 60").out;
    CAPTURE(breakdown);
    CHECK(breakdown.find("| false | fp32 breaks down: float ") != std::string::npos);
    CHECK(breakdown.find(" relative (above 0.001) |") != std::string::npos);
}

TEST_CASE("verify --brdf --param: bad values exit 2 naming the parameter, before compiling") {
    struct bad {
        const char* param;
        const char* says;
    };
    const auto b = GENERATE(values<bad>({
        {"guard=yes", "--param guard: a bool is true, false, 1 or 0, not 'yes'"},
        {"guard=0..1", "--param guard: only a float parameter takes a range LO..HI"},
        {"k=0.1,,0.2", "--param k: bad value '' in '0.1,,0.2'"},
        {"k=0.1,2", "--param k: 2 is outside its range -1 .. 1"},
        {"k=0.5..0.1", "--param k: the range 0.5..0.1 is empty"},
        {"k=0.1,0.2..0.5", "--param k: a range LO..HI has one number at each end"},
        {"k", "--param k: expected NAME=VALUE, NAME=LO..HI or NAME=A,B,C"},
    }));
    const auto r = run("--brdf '" + files().factor + "' --param " + b.param, true);
    CAPTURE(b.param, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find(b.says) != std::string::npos);
    const auto twice = run("--brdf '" + files().factor + "' --param k=0.1 --param k=0.2", true);
    CHECK(twice.status == 2);
    CHECK(twice.out.find("--param k: given twice") != std::string::npos);
}

TEST_CASE("verify --brdf --out --junit: a test case per record, named by its parameters and incidence") {
    normzoo_test::temp_dir out("brdf-run-out");
    const auto r = run("--brdf '" + files().factor + "' --param k=0,0.5 --theta 0,60 --out '" + out.path.string() + "' --junit '" +
                       (out.path / "j.xml").string() + "'");
    CHECK(r.status == 1);
    for (const char* f : {"brdf.md", "brdf.csv", "brdf.json", "brdf-checks.md", "brdf-checks.csv", "brdf-checks.json"})
        CHECK(fs::exists(out.path / f));
    const std::string xml = normzoo_test::slurp(out.path / "j.xml");
    std::set<std::string> names;
    std::size_t cases = 0;
    for (std::size_t at = xml.find("<testcase "); at != std::string::npos; at = xml.find("<testcase ", at + 1), ++cases) {
        const std::size_t name = xml.find(" name=\"", at) + 7;
        names.insert(xml.substr(name, xml.find('"', name) - name));
    }
    CAPTURE(xml);
    CHECK(cases == 6);  // 4 albedos, 2 reciprocity checks
    CHECK(names.size() == cases);
    CHECK(names.count("file = " + files().factor + ", param_k = 0.5, param_guard = false, param_cancel = false, theta_deg = 60, "
                      "fixed = light") == 1);
    CHECK(normzoo_test::slurp(out.path / "brdf.md").find("| " + files().factor + " | 0.5 | 60 |") != std::string::npos);
}
