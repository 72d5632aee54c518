// The specular terms of a GGX microfacet lobe, f = D * V * F with V = G / (4 N.L N.V),
// one function per term, in the form Filament's documentation gives them (Guy and Agopian,
// "Physically Based Rendering in Filament", section "Specular BRDF").
#pragma once

#include "math.glsl"

// 0: Hammon's approximation of the visibility; 1 (default): the height-correlated Smith term.
#ifndef SPECULAR_QUALITY
#define SPECULAR_QUALITY 1
#endif

float distributionGGX(float alpha, float NoH, vec3 n, vec3 h) {
    // 1 - NoH^2 as |n x h|^2 (Lagrange's identity): the subtraction cancels in half
    // precision where NoH is close to 1.
    vec3 nCrossH = cross(n, h);
    float cosAlpha = NoH * alpha;
    float ratio = alpha / (dot(nCrossH, nCrossH) + cosAlpha * cosAlpha);
    return saturateMediump(ratio * ratio * (1.0 / PI));
}

float visibilitySmithGGX(float alpha, float NoV, float NoL) {
#if SPECULAR_QUALITY >= 1
    float a2 = sq(alpha);
    float viewTerm = NoL * sqrt((NoV - a2 * NoV) * NoV + a2);
    float lightTerm = NoV * sqrt((NoL - a2 * NoL) * NoL + a2);
    return saturateMediump(0.5 / (viewTerm + lightTerm));
#else
    // Hammon 2017, "PBR Diffuse Lighting for GGX+Smith Microsurfaces"
    return saturateMediump(0.5 / mix(2.0 * NoL * NoV, NoL + NoV, alpha));
#endif
}

vec3 fresnelSchlick(vec3 f0, float VoH) {
    float f = pow(1.0 - VoH, 5.0);
    return f + f0 * (1.0 - f);
}
