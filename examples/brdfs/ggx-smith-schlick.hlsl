// [brdf]
// function = "SpecularGGX"
// language = "hlsl"
// [parameters.roughness]
// type = "float"
// range = [0.03, 1.0]
// default = 0.5
// [parameters.f0]
// type = "float"
// range = [0.0, 1.0]
// default = 1.0
//
// The GGX/Smith/Schlick BRDF of ggx-smith-schlick.brdf, written as engines keep it in HLSL
// (a BRDF.ush-like file): the same albedo, by the table brdf-examples' built-in twin.

static const float PI = 3.14159265358979323846;

float D_GGX(float NoH, float a)
{
    float a2 = a * a;
    float d = NoH * NoH * (a2 - 1) + 1;
    return a2 / (PI * d * d);
}

float Lambda_GGX(float NoX, float a)
{
    float tan2 = (1 - NoX * NoX) / (NoX * NoX);
    return (-1 + sqrt(1 + a * a * tan2)) * 0.5;
}

float3 SpecularGGX(float3 L, float3 V, float3 N, float3 X, float3 Y)
{
    float NoL = dot(N, L);
    float NoV = dot(N, V);
    if (NoL <= 0 || NoV <= 0) return 0;
    float a = roughness * roughness;
    float3 H = normalize(L + V);
    float D = D_GGX(saturate(dot(N, H)), a);
    float G = 1 / (1 + Lambda_GGX(NoL, a) + Lambda_GGX(NoV, a));
    float F = f0 + (1 - f0) * pow(1 - saturate(dot(V, H)), 5);
    return D * G * F / (4 * NoL * NoV);
}
