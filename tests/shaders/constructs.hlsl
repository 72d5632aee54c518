// [brdf]
// function = "Evaluate"
// [parameters.construct]
// type = "float"
// range = [0, 15]
// default = 0
// [parameters.roughness]
// type = "float"
// range = [0, 1]
// default = 0.5
// [parameters.tint]
// type = "color"
// default = [0.25, 0.5, 0.125]
//
// HLSL as engines write it (docs/brdf-code.md#what-is-supported), one construct for each value
// of `construct`: Evaluate returns value / (16 pi), whose albedo is value / 16, and
// tests/test_shader_language.cpp knows each value. One file, so one compilation for them all.

cbuffer Material : register(b0)
{
    float roughness;
    float3 tint;
};

float construct;  // a plain global: a uniform, in HLSL

static const float PI = 3.14159265358979323846;
static const float W[3] = { 1.0, 2.0, 4.0 };

struct Surface
{
    float3 n;
    float r;
};

float max3(float3 v) { return max(v.x, max(v.y, v.z)); }

void split(float x, out float lo, inout float hi)
{
    lo = x * 0.5;
    hi += x;
}

Surface make(float3 n)
{
    Surface s = (Surface)0;
    s.n = n;
    s.r = roughness;
    return s;
}

float Value(int c, float3 L, float3 V, float3 N, float3 X, float3 Y)
{
    [branch] if (c == 0) return roughness;
    if (c == 1) return rcp(4.0) + saturate(1.5) + saturate(-2.0);
    if (c == 2) return lerp(1.0, 3.0, 0.25);
    if (c == 3) return rsqrt(16.0) + frac(-0.25) + frac(1.75);
    if (c == 4) return mad(0.5, 3.0, 0.25);
    if (c == 5)
    {
        float2 r = fmod(float2(-5.5, 5.5), 2.0);
        return fmod(-5.5, 2.0) + 2.0 + r.x + r.y;
    }
    if (c == 6)
    {
        float s, co;
        sincos(0.5, s, co);
        float2 sc;
        sincos(0.0, sc.x, sc.y);
        return s * s + co * co + sc.x + sc.y;
    }
    if (c == 7)
    {
        float q = 0.125;
        float3 s = q.xxx;
        float3 t = q.rrr;
        return max3(s + t) + s.x;
    }
    if (c == 8)
    {
        float3 v = 0;
        v.xy = float2(0.25, 0.5);
        v.z = 0.125;
        v.zy *= 2;
        v.yx = v.xy;
        v.x += 1;
        v.z++;
        ++v.x;
        return v.x * 4 + v.y * 2 + v.z;
    }
    if (c == 9)
    {
        float a[3] = { 0.5, 0.25, 0.125 };
        float b[] = { 1.0, 2.0 };
        return a[0] + a[1] + a[2] + b[1] + W[2];
    }
    if (c == 10)
    {
        Surface s = make(N);
        float lo, hi = 1.0;
        split(s.r, lo, hi);
        return lo + hi + s.n.z;
    }
    if (c == 11)
    {
        float3x3 m = float3x3(X, X + Y, N);  // its rows
        float3 local = mul(m, V);
        float3 back = mul(V, m);
        bool same = abs(local.y - dot(V, X + Y)) < 1e-5 && abs(local.z - dot(V, N)) < 1e-5 &&
                    length(back - (V.x * X + V.y * (X + Y) + V.z * N)) < 1e-5 && length(m[1] - (X + Y)) < 1e-6;
        return same ? 1.0 : 0.0;
    }
    if (c == 12)
    {
        float acc = 0;
        [unroll] for (int i = 0; i < 3; ++i) acc += W[i];
        return acc;
    }
    if (c == 13)
    {
        half h = 0.5;
        min16float m = 0.25;
        return h + m;
    }
    if (c == 14)
    {
        float3 v = V;
        v.xy = -v.yx;
        return abs(v.x + V.y) + abs(v.y + V.x) + abs(v.z - V.z) == 0 ? 1.0 : 0.0;
    }
    return max3(tint) + max3((float3)0.5);
}

float Evaluate(float3 L, float3 V, float3 N, float3 X, float3 Y)
{
    return Value((int)construct, L, V, N, X, Y) / (16 * PI);
}
