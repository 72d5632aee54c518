// [brdf]
// function = "BRDF"
// [parameters.construct]
// type = "float"
// range = [0, 15]
// default = 0
// [parameters.k]
// type = "float"
// range = [0, 1]
// default = 0.5
// [parameters.tint]
// type = "color"
// default = [0.25, 0.5, 0.125]
// [parameters.flip]
// type = "bool"
// default = true
//
// GLSL as engines write it (docs/brdf-code.md#what-is-supported), one construct for each value
// of `construct`: BRDF returns value / (16 pi), whose albedo is value / 16, and
// tests/test_shader_language.cpp knows each value. One file, so one compilation for them all.

precision mediump float;

uniform highp float k;
uniform vec3 tint;
uniform bool flip;

const float PI = 3.14159265358979323846;
const int COUNT = 3;
const int PAIR = COUNT * 2 - 4;  // a constant of constants: an array's size
const int THREE = int(PI);       // a constant C++ computes when it runs
const float W[COUNT] = float[COUNT](1.0, 2.0, 4.0);

#define LUMA(c) dot(c.rgb, vec3(0.25, 0.5, 0.25))

struct Surface {
    vec3 n;
    float r;
    float w[2];
};

// fields named like swizzles
struct Channel {
    float r;
    vec3 rgb;
};

float sum3(vec3 v) { return v.x + v.y + v.z; }

// overloads of one name: a call of the other is no recursion
float sq(float x) { return x * x; }
vec3 sq(vec3 v) { return vec3(sq(v.x), sq(v.y), sq(v.z)); }

// in, out and inout; a struct passed in and out
void shade(in Surface s, out Surface o, inout float acc) {
    o = s;
    o.r = s.r * 2.0;
    o.w[1] = 0.75;
    acc += o.r;
}

Surface make(vec3 n, float r) { return Surface(n, r, float[2](0.0, 0.0)); }

void split(float x, out float lo, out float hi) {
    lo = x * 0.5;
    hi = x * 2.0;
}

float[3] weights() { return float[3](0.5, 0.25, 0.125); }

highp float value(int c, vec3 L, vec3 V, mediump vec3 N, vec3 X, vec3 Y) {
    if (c == 0) return k;
    if (c == 1) return sum3(tint) * (flip ? 2.0 : 1.0);
    if (c == 2) {
        mediump float h = 0.25;
        highp float g = h.x;
        return g;
    }
    if (c == 3) {
        float q = 0.125;
        vec3 s = q.xxx;
        vec3 t = q.rrr;
        return sum3(s) + t.g;
    }
    if (c == 4) {
        vec3 v = vec3(0.0);
        v.xy = vec2(0.25, 0.5);
        v.z = 0.125;
        v.zy *= 2.0;
        v.yx = v.xy;
        v.x += 1.0;
        v.z++;
        ++v.x;
        v.xy[1] = 0.5;
        return v.x * 4.0 + v.y * 2.0 + v.z;
    }
    if (c == 5) {
        float a[3] = float[3](0.5, 0.25, 0.125);
        float b[] = float[](1.0, 2.0);
        float[2] d = float[2](4.0, 8.0);
        float e[2] = {16.0, 32.0};
        return a[0] + a[1] + a[2] + float(b.length()) + d[1] / 8.0 + e[0] / 16.0;
    }
    if (c == 6) {
        const float U[2] = float[2](0.5, 1.5);
        float w[3] = weights();
        return W[0] + W[COUNT - 1] + U[1] + w[2] + (w == weights() ? 1.0 : 0.0);
    }
    if (c == 7) {
        Surface s = make(N, 0.25);
        Surface o;
        float acc = 1.0;
        shade(s, o, acc);
        return o.r + acc + o.w[1] + o.n.z;
    }
    if (c == 8) {
        vec2 p = vec2(0.0);
        split(0.5, p.x, p.y);
        float a = 1.0, b[2] = float[2](2.0, 3.0), e;
        e = a + b[1];
        return p.x + p.y + e;
    }
    if (c == 9) {
        Channel ch = Channel(0.25, vec3(0.5, 1.0, 2.0));
        ch.rgb.g = 4.0;
        ch.r += 1.0;
        return ch.r + ch.rgb.g + ch.rgb.z;
    }
    if (c == 10) {
        vec3 l = V;
        l.xy = -l.yx;
        vec3 expect = vec3(-V.y, -V.x, V.z);
        mat3 m = mat3(X, X + Y, N);  // its columns
        vec3 local = V * m;
        vec3 world = m * V;
        bool same = l == expect && abs(local.y - dot(V, X + Y)) < 1e-5 && abs(local.z - dot(V, N)) < 1e-5 &&
                    length(world - (V.x * X + V.y * (X + Y) + V.z * N)) < 1e-5 && m[1] == X + Y;
        return same ? 1.0 : 0.0;
    }
    if (c == 11) {
        float new = 0.25;
        float real = 0.5;
        float and = 0.125;
        return new + real + and;
    }
    if (c == 12) return mod(-0.5, 2.0) + fract(-0.25);
    if (c == 13) return sum3(sq(vec3(0.5)));
    if (c == 14) return LUMA(tint);
    float acc = 0.0;
    for (int i = 0; i < COUNT; ++i) acc += W[i];
    float pair[PAIR];
    pair[1] = float(THREE - 3);
    return acc + pair[1];
}

float BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {
    return value(int(construct), L, V, N, X, Y) / (16.0 * PI);
}
