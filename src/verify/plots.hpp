// Plots drawn by gnuplot (Debian gnuplot-nox) into SVG, staged like every other results file.
#pragma once
#include "writers.hpp"

namespace verify {

// Each Blinn-Phong normalization over its lower bound against n, with both bounds.
// Returns false (and says why on stderr) when gnuplot is missing or fails; the tables stand.
bool plot_bounds(const table_output& bounds, file_set& files);

// Directional albedo against incident angle, one panel per form, a curve per exponent.
bool plot_albedo(const table_output& energy, file_set& files);

// The seed's three F V graphs: minimalist against Schlick with Kelemen / Szirmay-Kalos.
bool plot_fresnel_visibility(const table_output& fv, file_set& files);

// Log-log convergence: the irradiance's deviation from the point light against r0/r, and the
// tiny cone's against its half-angle (needs the irradiance and punctual-limit tables).
bool plot_limits(const std::vector<table_output>& outputs, file_set& files);

// Relative error of every shader formula in fp16 and fp32: against n (log-log) for the exponent
// formulas and lobes, against L.H for Schlick's forms, up to where each breaks.
bool plot_shader_precision(const table_output& precision, file_set& files);
// The error audit: how many cases at each log10(estimate / true error), a curve per family and
// number type; the failing side (below 0) shaded.
bool plot_error_audit(const table_output& histogram, file_set& files);

// The modern forms' albedo against incident angle (models-energy): a panel per form, a curve per
// parameter value, the y axis logarithmic where a form reaches 2 (Ward, Duer).
bool plot_models_energy(const table_output& sweep, file_set& files);
// The non-projected integral of Beckmann and GGX less 1 against alpha, log-log (ndf): the closed
// form on a fine alpha grid as lines, the table's quadrature as points.
bool plot_ndf(const table_output& ndf, file_set& files);
// Smith G1 against view angle (ndf-furnace), a panel per NDF, a curve per alpha: closed form on a
// fine angle grid as lines, the table's G1 from the masking equation as points.
bool plot_ndf_furnace(const table_output& furnace, file_set& files);
// The enclosures table against n (log-log), a panel per zoo row: the enclosure's relative radius,
// the quadrature's error estimate and its true error as certified by the enclosure.
bool plot_enclosures(const table_output& enclosures, file_set& files);

}  // namespace verify
