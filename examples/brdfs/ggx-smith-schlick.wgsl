// [brdf]
// function = "BRDF"
// [parameters.perceptual_roughness]
// type = "float"
// range = [0.089, 1.0]
// default = 0.5
// [parameters.f0]
// type = "float"
// range = [0.0, 1.0]
// default = 1.0
//
// The GGX/Smith/Schlick BRDF of ggx-smith-schlick.brdf and .hlsl, written in WGSL as Bevy keeps
// its lighting functions (bevy_pbr's pbr_lighting.wgsl): one fn per term, named after it, the
// perceptual roughness squared into the roughness the terms take, dot products gathered in a
// struct passed by value, f32 throughout. The table brdf-examples' built-in twin holds it too
// (tests/test_brdf_wgsl.cpp; docs/brdf-code.md#wgsl).

const PI: f32 = 3.141592653589793;

// The dot products the terms read.
struct SpecularInput {
    n_dot_v: f32,
    n_dot_l: f32,
    n_dot_h: f32,
    l_dot_h: f32,
}

// An engine binds its parameters; this one is the header's f0.
@group(2) @binding(1) var<uniform> f0: f32;

fn perceptual_roughness_to_roughness(perceptual_roughness: f32) -> f32 {
    // engines keep the roughness above what f16 resolves; the header's range starts there
    let clamped = clamp(perceptual_roughness, 0.089, 1.0);
    return clamped * clamped;
}

// Trowbridge-Reitz (GGX) normal distribution.
fn d_ggx(roughness: f32, n_dot_h: f32) -> f32 {
    let a2 = roughness * roughness;
    let d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

// Smith's height-correlated masking-shadowing over 4 N.L N.V (Heitz 2014, eq. 99).
fn v_smith_ggx_correlated(roughness: f32, n_dot_v: f32, n_dot_l: f32) -> f32 {
    let a2 = roughness * roughness;
    let lambda_v = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
    let lambda_l = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
    return 0.5 / (lambda_v + lambda_l);
}

// Schlick's Fresnel from f0 to f90.
fn f_schlick(f0: vec3<f32>, f90: f32, l_dot_h: f32) -> vec3<f32> {
    let x = 1.0 - l_dot_h;
    let x2 = x * x;
    return f0 + (vec3(f90) - f0) * (x2 * x2 * x);
}

fn specular(input: SpecularInput, roughness: f32, f0: vec3<f32>) -> vec3<f32> {
    let d = d_ggx(roughness, input.n_dot_h);
    let v = v_smith_ggx_correlated(roughness, input.n_dot_v, input.n_dot_l);
    return d * v * f_schlick(f0, 1.0, input.l_dot_h);
}

fn BRDF(L: vec3<f32>, V: vec3<f32>, N: vec3<f32>, X: vec3<f32>, Y: vec3<f32>) -> vec3<f32> {
    var input: SpecularInput;
    input.n_dot_l = dot(N, L);
    input.n_dot_v = dot(N, V);
    if input.n_dot_l <= 0.0 || input.n_dot_v <= 0.0 {
        return vec3<f32>(0.0);
    }
    let h = normalize(L + V);
    input.n_dot_h = saturate(dot(N, h));
    input.l_dot_h = saturate(dot(L, h));
    let roughness = perceptual_roughness_to_roughness(perceptual_roughness);
    return specular(input, roughness, vec3f(f0));
}

// What the BRDF does not reach, an engine's file holds too: read, never run.
struct View {
    exposure: f32,
}
@group(0) @binding(0) var<uniform> view: View;

@fragment
fn fragment(@location(0) color: vec3<f32>) -> @location(0) vec4<f32> {
    return vec4<f32>(color * view.exposure, 1.0);
}
