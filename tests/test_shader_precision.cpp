#include <catch2/catch.hpp>
#include <normzoo/normzoo.hpp>
#include <verify/tables/tables.hpp>

#include <cmath>

using normzoo::shader::half;

namespace {

const normzoo::shader::formula& formula_by_id(const std::string& id) {
    for (const auto& f : normzoo::shader::formulas())
        if (f.id == id) return f;
    FAIL("no formula " << id);
    throw;
}

double as_double(half h) { return static_cast<double>(h); }

}  // namespace

TEST_CASE("half rounds to 11 significant bits, to nearest even, with binary16's range") {
    CHECK(as_double(half(1.0) + half(0x1p-11)) == 1.0);       // a tie: to even, 1
    CHECK(as_double(half(1.0) + half(0x1p-10)) == 1 + 0x1p-10);  // the next half after 1
    CHECK(as_double(half(1.0) + half(3 * 0x1p-12)) == 1 + 0x1p-10);
    CHECK(as_double(half(2049)) == 2048);   // tie between 2048 and 2050: to even
    CHECK(as_double(half(2051)) == 2052);
    CHECK(as_double(half::max()) == 65504);
    CHECK(as_double(half(65519.99)) == 65504);
    CHECK(std::isinf(as_double(half(65520))));  // halfway to 2^16: rounds to even, which is inf
    CHECK(std::isinf(as_double(half::max() + half(16))));
    CHECK(as_double(half::min_normal()) == 0x1p-14);
    CHECK(as_double(half::denorm_min()) == 0x1p-24);
    CHECK(as_double(half(0x1p-25)) == 0);  // tie between 0 and 2^-24
    CHECK(as_double(half(3 * 0x1p-26)) == 0x1p-24);
    CHECK(half(1.0).to_bits() == 0x3c00);
}

TEST_CASE("half rounds every operation, not only the end result (no excess precision)") {
    const half one(1.0), tiny(0x1p-11);
    // In float, 1 + 2^-11 + 2^-11 = 1 + 2^-10 exactly, which a half can hold; rounding after
    // each + gives 1.
    CHECK(as_double(one + tiny + tiny) == 1.0);
    CHECK(std::isinf(as_double(half::max() * half(2) / half(4))));  // in float: 32752
    CHECK(as_double(half(1) / half(3)) == 0x1.554p-2);  // 1/3 to 11 bits
    CHECK(as_double(half(M_PI)) == 3.140625);
}

TEST_CASE("the formulas' exact values are the library's closed forms") {
    using normzoo::quad;
    const auto n = GENERATE(0.0, 0.5, 8.0, 2048.0, 1e5);
    auto exact = [&](const char* id) { return formula_by_id(id).exact(quad(n), quad(0)); };
    auto close = [](const quad& a, const quad& b) { return abs(a / b - 1) < quad(1e-32); };
    CHECK(close(exact("phong, blinn-phong-ndf"), normzoo::zoo::phong::closed_form(quad(n))));
    CHECK(close(exact("phong, blinn-phong-ndf"), normzoo::zoo::blinn_phong_ndf::closed_form(quad(n))));
    CHECK(close(exact("phong-modified, blinn-phong-heightfield"), normzoo::zoo::phong_modified::closed_form(quad(n))));
    CHECK(close(exact("phong-modified, blinn-phong-heightfield"),
                normzoo::zoo::blinn_phong_heightfield::closed_form(quad(n))));
    CHECK(close(exact("blinn-phong"), normzoo::zoo::blinn_phong::closed_form(quad(n))));
    CHECK(close(exact("blinn-phong-modified"), normzoo::zoo::blinn_phong_modified::closed_form(quad(n))));
    CHECK(close(exact("blinn-phong-modified, reordered"), normzoo::zoo::blinn_phong_modified::closed_form(quad(n))));
    CHECK(close(exact("microfacet-blinn (n+2)/(8 pi)"), normzoo::brdf::microfacet_blinn::constant(quad(n))));
    CHECK(close(exact("approx (n+8)/(8 pi)"), normzoo::brdf::blinn_phong_modified_approx::constant(quad(n))));
    CHECK(close(formula_by_id("lambert").exact(quad(n), quad(0)), normzoo::zoo::lambert::closed_form(quad(n))));
}

TEST_CASE("Schlick, its exp2 form and the gloss decoding: exact values against their definitions") {
    using normzoo::quad;
    const double x = GENERATE(0.0, 0.25, 0.5, 0.9, 1.0);
    const auto& schlick = formula_by_id("schlick");
    CHECK(abs(schlick.exact(quad(x), 0) - normzoo::brdf::fresnel_schlick(quad("0.04"), quad(x))) < quad(1e-32));
    // 8.656170 = 6 / ln 2 to 7 digits: exp2(-8.656170 x) is exp(-6 x) to 3e-8 x
    const double e = static_cast<double>(formula_by_id("schlick exp2").exact(quad(x), 0));
    CHECK(e == Approx(0.04 + 0.96 * std::exp(-6 * x)).epsilon(1e-7));
    const int k = GENERATE(0, 1, 128, 255);
    CHECK(static_cast<double>(formula_by_id("gloss").exact(quad(k), 0)) == Approx(std::exp2(10.0 * k / 255 + 1)).epsilon(1e-15));
}

TEST_CASE("the audit finds overflows derived by hand") {
    // (n + 2) / (2 PI) in fp16: n + 2 at n = 65504 rounds back to 65504 (the spacing there is 32),
    // so the formula never overflows before n itself does: n >= 65520 rounds to inf.
    const auto a = verify::audit_shader_formula(formula_by_id("phong-modified, blinn-phong-heightfield"),
                                                 verify::shader_precision_kind::fp16);
    REQUIRE(a.breaks_at);
    CHECK(*a.breaks_at == 65520);
    CHECK(a.breaks_because == "input overflow");

    // (n + 2) * (n + 4) / ... in fp16 overflows when (n + 2)(n + 4) rounds to >= 65520. The halves
    // between 128 and 256 are 1/8 apart. At n = 252.875: n + 4 = 256.875 rounds to even, 257, and
    // 254.875 * 257 = 65502.875 rounds to 65504 (finite). At n = 253: 255 * 257 = 65535 -> inf.
    // An input n in [252.9375, 253) rounds up to 253 (252.9375 is the tie, and 253 = 2024/8 is even).
    const auto b = verify::audit_shader_formula(formula_by_id("blinn-phong-modified"), verify::shader_precision_kind::fp16);
    REQUIRE(b.breaks_at);
    CHECK(*b.breaks_at == 252.9375);
    CHECK(b.breaks_because == "overflow");
    // Reordered, (n + 2) / (8 PI) * ((n + 4) / (2^(-n/2) + n)) has no intermediate above n + 4: it lasts
    // until n itself overflows.
    const auto b2 = verify::audit_shader_formula(formula_by_id("blinn-phong-modified, reordered"),
                                                  verify::shader_precision_kind::fp16);
    REQUIRE(b2.breaks_at);
    CHECK(*b2.breaks_at == 65520);
    CHECK(b2.max_rel_error < 8 * 0x1p-11);

    // exp2(m * c - m): m * c and m are each rounded with an error up to m 2^-12, so their difference
    // (the exponent) is off by up to about m 2^-11 and the lobe by a factor 2^(m 2^-11): all accuracy
    // is gone (error >= 1, a factor 2) once m 2^-11 reaches about 1, m = (n + 1) / ln 2 ~ 2^11, n ~ 1400.
    // It must break by n = 4 * 1400 and not before n = 1400 / 4.
    const auto c = verify::audit_shader_formula(formula_by_id("spherical gaussian"), verify::shader_precision_kind::fp16);
    REQUIRE(c.breaks_at);
    CHECK(*c.breaks_at > 350);
    CHECK(*c.breaks_at < 5600);
    CHECK(c.breaks_because == "accuracy");
    // Its factored form exp2(m * (c - 1)) has c - 1 exact: it lasts until m = (n + 1) * 1.442695 overflows
    // fp16 near n = 65520 / 1.442695 - 1 = 45414, where inf * (c - 1 = 0) at the peak is NaN.
    const auto d = verify::audit_shader_formula(formula_by_id("spherical gaussian, factored"),
                                                 verify::shader_precision_kind::fp16);
    REQUIRE(d.breaks_at);
    CHECK(*d.breaks_at == Approx(65520 / 1.442695 - 1).epsilon(2e-3));
}

TEST_CASE("fp32 errors at a few points, evaluated independently") {
    // (n + 2) / (2 * PI) in float, written out here, against the exact value at the same float n.
    const float n = GENERATE(0.5f, 3.0f, 1000.25f, 123456.0f);
    const float pi_f = 3.14159265358979323846f;
    const float mine = (n + 2.0f) / (2.0f * pi_f);
    const auto& f = formula_by_id("phong-modified, blinn-phong-heightfield");
    CHECK(f.f32(n, 0) == mine);
    const long double exact = (static_cast<long double>(n) + 2) / (2 * 3.141592653589793238462643383279502884L);
    const double rel = static_cast<double>(std::fabs(mine / exact - 1));
    CHECK(rel < 2 * 0x1p-24);
    CHECK(static_cast<double>(abs(normzoo::quad(mine) / f.exact(normzoo::quad(n), 0) - 1)) == Approx(rel).epsilon(1e-9));
}

TEST_CASE("the table: every formula in both precisions, fp16 worse than fp32 on the range where both work") {
    const auto rs = verify::shader_precision_table(2);
    REQUIRE(rs.size() == 2 * normzoo::shader::formulas().size());
    auto number = [](const verify::record& r, const char* key) {
        const auto* v = r.find(key);
        return v && std::holds_alternative<double>(*v) ? std::get<double>(*v) : -1.0;
    };
    for (std::size_t i = 0; i < rs.size(); i += 2) {
        INFO(std::get<std::string>(*rs[i].find("formula")));
        CHECK(std::get<std::string>(*rs[i].find("precision")) == "fp16");
        CHECK(std::get<std::string>(*rs[i + 1].find("precision")) == "fp32");
        // Over n <= 2048 where both have it; else over the whole range when fp32 never breaks (fp16's
        // range is then a part of fp32's).
        const bool both_to_2048 = number(rs[i], "max_rel_error_n_to_2048") >= 0 && number(rs[i + 1], "max_rel_error_n_to_2048") >= 0;
        const char* key = both_to_2048 ? "max_rel_error_n_to_2048" : "max_rel_error";
        if (!both_to_2048 && rs[i + 1].find("breaks_because")->index() != 0) continue;
        CHECK(number(rs[i], key) > number(rs[i + 1], key));
        CHECK(number(rs[i + 1], key) >= 0);
    }
}
