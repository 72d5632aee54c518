#include "material_reference.hpp"

#include <stdexcept>

#include <normzoo/material/registry.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>

#include "args.hpp"

namespace verify {

namespace {

namespace mf = normzoo::microfacet;

// A composition D/G/F[/COMPENSATION] as a reference: its roughness, as alpha or as the perceptual
// r (alpha = r^2, where the code's is bound to r), and the parameters its parts declare, each a
// number, held at the declared default (alpha 0.5).
reference_material composition_reference(const std::string& id) {
    const mf::composition c = mf::composition::parse(id);
    reference_material m;
    m.id = id;
    m.parameters.push_back({"alpha", false, {0.5, 0.5, 0.5}, 1e-8, 1});
    m.parameters.push_back({"r", false, {-1, -1, -1}, 1e-4, 1});  // -1: not bound, alpha holds
    for (const normzoo::parameter& p : c.parameters())
        m.parameters.push_back({std::string(p.name), false, {p.held, p.held, p.held}, p.min, p.max});
    // values in `parameters` order: alpha, then the parts' (set on the composition, f0 as specular)
    auto at = [c, params = m.parameters](const std::vector<rgb_value>& values) {
        mf::composition d = c;
        double alpha = values[1][0] >= 0 ? values[1][0] * values[1][0] : values[0][0], f0 = 1;
        for (std::size_t k = 2; k < params.size(); ++k) {
            const double x = values[k][0];
            const std::string& n = params[k].name;
            if (n == "f0") f0 = x;
            else if (n == "f90") d.f90 = x;
            else if (n == "eta") d.eta = x;
            else if (n == "k") d.k = x;
            else if (n == "aspect") d.aspect = x;
            else if (n == "gamma") d.gamma = x;
        }
        return std::tuple{d, alpha, f0};
    };
    m.f = [at](const normzoo::vec3<double>& l, const normzoo::vec3<double>& v, const std::vector<rgb_value>& values) {
        const auto [d, alpha, f0] = at(values);
        const double x = d.f(l, v, normzoo::brdf::params<double>{0, f0, alpha});
        return rgb_value{x, x, x};
    };
    m.albedo = [at](double mu, const std::vector<rgb_value>& values, double tolerance) {
        const auto [d, alpha, f0] = at(values);
        normzoo::albedo_settings s;
        s.tolerance = tolerance;
        const auto e = mf::compensated_albedo(d, mu, alpha, f0, s);
        return std::array<normzoo::quadrature::estimate<double>, 3>{e, e, e};
    };
    return m;
}

// A library material (material/registry.hpp) as a reference: its numbers and colours by the
// specification's names at their defaults; a choice (glTF's masking) stays at its default (the
// specification's form), not a value a shader's parameter can give.
template <class M>
reference_material material_reference(const std::string& id, normzoo::material::compensation_kind k) {
    namespace mat = normzoo::material;
    reference_material m;
    m.id = id;
    std::vector<std::size_t> declared;  // the index in M::parameters of each reference parameter
    for (std::size_t i = 0; i < M::parameters.size(); ++i) {
        const normzoo::parameter& p = M::parameters[i];
        if (!p.choices.empty()) continue;
        m.parameters.push_back({std::string(p.name), p.components == 3, {p.held, p.held, p.held}, p.min, p.max});
        declared.push_back(i);
    }
    auto at = [declared](const std::vector<rgb_value>& values) {
        M g;
        for (std::size_t i = 0; i < declared.size(); ++i)
            for (std::size_t j = 0; j < std::size_t(M::parameters[declared[i]].components); ++j) g.set(declared[i], j, values[i][j]);
        return g;
    };
    m.f = [at](const normzoo::vec3<double>& l, const normzoo::vec3<double>& v, const std::vector<rgb_value>& values) {
        return at(values).f(l, v);
    };
    m.albedo = [at, k](double mu, const std::vector<rgb_value>& values, double tolerance) {
        normzoo::albedo_settings s;
        s.tolerance = tolerance;
        const auto a = mat::albedo(at(values), mu, k, s);
        std::array<normzoo::quadrature::estimate<double>, 3> out;
        for (std::size_t c = 0; c < 3; ++c) out[c] = {a.whole.value[c], a.whole.abs_error[c], a.evaluations};
        return out;
    };
    return m;
}

}  // namespace

reference_material reference_material_named(const std::string& id, const std::string& option) {
    // f of a compensated material or composition is not written (the library gives the
    // compensations' albedos), nor a transmitting interface's BTDF: only single scattering's
    // reflection is compared
    for (const char* c : {"/kulla-conty", "/turquin", "/fdez-aguera", "/transmission"})
        if (id.size() > std::string(c).size() && id.compare(id.size() - std::string(c).size(), std::string::npos, c) == 0)
            throw bad_input(option + ": " + id + ": the code is compared with the single-scattering material (its f); " +
                            "drop " + c + " (" + (std::string(c) == "/transmission" ? "the interface's albedo is energy --model's" : "a compensated albedo is energy --material's or --model's") +
                            ")");
    if (id.find('/') != std::string::npos && id.find('/') != id.rfind('/')) {  // D/G/F[/COMPENSATION]
        try {
            return composition_reference(id);
        } catch (const std::invalid_argument& e) {
            throw bad_input(option + ": " + e.what());
        }
    }
    const auto slash = id.find('/');
    namespace mat = normzoo::material;
    reference_material out;
    const bool known = mat::visit_material(id.substr(0, slash), [&](auto m) {
        try {
            const auto k = slash == std::string::npos ? mat::compensation_kind::none : mat::parse_compensation(id.substr(slash + 1));
            out = material_reference<decltype(m)>(id, k);
        } catch (const std::invalid_argument& e) {
            throw bad_input(option + ": " + id + ": " + e.what());
        }
    });
    if (known) return out;
    throw bad_input(option + ": unknown material '" + id + "' (known: " + normzoo::material::material_ids() + ", or a composition " +
                    "D/G/F[/COMPENSATION]; " + mf::composition::known_parts() + ")");
}

}  // namespace verify
