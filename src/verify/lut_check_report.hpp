// What `verify lut --check FILE` finds beyond its records, for its console report
// (lut_check_report.cpp): per channel the largest error per row and per column and in 8-bit
// display steps, for a split-sum table those of E = F0 A + B, what --detect tried, the reading
// a failing check would fit far better under, and an image's lookup error (lut_lookup.hpp).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "lut_detect.hpp"
#include "lut_layout.hpp"
#include "lut_lookup.hpp"
#include "writers.hpp"

namespace verify {

// One channel against the exact one: the largest error, at which point, and the tolerance
// there; how many texels are beyond their tolerance, of how many; the errors by decade
// ("<1e-8:3 1e-7:5"); per row and per column (a grid) the largest; the largest in 8-bit display
// steps (sRGB-encoded, of 255).
struct channel_errors {
    std::string name;
    double worst = -1, worst_tol = 0;
    std::size_t at = 0, above = 0, count = 0;
    std::string histogram;
    std::vector<double> by_row, by_col;
    double steps = 0;
};

// E = F0 A + B of a split-sum table, from its stored channels: the largest error and its steps.
struct e_errors {
    double worst = 0, steps = 0;
};

struct lut_check_report {
    std::string path, layout, model;
    std::vector<channel_errors> channels;
    std::optional<e_errors> dielectric, metal;  // F0 = 0.04 and 1 (dfg)
    bool grid = false;                          // an image: rows and columns
    std::vector<double> row_coord, col_coord;
    lut_axis row_axis = lut_axis::r, col_axis = lut_axis::mu;
    std::size_t not_compared = 0;                // texels at r = 0 or mu = 0
    std::size_t rounded_points = 0;              // a CSV's points whose decimals a double does not hold
    std::optional<layout_ranking> detected;      // --detect
    std::string hint;                            // a failing check: the reading that fits far better
    std::optional<lookup_errors> lookup;         // an image: its bilinear lookup's error
    std::string figure;                          // an image: the error map's file name (with --out)
};

// The report on stdout (with --json: the records are the report, the hint goes to stderr);
// drawn: the error map was staged (with --out), which stderr says.
void print_lut_check(const table_output& out, const console_view& v, const lut_check_report& r, bool drawn);

// A table of slices' report: a line per slice and channel (its index, its largest error and how
// many texels are beyond their tolerance), then the worst slice's report as print_lut_check's.
void print_lut_check_slices(const table_output& out, const console_view& v, const std::vector<lut_check_report>& reports,
                            std::size_t worst, bool drawn);

// The 8-bit sRGB display steps between two linear values (each clamped to [0, 1]).
double display_steps(double a, double b);

}  // namespace verify
