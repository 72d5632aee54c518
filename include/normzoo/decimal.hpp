// An input as the user typed it: the decimal number a text such as "0.37", "1e-300" or "89.99"
// denotes, never the double nearest to it (docs/conventions.md, "Inputs are decimals").
//
//   decimal n("0.37");
//   n.to<quad>()          the binary128 nearest 0.37 (each type's own correctly rounded parser:
//                         strtod, strtold, strtoflt128, Boost.Multiprecision's string constructor)
//   n.exact_in<double>()  false: 0.37 has no binary expansion
//   n.rounding<quad>()    a bound on |to<quad>() - 0.37| / 0.37: 0 when exact, else epsilon
//   decimal("90") - decimal("89.99")   exactly 0.01 (incidence near grazing, docs/energy.md)
//
// The value is kept exactly (an integer coefficient and a power of ten), so comparisons and
// differences are exact and a table can say whether its number type holds the input exactly.
#pragma once
#include <boost/multiprecision/cpp_int.hpp>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace normzoo {

template <class Real>
struct degrees_angle;  // geometry.hpp

class decimal {
public:
    using integer = boost::multiprecision::cpp_int;
    // Decimal exponents beyond this are refused: every number normzoo takes is far inside it,
    // and the exact arithmetic below grows with it.
    static constexpr long max_exponent = 100000;
    static constexpr std::size_t max_digits = 2000;

    decimal() : text_("0") {}

    // [+-]digits[.digits][(e|E)[+-]digits], or .digits; throws std::invalid_argument naming the text.
    explicit decimal(std::string_view text) : text_(text) {
        auto fail = [&](const char* why) {
            throw std::invalid_argument("'" + std::string(text) + "' is not a decimal number: " + why);
        };
        std::size_t i = 0;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative_ = text[i++] == '-';
        std::size_t digits = 0;
        long point_shift = 0;
        bool point = false;
        for (; i < text.size(); ++i) {
            const char c = text[i];
            if (c >= '0' && c <= '9') {
                coefficient_ = coefficient_ * 10 + (c - '0');
                ++digits;
                if (point) --point_shift;
                if (digits > max_digits) fail("more than 2000 digits");
            } else if (c == '.' && !point) {
                point = true;
            } else {
                break;
            }
        }
        if (digits == 0) fail("no digits");
        long exponent = 0;
        if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
            ++i;
            bool negative_exponent = false;
            if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative_exponent = text[i++] == '-';
            std::size_t exponent_digits = 0;
            for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i, ++exponent_digits) {
                exponent = exponent * 10 + (text[i] - '0');
                if (exponent > max_exponent) fail("exponent out of range");
            }
            if (exponent_digits == 0) fail("no digits in the exponent");
            if (negative_exponent) exponent = -exponent;
        }
        if (i != text.size()) fail("unexpected characters");
        exponent_ = exponent + point_shift;
        normalize();
        if (exponent_ > max_exponent || exponent_ + digit_count() < -max_exponent) fail("exponent out of range");
    }

    // The exact value of a double (0.1 becomes 0.1000000000000000055511151231257827...): for the
    // callers that hold a double, whose input is that double. Its text is the shortest that
    // reads back as the same double.
    static decimal exactly(double x) {
        if (!std::isfinite(x)) throw std::invalid_argument("not a finite number");
        decimal d;
        char shortest[40];
        for (int p = 1; p <= 17; ++p) {
            std::snprintf(shortest, sizeof shortest, "%.*g", p, x);
            if (std::strtod(shortest, nullptr) == x) break;
        }
        d.text_ = shortest;
        d.negative_ = std::signbit(x);
        int e2 = 0;
        const double m = std::frexp(std::fabs(x), &e2);  // |x| = m 2^e2, m in [0.5, 1)
        d.coefficient_ = integer(static_cast<unsigned long long>(std::ldexp(m, 53)));
        e2 -= 53;
        if (e2 >= 0) {
            d.coefficient_ <<= e2;
        } else {  // m 2^-k = m 5^k 10^-k
            d.coefficient_ *= boost::multiprecision::pow(integer(5), static_cast<unsigned>(-e2));
            d.exponent_ = e2;
        }
        d.normalize();
        return d;
    }

    // The decimal of the shortest text that reads back as x: what a source file that holds the
    // double x wrote (0.1 for the double nearest 0.1).
    static decimal shortest(double x) { return decimal(exactly(x).text()); }

    const std::string& text() const { return text_; }  // as given
    bool negative() const { return negative_; }
    bool is_zero() const { return coefficient_ == 0; }
    const integer& coefficient() const { return coefficient_; }  // value = +-coefficient 10^exponent
    long exponent() const { return exponent_; }

    // The value in `Real`, rounded to nearest by the type's own parser.
    template <class Real>
    Real to() const {
        const std::string s = canonical();
        if constexpr (std::is_same_v<Real, double>) return std::strtod(s.c_str(), nullptr);
        else if constexpr (std::is_same_v<Real, long double>) return std::strtold(s.c_str(), nullptr);
        else if constexpr (std::is_same_v<Real, float>) return std::strtof(s.c_str(), nullptr);
        else return Real(s);  // Boost.Multiprecision: binary128 through strtoflt128, cpp_bin_float exactly
    }

    // Whether `Real` holds this value exactly (then to<Real>() is the value itself).
    template <class Real>
    bool exact_in() const {
        using limits = std::numeric_limits<Real>;
        if (coefficient_ == 0) return true;
        // value = m 2^shift with m an integer: 10^e = 5^e 2^e
        integer m = coefficient_;
        long shift = exponent_;
        if (exponent_ >= 0) {
            m *= boost::multiprecision::pow(integer(5), static_cast<unsigned>(exponent_));
        } else {
            const integer five_q = boost::multiprecision::pow(integer(5), static_cast<unsigned>(-exponent_));
            if (m % five_q != 0) return false;  // a factor 1/5 left: no binary expansion
            m /= five_q;
        }
        const long lo = static_cast<long>(boost::multiprecision::lsb(m)) + shift;
        const long hi = static_cast<long>(boost::multiprecision::msb(m)) + shift;
        return hi - lo <= limits::digits - 1 && lo >= limits::min_exponent - limits::digits &&
               hi <= limits::max_exponent - 1;
    }

    // A bound on |to<Real>() - value| / |value|: 0 when Real holds the value, else the type's
    // epsilon (twice the unit roundoff, which also covers a parser that reads only the first
    // digits it can use), or more below the normal range.
    template <class Real>
    double rounding() const {
        if (exact_in<Real>()) return 0;
        using limits = std::numeric_limits<Real>;
        const double eps = static_cast<double>(limits::epsilon());
        const Real x = to<Real>();
        using std::fabs;
        using std::abs;
        if (abs(x) < limits::min()) {
            const double ratio = static_cast<double>(limits::denorm_min() / abs(x));
            return ratio > eps ? ratio : eps;
        }
        return eps;
    }

    // Exact comparison and difference.
    friend int compare(const decimal& a, const decimal& b) {
        const int sa = a.sign(), sb = b.sign();
        if (sa != sb) return sa < sb ? -1 : 1;
        if (sa == 0) return 0;
        const auto [x, y] = aligned(a, b);
        const int magnitude = x < y ? -1 : (x > y ? 1 : 0);
        return sa > 0 ? magnitude : -magnitude;
    }
    friend decimal operator-(const decimal& a, const decimal& b) {
        auto [x, y] = aligned(a, b);
        integer sx = a.negative_ ? integer(-x) : x, sy = b.negative_ ? integer(-y) : y;
        integer r = sx - sy;
        decimal d;
        d.negative_ = r < 0;
        d.coefficient_ = d.negative_ ? integer(-r) : r;
        d.exponent_ = a.exponent_ < b.exponent_ ? a.exponent_ : b.exponent_;
        d.normalize();
        d.text_ = d.canonical();
        return d;
    }
    friend bool operator<(const decimal& a, const decimal& b) { return compare(a, b) < 0; }
    friend bool operator>(const decimal& a, const decimal& b) { return compare(a, b) > 0; }
    friend bool operator<=(const decimal& a, const decimal& b) { return compare(a, b) <= 0; }
    friend bool operator>=(const decimal& a, const decimal& b) { return compare(a, b) >= 0; }
    friend bool operator==(const decimal& a, const decimal& b) { return compare(a, b) == 0; }
    friend bool operator!=(const decimal& a, const decimal& b) { return compare(a, b) != 0; }

    // coefficient "e" exponent, the form every parser reads.
    std::string canonical() const {
        return (negative_ && coefficient_ != 0 ? "-" : "") + coefficient_.str() + "e" + std::to_string(exponent_);
    }

private:
    std::string text_;
    bool negative_ = false;
    integer coefficient_ = 0;
    long exponent_ = 0;

    int sign() const { return coefficient_ == 0 ? 0 : (negative_ ? -1 : 1); }
    long digit_count() const { return static_cast<long>(coefficient_.str().size()); }
    void normalize() {
        if (coefficient_ == 0) {
            exponent_ = 0;
            negative_ = false;
            return;
        }
        while (coefficient_ % 10 == 0) coefficient_ /= 10, ++exponent_;
    }
    // Both magnitudes as integers in units of the smaller power of ten.
    static std::pair<integer, integer> aligned(const decimal& a, const decimal& b) {
        const long e = a.exponent_ < b.exponent_ ? a.exponent_ : b.exponent_;
        auto scaled = [e](const decimal& d) -> integer {
            return d.coefficient_ * boost::multiprecision::pow(integer(10), static_cast<unsigned>(d.exponent_ - e));
        };
        return {scaled(a), scaled(b)};
    }
};

// An angle typed in degrees, in Real: the angle and its distances to 90 and 180 degrees are
// each exact decimals rounded once, so cos t near grazing is as accurate as Real allows.
template <class Real>
degrees_angle<Real> degrees_of(const decimal& deg) {
    return degrees_angle<Real>(deg.to<Real>(), (decimal("90") - deg).to<Real>(), (decimal("180") - deg).to<Real>());
}

}  // namespace normzoo
