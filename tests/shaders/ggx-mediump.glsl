// [brdf]
// [parameters.roughness]
// range = [0.01, 1]
// default = 0.5
// [parameters.robust]
// type = "bool"
// default = false
//

// GGX (Walter et al. 2007) in a file whose default precision is mediump, its directions highp, as
// engines write it for mobile GPUs: D from 1 - (N.H)^2 as written (robust = false), which cancels
// in binary16 near the highlight, or from |N x H|^2 = 1 - (N.H)^2 (Lagrange's identity, the
// remedy Filament's brdf.fs describes), kept below binary16's largest value (65504) as engines
// do; Smith's height-correlated visibility (Heitz 2014) in highp. docs/brdf-code.md#precision.
precision mediump float;

const highp float PI = 3.14159265358979323846;

float D_GGX(float NoH, float oneMinusNoH2, float a)
{
    float x = NoH * a;
    float k = a / (oneMinusNoH2 + x * x);
    return min(k * k * (1.0 / PI), 65504.0);
}

// Smith's height-correlated visibility, G / (4 N.L N.V) (Heitz 2014)
highp float V_Smith(highp float NoV, highp float NoL, highp float a)
{
    highp float a2 = a * a;
    highp float v = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    highp float l = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / (v + l);
}

vec3 BRDF(highp vec3 L, highp vec3 V, highp vec3 N, highp vec3 X, highp vec3 Y)
{
    highp float NoL = dot(N, L);
    highp float NoV = dot(N, V);
    if (NoL <= 0.0 || NoV <= 0.0) return vec3(0.0);
    highp vec3 H = normalize(L + V);
    highp vec3 NxH = cross(N, H);
    float NoH = dot(N, H);
    float oneMinus = robust ? dot(NxH, NxH) : 1.0 - NoH * NoH;
    float a = roughness * roughness;
    return vec3(D_GGX(NoH, oneMinus, a) * V_Smith(NoV, NoL, a));
}
