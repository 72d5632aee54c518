// For a harness that parses --layout (lut_layout.cpp) without building lut_exact.cpp, whose exact
// tables are not input parsing: lut_layout.cpp's layout_text and check_layout name a kind and its
// channels with these, and --layout's parsing never calls them. Included by one file per harness.
#pragma once
#include <string>
#include <vector>

#include "lut_exact.hpp"

std::vector<std::string> verify::lut_channels(lut_kind k) {
    if (k == lut_kind::dfg) return {"A", "B"};
    return {k == lut_kind::e ? "E" : "E_avg"};
}
std::string verify::lut_kind_name(lut_kind k) { return k == lut_kind::dfg ? "dfg" : k == lut_kind::e ? "E" : "Eavg"; }

