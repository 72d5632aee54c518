// The translation's precision pass (docs/brdf-code.md#precision): a floating type the code
// declares in reduced precision becomes the translation's reduced type (real -> hreal, vec3 ->
// hvec3, mat3 -> hmat3), which the binary16 program rounds to binary16 and the double and float
// programs take as their own real, vec3 and mat3.
#include <cctype>

#include "shader_rewrite.hpp"

namespace verify {

namespace {

// The translation's floating types: real, vecN, matN, matNxM.
bool floating_type(const std::string& o) {
    auto digit = [](char c) { return c >= '2' && c <= '4'; };
    if (o == "real") return true;
    if (o.size() == 4 && o.compare(0, 3, "vec") == 0) return digit(o[3]);
    if (o.size() == 4 && o.compare(0, 3, "mat") == 0) return digit(o[3]);
    return o.size() == 6 && o.compare(0, 3, "mat") == 0 && digit(o[3]) && o[4] == 'x' && digit(o[5]);
}

}  // namespace

// HLSL: half, min16float, min10float and their vectors and matrices (lowp's min10float as
// mediump's binary16). GLSL: a type after mediump or lowp (lowp as mediump: binary16 holds what
// lowp requires, GLSL ES 3.20 sec. 4.7.2), or, where `precision mediump float;` sets the file's
// default, one without highp; a constructor (vec3(...)) takes its arguments' precision, and stays.
void shader_rewriter::precision() {
    const bool reduced_default = !hlsl() && (s.float_precision == "mediump" || s.float_precision == "lowp");
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (!t.is_word(i) || t.is(t.prev(i), ".") || !floating_type(out[i])) continue;
        bool reduced = false;
        if (hlsl()) {
            reduced = is_reduced_precision(t[i].text);
        } else {
            const std::size_t q = t.prev(i);
            const bool qualified = t.is(q, "mediump") || t.is(q, "lowp");
            reduced = qualified || (reduced_default && !t.is(q, "highp") && !t.is(t.next(i), "("));
        }
        if (reduced) out[i] = "h" + out[i];
    }
}

}  // namespace verify
