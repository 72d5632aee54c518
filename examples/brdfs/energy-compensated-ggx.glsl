// [brdf]
// [parameters.r]
// range = [0.05, 1]
// default = 0.515625
//
// GGX with Smith's height-correlated masking, F = 1, compensated for the energy single
// scattering loses by dividing by the split-sum table's A + B = E(N.V, r), read from a DFG
// texture as engines read it (docs/brdf-code.md#textures). Bake the table and bind it:
//   ./verify lut --kind dfg --size 32 --format exr --out /tmp/dfg
//   ./verify --brdf examples/brdfs/energy-compensated-ggx.glsl --texture dfg=/tmp/dfg/lut-dfg-32.exr --fixed view
// With V held the albedo is E / E_table: 1 where the table holds E exactly, and off by what its
// storage and its bilinear lookup between texel centres lose elsewhere.

const float PI = 3.14159265358979323846;

float D_GGX(float NoH, float a) {
    float ratio = a / (1.0 - NoH * NoH + NoH * NoH * a * a);
    return ratio * ratio / PI;
}

float V_SmithGGXCorrelated(float NoV, float NoL, float a) {
    float a2 = a * a;
    float lightTerm = NoV * sqrt((NoL - NoL * a2) * NoL + a2);
    float viewTerm = NoL * sqrt((NoV - NoV * a2) * NoV + a2);
    return 0.5 / (viewTerm + lightTerm);
}

uniform sampler2D dfg;

// The split-sum pair at (N.V, r): the table's rows are r, its columns N.V, at texel centres.
vec2 prefilteredDFG(sampler2D table, float NoV, float roughness) {
    return texture2D(table, vec2(NoV, roughness)).rg;
}

vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {
    float NoV = dot(N, V), NoL = dot(N, L);
    if (NoL <= 0.0 || NoV <= 0.0) return vec3(0.0);
    vec3 H = normalize(L + V);
    float a = r * r;
    vec2 ab = prefilteredDFG(dfg, NoV, r);
    return vec3(D_GGX(dot(N, H), a) * V_SmithGGXCorrelated(NoV, NoL, a) / (ab.x + ab.y));
}
