// [brdf]
// function = "specularLobe"
// [parameters.perceptualRoughness]
// type = "float"
// range = [0.0, 1.0]
// default = 0.5
// [parameters.f0]
// type = "color"
// default = [0.04, 0.04, 0.04]
//
// A specular lobe as an engine keeps it: its terms in a shared file found through the include
// path (--include-dir examples/brdfs/engine/common), a quality switch (SPECULAR_QUALITY), a
// mobile path (TARGET_MOBILE), the material's parameters as uniforms, mediump as the default
// precision, and energy compensation for multiple scattering (ENERGY_COMPENSATION) that
// divides by the lobe's directional albedo read from a DFG texture (dfgLut). docs/brdf-code.md,
// "An engine's file", shows how to check it.
#version 300 es
precision mediump float;

#include "brdf.glsl"

#define MIN_PERCEPTUAL_ROUGHNESS 0.045

uniform highp float perceptualRoughness;
uniform vec3 f0;

#if defined(ENERGY_COMPENSATION)
// The split-sum pair (A, B) of GGX with height-correlated Smith at F = 1, in u = N.V and
// v = perceptual roughness; A + B is the lobe's directional albedo.
uniform sampler2D dfgLut;
#endif

vec3 specularLobe(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {
    float NoL = dot(N, L);
    float NoV = dot(N, V);
    if (NoL <= 0.0 || NoV <= 0.0) {
        return vec3(0.0);
    }
    vec3 H = normalize(L + V);
    float NoH = clamp(dot(N, H), 0.0, 1.0);
    float VoH = clamp(dot(V, H), 0.0, 1.0);
    float roughness = clamp(perceptualRoughness, MIN_PERCEPTUAL_ROUGHNESS, 1.0);
    float alpha = roughness * roughness;
    vec3 f = (distributionGGX(alpha, NoH, N, H) * visibilitySmithGGX(alpha, NoV, NoL)) * fresnelSchlick(f0, VoH);
#if defined(ENERGY_COMPENSATION)
    vec2 dfg = textureLod(dfgLut, vec2(NoV, roughness), 0.0).xy;
    f *= 1.0 + f0 * (1.0 / (dfg.x + dfg.y) - 1.0);
#endif
    return f;
}
