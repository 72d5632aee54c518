// The work-precision benchmark: time against achieved error for each integral family, method
// and number type (results/bench.md). One JSON object per line on stdout:
//   {"kind":"family", family, dimension, truth, truth_error, description}   once per family
//   {"kind":"run", family, method, type, knob, seconds, value, error, reported_error, evaluations}
// Time is the minimum over repeated runs after a warm-up (the first call builds node tables).
// `--smoke` runs one knob per curve (CI checks that the tables come out, never the speed).
#include <normzoo/normzoo.hpp>
#include <normzoo/microfacet/albedo.hpp>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/quadrature/trapezoidal.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace {
using namespace normzoo;
namespace bq = boost::math::quadrature;
using wide_t = wide;  // 50 digits

bool smoke = false;

// A nested integrator that would need more than this many evaluations is stopped and the point
// recorded as given up (Boost's adaptive rules on the cap's kink reach 1e9 and minutes).
constexpr long evaluation_budget = 4000000;
struct over_budget {};

template <class T> const char* type_name();
template <> const char* type_name<double>() { return "double"; }
template <> const char* type_name<long double>() { return "long double"; }
template <> const char* type_name<quad>() { return "float128"; }
template <> const char* type_name<wide_t>() { return "50 digits"; }

template <class T>
int type_digits() { return std::numeric_limits<T>::digits10; }

struct family {
    std::string id, description;
    int dimension;
    wide_t truth, truth_error;  // truth_error: 0 for a closed form, else the reference's bound
};

// One timed point of a curve.
struct outcome {
    wide_t value;
    double reported_error = -1;  // what the method says about its error; -1: nothing
    long evaluations = 0;
};

void emit_family(const family& f) {
    std::printf("{\"kind\":\"family\",\"family\":\"%s\",\"dimension\":%d,\"truth\":\"%s\",\"truth_error\":%.3e,\"description\":\"%s\"}\n",
                f.id.c_str(), f.dimension, to_decimal(f.truth, 45).c_str(), static_cast<double>(f.truth_error),
                f.description.c_str());
    std::fflush(stdout);
}

// Runs `run` after a warm-up, repeating while the total stays short; prints the record.
// Returns the seconds of one call (so that a sweep can stop before a point gets too slow).
double measure(const family& fam, const std::string& method, const char* type, const std::string& knob,
               const std::function<outcome()>& run) {
    using clock = std::chrono::steady_clock;
    auto a = clock::now();
    outcome o;
    try {
        o = run();  // warm-up
    } catch (const over_budget&) {
        std::printf("{\"kind\":\"gave_up\",\"family\":\"%s\",\"method\":\"%s\",\"type\":\"%s\",\"knob\":\"%s\",\"evaluations\":%ld}\n",
                    fam.id.c_str(), method.c_str(), type, knob.c_str(), evaluation_budget);
        std::fflush(stdout);
        return 1e9;
    }
    double first = std::chrono::duration<double>(clock::now() - a).count();
    double best = first;
    const int repeats = smoke ? 0 : first > 0.5 ? 1 : std::min(21, static_cast<int>(0.1 / std::max(first, 1e-7)) + 2);
    for (int i = 0; i < repeats; ++i) {
        a = clock::now();
        o = run();
        best = std::min(best, std::chrono::duration<double>(clock::now() - a).count());
    }
    const wide_t err = abs(o.value - fam.truth);
    std::printf("{\"kind\":\"run\",\"family\":\"%s\",\"method\":\"%s\",\"type\":\"%s\",\"knob\":\"%s\",\"seconds\":%.4e,"
                "\"value\":\"%s\",\"error\":%.3e,\"reported_error\":%.3e,\"evaluations\":%ld}\n",
                fam.id.c_str(), method.c_str(), type, knob.c_str(), best, to_decimal(o.value, 40).c_str(),
                static_cast<double>(err), o.reported_error, o.evaluations);
    std::fflush(stdout);
    return best;
}

std::string sci(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.0e", x);
    return b;
}

// A sweep stops once a point takes longer than this (the next would take longer still).
bool too_slow(double seconds) { return seconds > 1.0; }

// 1e-4, 1e-6, ... to the type's digits (at most max_digits), in steps of 3 digits beyond 1e-16.
template <class T>
std::vector<double> tolerances(int max_digits = 45) {
    std::vector<double> t;
    const int last = std::min(max_digits, type_digits<T>());
    for (int d = 4; d <= last; d += (d < 16 ? 2 : 3)) t.push_back(std::pow(10.0, -d));
    if (smoke) t.resize(1);
    return t;
}

// Monte Carlo with N samples from a sampler returning (estimate of f/pdf); standard error reported.
void monte_carlo(const family& fam, const std::string& method, unsigned seed,
                 const std::function<double(std::mt19937_64&)>& sample) {
    for (long samples = 1000; samples <= (smoke ? 1000 : 10000000); samples *= 10) {
        measure(fam, method, "double", std::to_string(samples) + " samples", [&] {
            std::mt19937_64 rng(seed);
            double sum = 0, sum2 = 0;
            for (long i = 0; i < samples; ++i) {
                const double v = sample(rng);
                sum += v;
                sum2 += v * v;
            }
            const double mean = sum / samples, var = std::max(0.0, sum2 / samples - mean * mean);
            return outcome{wide_t(mean), std::sqrt(var / samples), samples};
        });
    }
}

// ---------------------------------------------------------------------------------------------
// 1D: the zoo integral of the modified Phong row, integral over [0, pi/2] of cos^(n+1) t sin t dt
// = 1/(n+2). The generic methods get the integrand in t as normzoo writes it (the power from
// 2 sin^2(t/2), accurate at any n); exp_sinh gets it in s = -ln cos t over [0, inf).
// ---------------------------------------------------------------------------------------------
using zoo_row_t = zoo::phong_modified;

template <class T>
void zoo_family(const family& fam, double n) {
    const char* tn = type_name<T>();
    const T a = 0, b = boost::math::constants::half_pi<T>(), nn = n;
    long calls = 0;
    auto f = [&](const T& t) {
        ++calls;
        return reduced_integrand<zoo_row_t>(t, nn);
    };

    bq::tanh_sinh<T> ts(15);  // one integrator per sweep: its node tables are built once
    for (double tol : tolerances<T>()) {
        if (too_slow(measure(fam, "tanh_sinh", tn, sci(tol), [&] {
                calls = 0;
                T err = 0, l1 = 0;
                const T v = ts.integrate(f, a, b, T(tol), &err, &l1);
                return outcome{wide_t(v), static_cast<double>(err), calls};
            })))
            break;
    }
    bq::exp_sinh<T> es(15);
    for (double tol : tolerances<T>()) {
        // In s = -ln cos t, [0, inf), as a user of exp_sinh would write it: cos = e^-s from expm1,
        // sin = sqrt(1 - cos^2) without cancellation, dt/ds = cos/sin.
        auto h = [&](const T& s) {
            ++calls;
            using std::expm1;
            using std::sqrt;
            const T e = expm1(-s), c = 1 + e, sn = sqrt(-e * (2 + e));
            // f(t(s)) dt/ds with f = pow(cos, n + 1) sin: written with the power of the cosine
            return pow_cosine(-e, nn) * c * sn * c / sn;
        };
        if (too_slow(measure(fam, "exp_sinh", tn, sci(tol), [&] {
                calls = 0;
                T err = 0, l1 = 0;
                const T v = es.integrate(h, T(tol), &err, &l1);
                return outcome{wide_t(v), static_cast<double>(err), calls};
            })))
            break;
    }
    auto kronrod = [&](auto points) {
        constexpr unsigned P = decltype(points)::value;
        for (double tol : tolerances<T>()) {
            if (too_slow(measure(fam, "gauss_kronrod " + std::to_string(P), tn, sci(tol), [&] {
                    calls = 0;
                    T err = 0, l1 = 0;
                    const T v = bq::gauss_kronrod<T, P>::integrate(f, a, b, 15, T(tol), &err, &l1);
                    return outcome{wide_t(v), static_cast<double>(err), calls};
                })))
                break;
        }
    };
    kronrod(std::integral_constant<unsigned, 15>{});
    kronrod(std::integral_constant<unsigned, 31>{});
    kronrod(std::integral_constant<unsigned, 61>{});
    for (double tol : tolerances<T>()) {
        if (too_slow(measure(fam, "trapezoidal", tn, sci(tol), [&] {
                calls = 0;
                T err = 0, l1 = 0;
                const T v = bq::trapezoidal(f, a, b, T(tol), 12, &err, &l1);
                return outcome{wide_t(v), static_cast<double>(err), calls};
            })))
            break;
    }
    // Fixed Gauss: 20-point Gauss-Legendre on m equal panels, no error estimate of its own.
    for (int m = 1; m <= (smoke ? 1 : 4096); m *= 4) {
        if (too_slow(measure(fam, "gauss 20 fixed", tn, std::to_string(m) + " panels", [&] {
                calls = 0;
                T sum = 0;
                const T h = (b - a) / m;
                for (int i = 0; i < m; ++i) sum += bq::gauss<T, 20>::integrate(f, a + i * h, a + (i + 1) * h);
                return outcome{wide_t(sum), -1, calls};
            })))
            break;
    }
}

// normzoo's own scheme for the zoo family: the lobe quadrature in its three native types.
template <class T>
void zoo_normzoo(const family& fam, double n) {
    auto f = [](const auto& p) { return p.power * zoo_row_t::weight(p.cos_theta, p.sin_theta); };
    // the full plan, and the quick plan a relative tolerance of 1e-8 selects (quadrature/lobe.hpp)
    for (const double tol : {0.0, 1e-8})
        measure(fam, "normzoo", type_name<T>(), tol > 0 ? "lobe rule, 1e-8" : "lobe rule", [&] {
            const auto e = quadrature::lobe_quadrature<T>(T(tol)).integrate(f, T(1), T(n), boost::math::constants::half_pi<T>());
            return outcome{wide_t(e.value), static_cast<double>(e.abs_error), static_cast<long>(e.evaluations)};
        });
}

void run_zoo(const std::string& id, double n) {
    char n_text[32];
    std::snprintf(n_text, sizeof n_text, "%g", n);
    const family fam{id, std::string("modified Phong zoo row: integral over [0, pi/2] of cos^(n+1) t sin t dt = 1/(n+2), n = ") + n_text,
                     1, 1 / (wide_t(n) + 2), 0};
    emit_family(fam);
    zoo_normzoo<double>(fam, n);
    zoo_normzoo<long double>(fam, n);
    zoo_normzoo<quad>(fam, n);
    zoo_family<double>(fam, n);
    zoo_family<long double>(fam, n);
    zoo_family<quad>(fam, n);
    zoo_family<wide_t>(fam, n);
    // naive Monte Carlo in t (uniform)
    monte_carlo(fam, "naive Monte Carlo", 7, [&](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(0, M_PI / 2);
        return reduced_integrand<zoo_row_t>(u(rng), n) * (M_PI / 2);
    });
}

// ---------------------------------------------------------------------------------------------
// 2D: the directional albedo of a BRDF form, and the irradiance of a sphere light's cap. The
// generic methods integrate the plain spherical parametrization with nested 1D integrators
// (outer theta, inner phi) in double and long double; Monte Carlo in double.
// ---------------------------------------------------------------------------------------------
template <class T>
using integrand_2d = std::function<T(const T&, const T&)>;

template <class T>
void generic_2d(const family& fam, const integrand_2d<T>& f, const T& theta_hi, const T& phi_hi) {
    const char* tn = type_name<T>();
    long calls = 0;
    auto g = [&](const T& theta, const T& phi) {
        if (++calls > evaluation_budget) throw over_budget{};
        return f(theta, phi);
    };
    const std::vector<double> tols = tolerances<T>(15);
    bq::tanh_sinh<T> ts(12);  // one integrator for the sweep: its node tables are built once
    for (double tol : tols) {
        if (too_slow(measure(fam, "tanh_sinh", tn, sci(tol), [&] {
                calls = 0;
                auto outer = [&](const T& theta) {
                    return ts.integrate([&](const T& phi) { return g(theta, phi); }, T(0), phi_hi, T(tol));
                };
                T err = 0;
                const T v = ts.integrate(outer, T(0), theta_hi, T(tol), &err);
                return outcome{wide_t(v), static_cast<double>(err), calls};
            })))
            break;
    }
    auto kronrod = [&](auto points) {
        constexpr unsigned P = decltype(points)::value;
        for (double tol : tols) {
            if (too_slow(measure(fam, "gauss_kronrod " + std::to_string(P), tn, sci(tol), [&] {
                    calls = 0;
                    auto outer = [&](const T& theta) {
                        return bq::gauss_kronrod<T, P>::integrate([&](const T& phi) { return g(theta, phi); }, T(0), phi_hi, 15, T(tol));
                    };
                    T err = 0;
                    const T v = bq::gauss_kronrod<T, P>::integrate(outer, T(0), theta_hi, 15, T(tol), &err);
                    return outcome{wide_t(v), static_cast<double>(err), calls};
                })))
                break;
        }
    };
    kronrod(std::integral_constant<unsigned, 15>{});
    kronrod(std::integral_constant<unsigned, 31>{});
    kronrod(std::integral_constant<unsigned, 61>{});
    for (double tol : tols) {
        if (tol < 1e-10) break;  // 2^12 x 2^12 nodes and still far off: beyond is minutes
        if (too_slow(measure(fam, "trapezoidal", tn, sci(tol), [&] {
                calls = 0;
                auto outer = [&](const T& theta) {
                    return bq::trapezoidal([&](const T& phi) { return g(theta, phi); }, T(0), phi_hi, T(tol), 10);
                };
                T err = 0;
                const T v = bq::trapezoidal(outer, T(0), theta_hi, T(tol), 10, &err);
                return outcome{wide_t(v), static_cast<double>(err), calls};
            })))
            break;
    }
    for (int m = 1; m <= (smoke ? 1 : 256); m *= 2) {
        if (too_slow(measure(fam, "gauss 20 fixed", tn, std::to_string(m) + "x" + std::to_string(m) + " panels", [&] {
                calls = 0;
                T sum = 0;
                const T ht = theta_hi / m, hp = phi_hi / m;
                for (int i = 0; i < m; ++i) {
                    auto outer = [&](const T& theta) {
                        T inner = 0;
                        for (int j = 0; j < m; ++j)
                            inner += bq::gauss<T, 20>::integrate([&](const T& phi) { return g(theta, phi); }, j * hp, (j + 1) * hp);
                        return inner;
                    };
                    sum += bq::gauss<T, 20>::integrate(outer, i * ht, (i + 1) * ht);
                }
                return outcome{wide_t(sum), -1, calls};
            })))
            break;
    }
}

using albedo_form = brdf::blinn_phong_modified;

template <class T>
integrand_2d<T> albedo_integrand(double theta_deg, double n) {
    const degrees_angle<T> in(theta_deg);
    const vec3<T> l(in.sin_t, 0, in.cos_t);
    const brdf::params<T> p{T(n), T(1)};
    return [=](const T& theta, const T& phi) {
        using std::cos;
        using std::sin;
        const T st = sin(theta), ct = cos(theta);
        const vec3<T> v(st * cos(phi), st * sin(phi), ct);
        return albedo_form::f(l, v, p) * ct * st;
    };
}

void run_albedo(const std::string& id, double theta_deg, double n) {
    family fam{id, "", 2, 0, 0};
    char text[200];
    if (theta_deg == 0) {
        fam.truth = wide_t(albedo_form::albedo_at_normal(brdf::params<quad>{quad(n)}));
        std::snprintf(text, sizeof text, "albedo of %s, n = %g, at %g deg: closed form", albedo_form::id, n, theta_deg);
    } else {
        const auto ref = albedo<albedo_form>(theta_deg, n, 1, albedo_settings{1e-14, 4000});
        fam.truth = ref.value;
        fam.truth_error = ref.abs_error;
        std::snprintf(text, sizeof text, "albedo of %s, n = %g, at %g deg: reference by normzoo at 1e-14 (bound %.1e)",
                      albedo_form::id, n, theta_deg, ref.abs_error);
    }
    fam.description = text;
    emit_family(fam);
    for (int d = 4; d <= (smoke ? 4 : 14); d += 2) {
        const double tol = std::pow(10.0, -d);
        measure(fam, "normzoo", "double", sci(tol), [&] {
            const auto e = albedo<albedo_form>(theta_deg, n, 1, albedo_settings{tol, 400});
            return outcome{wide_t(e.value), e.abs_error, static_cast<long>(e.evaluations)};
        });
    }
    const double half_pi = M_PI / 2, two_pi = 2 * M_PI;
    generic_2d<double>(fam, albedo_integrand<double>(theta_deg, n), half_pi, two_pi);
    generic_2d<long double>(fam, albedo_integrand<long double>(theta_deg, n), boost::math::constants::half_pi<long double>(),
                            boost::math::constants::two_pi<long double>());
    const auto f = albedo_integrand<double>(theta_deg, n);
    monte_carlo(fam, "naive Monte Carlo", 11, [&](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(0, 1);
        return f(u(rng) * half_pi, u(rng) * two_pi) * half_pi * two_pi;
    });
    // pbrt's estimator: cosine-weighted directions (Malley's method), f cos / pdf = pi f.
    const degrees_angle<double> in(theta_deg);
    const vec3<double> l(in.sin_t, 0, in.cos_t);
    monte_carlo(fam, "pbrt-style Monte Carlo", 11, [&](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(0, 1);
        const double r = std::sqrt(u(rng)), phi = two_pi * u(rng);
        const vec3<double> v(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - r * r)));
        return M_PI * albedo_form::f(l, v, brdf::params<double>{n, 1});
    });
}

// E(mu, alpha) of a microfacet composition (docs/microfacet.md): normzoo's integral in the
// distribution's own variable against the generic nested rules on the plain parametrization of L,
// Monte Carlo (naive, cosine-weighted, and GGX importance sampling as engines bake), all in one run.
template <class T>
integrand_2d<T> composition_integrand(const microfacet::composition& c, double mu, double alpha) {
    const T m(mu), s = sqrt((1 - m) * (1 + m));
    const vec3<T> v(s, 0, m);
    const brdf::params<T> p{0, T(1), T(alpha)};
    return [=](const T& theta, const T& phi) {
        using std::cos;
        using std::sin;
        const T st = sin(theta), ct = cos(theta);
        const vec3<T> l(st * cos(phi), st * sin(phi), ct);
        return c.f(l, v, p) * ct * st;
    };
}

void run_microfacet(const std::string& id, double mu, double alpha) {
    const auto c = microfacet::composition::parse("ggx/smith-height-correlated/one");
    family fam{id, "", 2, 0, 0};
    const auto ref = albedo<microfacet::composition>(microfacet::angle_of_cosine(mu), microfacet::composition::node_exponent(alpha),
                                                     1, albedo_settings{1e-14, 4000}, alpha, c);
    fam.truth = ref.value;
    fam.truth_error = ref.abs_error;
    char text[240];
    std::snprintf(text, sizeof text,
                  "E(mu = %g, alpha = %g) of ggx/smith-height-correlated/one: reference by the generic lobe integral at 1e-14 "
                  "(bound %.1e)", mu, alpha, ref.abs_error);
    fam.description = text;
    emit_family(fam);
    for (int d = 4; d <= (smoke ? 4 : 14); d += 2) {
        const double tol = std::pow(10.0, -d);
        measure(fam, "normzoo", "double", sci(tol), [&] {
            const auto e = microfacet::directional_albedo(c, mu, alpha, 1, albedo_settings{tol, 400});
            return outcome{wide_t(e.value), e.abs_error, static_cast<long>(e.evaluations)};
        });
    }
    const double half_pi = M_PI / 2, two_pi = 2 * M_PI;
    generic_2d<double>(fam, composition_integrand<double>(c, mu, alpha), half_pi, two_pi);
    const auto f = composition_integrand<double>(c, mu, alpha);
    monte_carlo(fam, "naive Monte Carlo", 11, [&](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(0, 1);
        return f(u(rng) * half_pi, u(rng) * two_pi) * half_pi * two_pi;
    });
    // GGX importance sampling of h (Walter et al. 2007), the estimator engines bake with:
    // G V.h / (N.V N.h) for L = reflect(V, h) above the horizon.
    const double s = std::sqrt((1 - mu) * (1 + mu)), a2 = alpha * alpha;
    const vec3<double> v(s, 0, mu);
    monte_carlo(fam, "GGX-sampled Monte Carlo", 11, [&](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(0, 1);
        const double u1 = u(rng), phi = two_pi * u(rng);
        const double ct = std::sqrt((1 - u1) / (1 + (a2 - 1) * u1)), st = std::sqrt(std::max(0.0, 1 - ct * ct));
        const vec3<double> h(st * std::cos(phi), st * std::sin(phi), ct);
        const double vh = v.dot(h);
        const vec3<double> l = 2 * vh * h - v;
        if (!(l.z() > 0 && vh > 0)) return 0.0;
        return c.f(l, v, brdf::params<double>{0, 1, alpha}) * 4 * l.z() * vh / (microfacet::d_ggx::d(h, c.ndf(alpha)) * ct);
    });
}

template <class T>
integrand_2d<T> cap_integrand(double tilt_deg) {
    const degrees_angle<T> tc(tilt_deg);
    return [=](const T& theta, const T& phi) {
        using std::cos;
        using std::sin;
        const T st = sin(theta);
        const T nl = cos(theta) * tc.cos_t - st * cos(phi) * tc.sin_t;  // N.omega, omega about the cap's centre
        return (nl > 0 ? nl : T(0)) * st;
    };
}

void run_irradiance(const std::string& id, double ratio, double tilt_deg) {
    const auto cap = light_cap<quad>::sphere(quad(ratio));
    const degrees_angle<quad> tq(tilt_deg);
    family fam{id, "", 2, wide_t(cap_irradiance_closed_form(cap, tq).value), 0};
    char text[200];
    std::snprintf(text, sizeof text, "irradiance of a sphere light, r0/r = %g, centre %g deg from N (the cap crosses the horizon): closed form (L = 1)",
                  ratio, tilt_deg);
    fam.description = text;
    emit_family(fam);
    auto ours = [&](auto zero) {
        using T = decltype(zero);
        measure(fam, "normzoo", type_name<T>(), "cap rule", [&] {
            const auto e = cap_irradiance<T>(light_cap<T>::sphere(T(ratio)), degrees_angle<T>(tilt_deg));
            return outcome{wide_t(e.value), static_cast<double>(e.abs_error), static_cast<long>(e.evaluations)};
        });
    };
    ours(0.0);
    ours(0.0L);
    ours(quad(0));
    const double beta = std::asin(ratio), two_pi = 2 * M_PI;
    generic_2d<double>(fam, cap_integrand<double>(tilt_deg), beta, two_pi);
    generic_2d<long double>(fam, cap_integrand<long double>(tilt_deg), std::asin(static_cast<long double>(ratio)),
                            boost::math::constants::two_pi<long double>());
    const auto f = cap_integrand<double>(tilt_deg);
    monte_carlo(fam, "naive Monte Carlo", 11, [&](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(0, 1);
        return f(u(rng) * beta, u(rng) * two_pi) * beta * two_pi;
    });
    // pbrt's sphere-light estimator: directions uniform in the cone, (N.w)+ / pdf.
    const double cos_b = std::cos(beta), tilt = tilt_deg * M_PI / 180;
    monte_carlo(fam, "pbrt-style Monte Carlo", 11, [&](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(0, 1);
        const double c = 1 - u(rng) * (1 - cos_b), st = std::sqrt(std::max(0.0, 1 - c * c)), phi = two_pi * u(rng);
        const double nl = c * std::cos(tilt) - st * std::cos(phi) * std::sin(tilt);
        return std::max(nl, 0.0) * two_pi * (1 - cos_b);
    });
}

}  // namespace

int main(int argc, char** argv) {
    std::string only;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--smoke")) smoke = true;
        else only = argv[i];
    }
    auto want = [&](const char* id) { return only.empty() || only == id; };
    if (want("zoo-low")) run_zoo("zoo-low", 0.5);
    if (want("zoo-high")) run_zoo("zoo-high", 1e6);
    if (want("albedo-normal")) run_albedo("albedo-normal", 0, 64);
    if (want("albedo-grazing")) run_albedo("albedo-grazing", 85, 64);
    if (want("irradiance-cap")) run_irradiance("irradiance-cap", 0.5, 80);
    if (want("microfacet-albedo")) run_microfacet("microfacet-albedo", 0.5, 0.3);
}
