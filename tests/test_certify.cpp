#include <catch2/catch.hpp>
#include <verify/tables/enclosures.hpp>
#include <verify/tables/proofs.hpp>

#include <string>

namespace nc = verify::certify;  // the certified tables, and through them the library's certified core
using normzoo::zoo::blinn_phong;
using normzoo::zoo::blinn_phong_modified;
using normzoo::zoo::phong;

namespace {
bool flag(const verify::record& r, const char* k) { return std::get<bool>(*r.find(k)); }
double number(const verify::record& r, const char* k) { return std::get<double>(*r.find(k)); }

template <class Row>
nc::enclosure enclose(double n) {
    return nc::enclose_zoo_integral<Row>(normzoo::decimal::shortest(n), static_cast<double>(1 / Row::closed_form(normzoo::wide(n))));
}
}  // namespace

TEST_CASE("enclosures hold the closed forms and the quadrature, to 1e-40") {
    using R = verify::record (*)(const normzoo::decimal&, const nc::enclosure_check&, const nc::enclosure_settings&);
    // Integer and non-integer n (the branch of cos^n at pi/2 for the alpha = 1 rows), 0, 1e7.
    const auto [id, make, n] = GENERATE(table<const char*, R, double>({
        {"lambert", nc::enclosure_record<normzoo::zoo::lambert>, 0.0},
        {"phong", nc::enclosure_record<phong>, 0.1},
        {"phong", nc::enclosure_record<phong>, 1e7},
        {"phong-modified", nc::enclosure_record<normzoo::zoo::phong_modified>, 0.5},
        {"blinn-phong", nc::enclosure_record<blinn_phong>, 2.5},
        {"blinn-phong-modified", nc::enclosure_record<blinn_phong_modified>, 1e5},
        {"blinn-phong-ndf", nc::enclosure_record<normzoo::zoo::blinn_phong_ndf>, 0.3},
        {"blinn-phong-heightfield", nc::enclosure_record<normzoo::zoo::blinn_phong_heightfield>, 64.0},
    }));
    CAPTURE(id, n);
    const auto r = make(normzoo::decimal::shortest(n), {}, {});
    nc::release_thread_caches();
    CHECK(flag(r, "arb_converged"));
    CHECK(flag(r, "closed_form_inside"));
    CHECK(flag(r, "quadrature_inside"));
    CHECK(number(r, "enclosure_rel_radius") <= 1e-40);
    CHECK(number(r, "quadrature_error_certified") <= number(r, "quadrature_error_estimate"));
    CHECK_FALSE(r.failed());
}

TEST_CASE("a wrong value lies outside the enclosure") {
    const double n = GENERATE(0.1, 8.0, 1e6);
    CAPTURE(n);
    const auto e = enclose<blinn_phong>(n);
    using hp = nc::closed_form_real;
    const normzoo::decimal typed = normzoo::decimal::shortest(n);  // 0.1 is the decimal 0.1
    const hp closed = blinn_phong::closed_form(typed.to<hp>());
    const auto as_ball = [&](const hp& x) { return nc::ball::parse(normzoo::to_decimal(x, 80), 256); };
    CHECK(e.normalization.contains(as_ball(closed)));
    // The closed form at the double nearest 0.1 (0.1000000000000000055...) is another number's.
    if (!typed.exact_in<double>()) CHECK_FALSE(e.normalization.contains(as_ball(blinn_phong::closed_form(hp(n)))));
    // Off by 1e-35 relative (below what binary128 can even show): outside.
    CHECK_FALSE(e.normalization.contains(as_ball(closed * (1 + hp(1e-35)))));
    CHECK_FALSE(e.normalization.contains(as_ball(closed * (1 - hp(1e-35)))));
    // Another row's closed form (the modified one) is far outside.
    CHECK_FALSE(e.normalization.overlaps(as_ball(blinn_phong_modified::closed_form(hp(n)))));
    // And the printed form [mid +- radius] says the same as the ball.
    const auto [mid, radius] = e.normalization.printed(45);
    CHECK(radius >= e.normalization.radius());
    CHECK(std::abs(std::stod(mid) - static_cast<double>(closed)) <= 1e-15 * static_cast<double>(closed));
    nc::release_thread_caches();
}

TEST_CASE("the four Blinn-Phong bound claims are proved on [0, 1e7]") {
    const auto i = GENERATE(0, 1, 2, 3);
    const nc::bound_claim& c = nc::bound_claims()[i];
    CAPTURE(c.id);
    CHECK(nc::form_matches_closed_form(c));
    const auto r = nc::prove_positive(c.margin, c.margin_dual, c.equality_at_zero, {});
    CHECK(r.outcome == nc::proof_outcome::proved);
    CHECK(r.boxes == r.direct + r.monotone + (r.boxes - r.direct - r.monotone));  // bisected boxes are the rest
    CHECK(r.boxes >= r.direct + r.monotone);
    // The upper bounds are equalities at n = 0: only monotonicity settles the box at 0.
    CHECK((r.monotone > 0) == c.equality_at_zero);
}

TEST_CASE("false claims are refuted with a counterexample box") {
    const auto i = GENERATE(0, 1, 2, 3);
    const double tighten = GENERATE(1e-6, 1e-3);
    const nc::bound_claim& c = nc::bound_claims()[i];
    CAPTURE(c.id, tighten);
    nc::proof_settings s;
    s.tighten = tighten;
    const auto r = nc::prove_positive(c.margin, c.margin_dual, c.equality_at_zero, s);
    REQUIRE(r.outcome == nc::proof_outcome::refuted);
    // The box really holds a point where the tightened margin is <= 0, checked in 50 digits
    // from the closed form, independently of the prover's forms.
    const double at = r.detail.find("at n = ") != std::string::npos ? r.at_lo + (r.at_hi - r.at_lo) / 2 : r.at_lo;
    const normzoo::wide n = at;
    const normzoo::wide norm = std::string(c.row) == "blinn-phong" ? blinn_phong::closed_form(n) : blinn_phong_modified::closed_form(n);
    const normzoo::wide bound = (n + c.bound_offset) / (8 * normzoo::pi<normzoo::wide>());
    const normzoo::wide margin = c.is_upper ? 1 - norm / bound : norm / bound - 1;
    CHECK(margin <= normzoo::wide(tighten));
}

TEST_CASE("a margin written with n - n cannot be decided: the prover says undecided, not proved") {
    // The blinn-phong upper margin's numerator as bounds.hpp first writes it, (n+4)(1-p) - n:
    // as an interval, n - n is twice the box wide, so wide boxes never become positive.
    auto naive = [](const auto& n) {
        const auto p = exp2(-n / 2);
        return ((n + 4) * (1 - p) - n) / ((n + 4) * (2 - p));
    };
    nc::proof_settings s;
    s.max_boxes = 2000;
    const auto r = nc::prove_positive(naive, naive, true, s);
    CHECK(r.outcome == nc::proof_outcome::undecided);
}

TEST_CASE("the proofs table: claims proved, controls refuted, every record passes") {
    const auto rs = nc::proofs_table();
    REQUIRE(rs.size() == 8);
    for (const auto& r : rs) {
        CAPTURE(std::get<std::string>(*r.find("claim")));
        CHECK_FALSE(r.failed());
        const bool control = std::get<std::string>(*r.find("expected")) == "refuted";
        CHECK(std::get<std::string>(*r.find("result")).rfind(control ? "refuted at box" : "proved", 0) == 0);
    }
}
