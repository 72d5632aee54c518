// OpenPBR Surface 1.1 (docs/materials.md, "OpenPBR Surface 1.1"): the material (openpbr_model.hpp:
// its inputs, lobes and layering operators, f), its coat's absorption and darkening
// (openpbr_coat.hpp), its fuzz (openpbr_fuzz.hpp) and its albedo with V fixed (openpbr_albedo.hpp).
#pragma once
#include "openpbr_albedo.hpp"
#include "openpbr_coat.hpp"
#include "openpbr_fuzz.hpp"
#include "openpbr_model.hpp"
