#include "brdf_parameters.hpp"

#include <cstdlib>

#include "args.hpp"

namespace verify {

namespace {

// The items of a comma-separated list, empty ones kept (so that "true,,false" is refused by name).
std::vector<std::string> items(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        out.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

// One end of a range LO..HI.
normzoo::decimal one_decimal(const std::string& option, const std::string& text) {
    const auto v = parse_decimal_list(option, text, "-1e300", "1e300");
    if (v.size() != 1) throw bad_input(option + ": a range LO..HI has one number at each end, not '" + text + "'");
    return v.front();
}

std::string joined(const std::vector<std::string>& texts, const char* separator) {
    std::string s;
    for (const auto& t : texts) s += (s.empty() ? "" : separator) + t;
    return s;
}

// One parameter's values from its --param text: a range, a list, a bool or a color.
class parameter_reader {
public:
    parameter_reader(const shader_source& s, parameter_values& pv, std::size_t steps)
        : s_(s), p_(*pv.p), pv_(pv), steps_(steps), option_("--param " + pv.p->name) {}

    void read(const std::string& text) {
        pv_.values.clear();
        pv_.texts.clear();
        if (text.empty()) throw bad_input(option_ + ": no value (NAME=VALUE, NAME=LO..HI or NAME=A,B,C)");
        const auto dots = text.find("..");
        if (dots != std::string::npos) range(text.substr(0, dots), text.substr(dots + 2));
        else if (p_.type == shader_parameter::kind::color) color(text);
        else if (p_.type == shader_parameter::kind::boolean) booleans(text);
        else reals(text);
        pv_.given = dots != std::string::npos ? text + " in " + std::to_string(steps_) + " values" : joined(pv_.texts, ", ");
    }

private:
    const shader_source& s_;
    const shader_parameter& p_;
    parameter_values& pv_;
    std::size_t steps_;
    std::string option_;

    void in_range(double x, const std::string& shown) const {
        if (!(x >= p_.min && x <= p_.max))
            throw bad_input(option_ + ": " + shown + " is outside its range " + shortest_text(p_.min) + " .. " +
                            shortest_text(p_.max) + " (" + s_.path + ":" + std::to_string(p_.line) + ")");
    }
    void add(double x) {
        pv_.values.push_back({x});
        pv_.texts.push_back(shortest_text(x));
    }
    void range(const std::string& lo_text, const std::string& hi_text) {
        if (p_.type != shader_parameter::kind::real) throw bad_input(option_ + ": only a float parameter takes a range LO..HI");
        const normzoo::decimal lo = one_decimal(option_, lo_text), hi = one_decimal(option_, hi_text);
        in_range(lo.to<double>(), lo_text);
        in_range(hi.to<double>(), hi_text);
        if (!(lo < hi)) throw bad_input(option_ + ": the range " + lo_text + ".." + hi_text + " is empty");
        for (double x : sweep_values(lo, hi, steps_)) add(x);
    }
    void reals(const std::string& text) {
        for (const auto& d : parse_decimal_list(option_, text, "-1e300", "1e300")) {
            const double x = d.to<double>();
            in_range(x, d.text());
            add(x);
        }
    }
    void booleans(const std::string& text) {
        for (const auto& item : items(text)) {
            if (item != "true" && item != "false" && item != "1" && item != "0")
                throw bad_input(option_ + ": a bool is true, false, 1 or 0, not '" + item + "'");
            const bool b = item == "true" || item == "1";
            pv_.values.push_back({b ? 1.0 : 0.0});
            pv_.texts.push_back(b ? "true" : "false");
        }
    }
    void color(const std::string& text) {
        const auto channels = parse_decimal_list(option_, text, "-1e300", "1e300");
        if (channels.size() != 3)
            throw bad_input(option_ + ": a color is three channels R,G,B (each >= 0, e.g. 0.8,0.5,0.2), not '" + text + "'");
        std::vector<double> v;
        std::vector<std::string> shown;
        for (const auto& c : channels) {
            const double x = c.to<double>();
            if (x < 0) throw bad_input(option_ + ": a color's channels are >= 0, not " + c.text());
            v.push_back(x);
            shown.push_back(shortest_text(x));
        }
        pv_.values.push_back(v);
        pv_.texts.push_back(joined(shown, ","));
    }
};

}  // namespace

std::string shortest_text(double x) { return normzoo::decimal::exactly(x).text(); }

// Exactly: with lo = a 10^e and hi = b 10^e in a common exponent, value k is
// (a (n - 1) + (b - a) k) / (n - 1) 10^e, a ratio of integers. Its quotient to 40 more digits, with
// a last digit 1 where a remainder is left, rounds to the same double as the ratio: the ratio is
// then no terminating decimal, so no tie between two doubles, and only a tie closer to it than
// 1e-40 relatively could part the two.
std::vector<double> sweep_values(const normzoo::decimal& lo, const normzoo::decimal& hi, std::size_t n) {
    using integer = normzoo::decimal::integer;
    const long e = std::min(lo.exponent(), hi.exponent());
    auto scaled = [e](const normzoo::decimal& d) {
        const integer c = d.coefficient() * boost::multiprecision::pow(integer(10), static_cast<unsigned>(d.exponent() - e));
        return d.negative() ? integer(-c) : c;
    };
    const integer a = scaled(lo), b = scaled(hi), den = integer(n - 1);
    const unsigned extra = 40;
    const integer shift = boost::multiprecision::pow(integer(10), extra);
    std::vector<double> out;
    for (std::size_t k = 0; k < n; ++k) {
        const integer num = a * den + (b - a) * integer(k);
        const integer magnitude = (num < 0 ? integer(-num) : num) * shift;
        const integer quotient = magnitude / den;
        const bool remainder = magnitude % den != 0;
        const std::string digits = (num < 0 ? "-" : "") + integer(quotient * 10 + (remainder ? 1 : 0)).str() + "e" +
                                   std::to_string(e - static_cast<long>(extra) - 1);
        out.push_back(std::strtod(digits.c_str(), nullptr));
    }
    return out;
}

std::vector<parameter_values> parameter_grid(const shader_source& s, const std::vector<std::string>& params, std::size_t steps) {
    std::vector<parameter_values> grid;
    for (const auto& p : s.parameters) grid.push_back({&p, {p.default_value}, {}, {}});
    for (auto& g : grid) {
        if (g.p->type == shader_parameter::kind::boolean) g.texts = {g.p->default_value[0] != 0 ? "true" : "false"};
        else if (g.p->type == shader_parameter::kind::color)
            g.texts = {shortest_text(g.p->default_value[0]) + "," + shortest_text(g.p->default_value[1]) + "," +
                       shortest_text(g.p->default_value[2])};
        else g.texts = {shortest_text(g.p->default_value[0])};
        g.given = g.texts[0];
    }
    std::vector<std::string> seen;
    for (const auto& text : params) {
        const auto eq = text.find('=');
        if (eq == std::string::npos) throw bad_input("--param " + text + ": expected NAME=VALUE, NAME=LO..HI or NAME=A,B,C");
        const std::string name = text.substr(0, eq);
        parameter_values* pv = nullptr;
        for (auto& g : grid)
            if (g.p->name == name) pv = &g;
        if (!pv) {
            std::string known;
            for (const auto& p : s.parameters) known += (known.empty() ? "" : ", ") + p.name;
            throw bad_input("--param " + name + ": " + s.path + " declares no parameter " + name +
                            (known.empty() ? " (it declares none)" : " (it declares " + known + ")"));
        }
        for (const auto& n : seen)
            if (n == name) throw bad_input("--param " + name + ": given twice (a list is NAME=A,B,C)");
        seen.push_back(name);
        parameter_reader(s, *pv, steps).read(text.substr(eq + 1));
    }
    return grid;
}

}  // namespace verify
