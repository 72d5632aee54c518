// The figures: SVGs drawn by gnuplot (src/verify/plots/gnuplot.hpp), one file each under
// src/verify/plots/, staged like every other results file. A table's runner hands its figure to
// table_output::figure. Each returns false (and says why on stderr) when gnuplot is missing or
// fails; the tables stand.
#pragma once
#include "writers.hpp"

#include <string>
#include <vector>

#include "library_names.hpp"

namespace verify {
struct shader_precision_audit;  // tables/shader_precision.hpp
}

namespace verify {

// bounds.svg: each Blinn-Phong normalization over its lower bound against n, with both bounds.
bool plot_bounds(const table_output& bounds, file_set& files);

// energy-albedo.svg: directional albedo against incident angle, a panel per form, a curve per exponent.
bool plot_albedo(const table_output& energy, file_set& files);

// fresnel-visibility.svg: the seed's three F V graphs, minimalist against Schlick with Kelemen /
// Szirmay-Kalos.
bool plot_fresnel_visibility(const table_output& fv, file_set& files);

// irradiance-limit.svg: log-log convergence, the irradiance's deviation from the point light
// against r0/r (the irradiance table's records), and the tiny cone's against its half-angle.
bool plot_limits(const std::vector<record>& irradiance, const table_output& punctual, file_set& files);

// shader-precision.svg: relative error of every shader formula in fp16 and fp32, against n
// (log-log) for the exponent formulas and lobes, against L.H for Schlick's forms, up to where each
// breaks; from the audits the table's records summarize.
bool plot_shader_precision(const std::vector<shader_precision_audit>& audits, file_set& files);

// error-audit.svg: how many cases at each log10(estimate / true error), a curve per family and
// number type; the failing side (below 0) shaded.
bool plot_error_audit(const table_output& histogram, file_set& files);

// models-energy.svg: the modern forms' albedo against incident angle, a panel per form, a curve
// per parameter value, the y axis logarithmic where a form reaches 2 (Ward, Duer).
bool plot_models_energy(const table_output& sweep, file_set& files);

// ndf.svg: the non-projected integral of Beckmann and GGX less 1 against alpha, log-log: the
// closed form on a fine alpha grid as lines, the table's quadrature as points.
bool plot_ndf(const table_output& ndf, file_set& files);

// ndf-furnace.svg: Smith G1 against view angle, a panel per NDF, a curve per alpha: closed form on
// a fine angle grid as lines, the table's G1 from the masking equation as points.
bool plot_ndf_furnace(const table_output& furnace, file_set& files);

// enclosures.svg: the enclosures table against n (log-log), a panel per zoo row: the enclosure's
// relative radius, the quadrature's error estimate and its true error as certified by the enclosure.
bool plot_enclosures(const table_output& enclosures, file_set& files);

// microfacet-energy.svg: E(mu, alpha) of each composition as a map (log mu, log alpha), its colour
// range fitted to the panel's data.
bool plot_microfacet_energy(const table_output& energy, file_set& files);

// One map of signed errors over (mu, alpha): values[j * mus.size() + i] at (mus[i], alphas[j]).
struct error_map {
    std::string title;
    std::vector<double> mus, alphas, values;
};

// microfacet-shortcuts.svg: each shortcut's error against the exact integral as a map over log mu
// and log alpha, the colour log10 |error| on a range fitted to the panel's data.
bool plot_error_maps(const std::vector<error_map>& maps, file_set& files);

// A checked table's error map (lut_lookup.hpp, error_map_of): cells in ascending coordinates, x
// along the mu axis (one column for E_avg), y along the roughness axis.
struct lut_error_map {
    std::string mu_axis, roughness_axis;  // as the layout names them: mu or sqrt-mu, r or alpha
    std::vector<double> xs, ys;           // each cell's coordinate
    std::size_t block = 1;                // a cell holds block x block texels and shows their largest error
    std::vector<std::string> names;       // per map: a channel, or "E at F0 = 0.04"
    std::vector<std::vector<double>> errors;  // per map: |stored - exact| at [y * xs.size() + x]; NaN: not compared
    std::vector<std::string> checked;     // the channels checked against their tolerance, in the order of the bits
    std::vector<unsigned> above;          // per cell: bit c set where a texel's channel c is beyond its tolerance
};

// lut-check-STEM.svg: the map of |stored - exact| of each channel over the table's coordinates,
// coloured by log10 (viridis), and where texels are beyond their tolerance; for E_avg, the error
// against the roughness. title: the file checked.
bool plot_lut_check(const lut_error_map& m, const std::string& name, const std::string& title, file_set& files);

// microfacet-eavg.svg: E_avg(alpha), a curve per composition.
bool plot_microfacet_eavg(const table_output& eavg, file_set& files);

// material-blend.svg: the difference of the two ways of mixing over roughness, at mu = 1.
bool plot_material_blend(const table_output& blend, file_set& files);

// material-furnace.svg: the whole's albedo over roughness at mu = 1, a panel per configuration.
bool plot_material_furnace(const table_output& furnace, file_set& files);

}  // namespace verify
