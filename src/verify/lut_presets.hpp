// The layouts engines store their split-sum and E tables in, and the model each bakes with
// (docs/lut.md, "Presets", which cites each engine's source): `verify lut --check FILE --preset
// ENGINE`. --layout keys given beside a preset override its keys, --model its model.
#pragma once
#include <string>
#include <vector>

#include "lut_exact.hpp"

namespace verify {

struct lut_preset {
    std::string name;
    lut_kind kind;
    std::string layout;  // --layout keys (lut_layout.hpp)
    std::string model;   // the composition the engine bakes with
    std::string eta;     // size=WxHxD: each slice's index, as --eta would list them
};

namespace detail {
// num/den < 1 to 20 places by long division (cut, not rounded: within 1e-20 of the fraction),
// without trailing zeros
inline std::string places_of(long num, long den) {
    std::string s = "0.";
    for (int k = 0; k < 20; ++k, num %= den) s += char('0' + (num *= 10) / den);
    return s.substr(0, s.find_last_not_of('0') + 1);
}
}  // namespace detail

// openpbr-bsdf's index axis of 32 slices (impl/openpbr_microfacet_multiple_scattering_data.h,
// openpbr_ior_to_exact_index): 1/eta from 2.5 down to 1 by 0.1 in slices 0 to 15, eta from 1 up
// to 2.5 by 0.1 in slices 16 to 31; the two at eta = 1 baked at 1/1.0001 and 1.0001, the least
// index its BSDF refracts at (MinRefractionIorAboveOne, impl/openpbr_bsdf.h; docs/lut.md). The
// fractions 10/(25 - i) and 1/1.0001 are written to 20 places: within 1e-20. Inline, as the
// presets are.
inline std::string openpbr_bsdf_eta_axis() {
    std::string s;
    for (int i = 0; i < 32; ++i) {
        std::string v;
        if (i == 15) v = detail::places_of(10000, 10001);  // 1/1.0001
        else if (i == 16) v = "1.0001";
        else if (i < 16) v = detail::places_of(10, 25 - i);
        else v = std::to_string((i - 6) / 10) + "." + std::to_string((i - 6) % 10);  // 1 + (i - 16)/10
        s += (s.empty() ? "" : ",") + v;
    }
    return s;
}

// Each line is what the engine's own source says (docs/lut.md, "Presets", cites the files); where
// it says nothing, the line says so. Inline: the command line lists the names in its help.
inline const std::vector<lut_preset>& lut_presets() {
    const std::string correlated = "ggx/smith-height-correlated/one";
    // Schlick-GGX with k = alpha/2 (LearnOpenGL's k = a*a/2 with a = r; Godot likewise)
    const std::string schlick = "ggx/schlick-ggx/one";
    const std::string sheen = sheen_e_model, cloth = "charlie/ashikhmin/one";
    const std::string separable = "ggx/smith-separable/one", separable_dielectric = "ggx/smith-separable/dielectric";
    const std::string transmitting = separable_dielectric + "/transmission";
    static const std::vector<lut_preset> presets = {
        // the .inc cmgen writes "in GL order"; its image outputs (png, exr, dds) start at r = 1: row0=high
        {"filament", lut_kind::dfg, "rows=r,cols=mu,row0=low,col0=low,grid=filament,channels=B,A+B,-,encoding=half", correlated, ""},
        {"gltf-sample-viewer", lut_kind::dfg, "rows=r,cols=mu,row0=low,col0=low,grid=centres,channels=A,B,encoding=linear", correlated, ""},
        {"gltf-ibl-sampler", lut_kind::dfg, "rows=r,cols=mu,row0=low,col0=low,grid=centres,channels=A,B,encoding=linear", correlated, ""},
        // the public talk gives only a 2D table of (roughness, cos) holding scale and bias, and
        // Schlick's G "matched to Smith"; the rest is the common reading, not verifiable
        {"unreal", lut_kind::dfg, "rows=r,cols=mu,row0=low,col0=low,grid=centres,channels=A,B,encoding=linear", schlick, ""},
        // baked at run time into A2B10G10R10: 10-bit codes; sqrt(N.V) and r corner-aligned
        {"unity-hdrp", lut_kind::dfg, "rows=r,cols=sqrt-mu,row0=low,col0=low,grid=edges,channels=B,A+B,-,encoding=unorm10", correlated, ""},
        // RGBA16F, written at row 127 - y: the first row is r = 1
        {"godot", lut_kind::dfg, "rows=r,cols=mu,row0=high,col0=low,grid=centres,channels=B,A+B,-,-,encoding=half", schlick, ""},
        {"bevy", lut_kind::dfg, "rows=r,cols=mu,row0=low,col0=low,grid=centres,channels=A,B,encoding=half", correlated, ""},
        // looked up at (r, N.V): rows are N.V
        {"threejs", lut_kind::dfg, "rows=mu,cols=r,row0=low,col0=low,grid=centres,channels=A,B,encoding=half", correlated, ""},
        {"babylon", lut_kind::dfg, "rows=r,cols=mu,row0=low,col0=low,grid=centres,channels=B,A+B,-,encoding=rgbd", correlated, ""},
        {"learnopengl", lut_kind::dfg, "rows=r,cols=mu,row0=low,col0=low,grid=centres,channels=A,B,encoding=half", schlick, ""},
        // table_ggx_E[1024] in intern/cycles/scene/shader.tables: a flat array, rows mu, columns r
        {"cycles", lut_kind::e, "rows=mu,cols=r,row0=low,col0=low,grid=edges,channels=E,encoding=linear,size=32x32", correlated, ""},
        // lut_sheen_E.png, looked up at (N.V, sheenRoughness).r with no remap; D_Charlie and V_Sheen
        // square sheenRoughness (source/Renderer/shaders/brdf.glsl): rows=r
        {"gltf-sample-viewer-sheen", lut_kind::e, "rows=r,cols=mu,row0=low,col0=low,grid=centres,channels=E,encoding=linear", sheen, ""},
        // cmgen's cloth channel, dfg.z: Charlie D at alpha = r^2 with the Ashikhmin (Neubelt) visibility, F = 1
        {"filament-cloth", lut_kind::e, "rows=r,cols=mu,row0=low,col0=low,grid=filament,channels=-,-,E,encoding=half", cloth, ""},
        // openpbr-bsdf's impl/data energy tables: 1 - E of GGX with F = 1 and separable Smith
        // (openpbr_eval_aniso_smith_g2 = G1 G1), [r][mu] with r = sqrt(alpha), both corner-aligned
        // (index x 31), unorm16 codes in C source
        {"openpbr-bsdf-metal", lut_kind::e, "rows=r,cols=mu,row0=low,col0=low,grid=edges,channels=1-E,encoding=unorm16,size=32x32", separable, ""},
        {"openpbr-bsdf-metal-average", lut_kind::eavg, "rows=r,row0=low,grid=edges,channels=1-E_avg,encoding=unorm16,size=1x32", separable, ""},
        // the blue channel of Babylon's RGBD table: Filament's cloth integral (Charlie D at alpha = r^2,
        // the Ashikhmin visibility), on Filament's grid, both as the shipped table reads (docs/lut.md)
        {"babylon-sheen", lut_kind::e, "rows=r,cols=mu,row0=low,col0=low,grid=filament,channels=-,-,E,encoding=rgbd", cloth, ""},
        // openpbr-bsdf's opaque dielectric: 1 - E of the reflection alone (the refracted light
        // lost), GGX with separable Smith and the exact F, [eta][r][mu], 32 slices of its index axis
        {"openpbr-bsdf-opaque-dielectric", lut_kind::e,
         "rows=r,cols=mu,row0=low,col0=low,grid=edges,channels=1-E,encoding=unorm16,size=32x32x32", separable_dielectric, openpbr_bsdf_eta_axis()},
        {"openpbr-bsdf-opaque-dielectric-average", lut_kind::eavg, "rows=r,row0=low,grid=edges,channels=1-E_avg,encoding=unorm16,size=1x32x32",
         separable_dielectric, openpbr_bsdf_eta_axis()},
        // its transmitting dielectric: 1 - E of reflection and refraction together (Walter et al.'s
        // BTDF, the same G and F), the same axes
        {"openpbr-bsdf-ideal-dielectric", lut_kind::e,
         "rows=r,cols=mu,row0=low,col0=low,grid=edges,channels=1-E,encoding=unorm16,size=32x32x32", transmitting, openpbr_bsdf_eta_axis()},
        {"openpbr-bsdf-ideal-dielectric-average", lut_kind::eavg, "rows=r,row0=low,grid=edges,channels=1-E_avg,encoding=unorm16,size=1x32x32",
         transmitting, openpbr_bsdf_eta_axis()},
    };
    return presets;
}

// The preset named, which must be a table of kind; bad_input (beginning "lut: --preset") naming
// it and the presets otherwise.
const lut_preset& preset_named(const std::string& name, lut_kind kind);

}  // namespace verify
