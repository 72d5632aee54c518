// [brdf]
// function = "BRDF"
// [parameters.one]
// type = "float"
// range = [1, 1]
// default = 1
//
// WGSL's semantics where GLSL's or C++'s differ, checked at run time: the BRDF is Lambert's 1/pi
// when every check holds and 0 otherwise, so its albedo is 1 exactly when the translation computes
// what WGSL defines (tests/test_brdf_wgsl.cpp). `one` is a parameter, so nothing here is folded
// at shader creation unless WGSL folds it (the abstract checks).

const PI = 3.14159265358979323846;

fn near(a: f32, b: f32) -> bool {
    return abs(a - b) <= 1e-6 * max(1.0, abs(b));
}

// A module-scope fn shadows the built-in of its name (#declaration-and-scope).
fn exp2(x: f32) -> f32 {
    return 42.0 + x;
}

// i32 division and remainder at zero and at the extremes (#arithmetic-expr), conversions from
// f32 (#floating-point-conversion), the integer built-ins.
fn integers() -> bool {
    let k = i32(one);
    let zero = k - 1;
    var ok = 7 / zero == 7 && 7 % zero == 0;
    ok = ok && -7 / (2 * k) == -3 && -7 % (2 * k) == -1;
    ok = ok && i32(-2.7 * one) == -2 && i32(1e20 * one) == 2147483520 && i32(-1e20 * one) == i32(-2147483648.0);
    let lowest = i32(-2147483648.0 * one);
    ok = ok && lowest / -k == lowest && lowest % -k == 0;
    ok = ok && abs(-5 * k) == 5 && min(3 * k, -2) == -2 && max(3 * k, -2) == 3 && clamp(9 * k, 0, 4) == 4 && sign(-3 * k) == -1;
    let u = u32(7.9 * one);
    ok = ok && u == 7u && u / 2u == 3u && u % 4u == 3u && u32(-3.0 * one) == 0u;
    ok = ok && f32(k + 2) == 3.0 && bool(zero) == false && i32(true) == 1;
    return ok;
}

fn floats() -> bool {
    let x = 5.5 * one;
    var ok = near(x % 2.0, 1.5) && near(-x % 2.0, -1.5);
    let v = vec3<f32>(5.5, -5.5, 1.0) * one % 2.0;
    ok = ok && near(v.x, 1.5) && near(v.y, -1.5) && near(v.z, 1.0);
    ok = ok && round(2.5 * one) == 2.0 && round(3.5 * one) == 4.0 && round(-2.5 * one) == -2.0 && round(0.4 * one) == 0.0;
    ok = ok && trunc(-2.7 * one) == -2.0 && fract(-0.25 * one) == 0.75 && floor(-0.5 * one) == -1.0 && ceil(0.5 * one) == 1.0;
    ok = ok && select(1.0, 2.0, one > 0.5) == 2.0 && select(1.0, 2.0, one < 0.5) == 1.0;
    ok = ok && step(1.0, one) == 1.0 && step(1.5, one) == 0.0 && near(smoothstep(0.0, 2.0, one), 0.5);
    ok = ok && near(mix(2.0, 4.0, 0.25 * one), 2.5) && fma(2.0 * one, 3.0, 1.0) == 7.0 && saturate(1.5 * one) == 1.0;
    ok = ok && near(atan2(one, -one), 0.75 * PI) && near(atan(one), 0.25 * PI) && inverseSqrt(4.0 * one) == 0.5;
    ok = ok && near(pow(2.0 * one, 10.0), 1024.0) && near(exp(one), 2.718281828) && near(log2(8.0 * one), 3.0);
    ok = ok && near(degrees(PI * one), 180.0) && near(radians(180.0 * one), PI) && sign(-2.0 * one) == -1.0;
    ok = ok && exp2(one) == 43.0;
    let min = 3.0 * one;  // a local shadows the built-in
    return ok && min == 3.0;
}

fn vectors_and_matrices() -> bool {
    let m = mat2x2<f32>(1.0, 2.0, 3.0, 4.0) * one;  // columns (1, 2) and (3, 4)
    let a = m * vec2(1.0, 0.0);
    let b = vec2(1.0, 0.0) * m;
    var ok = a.x == 1.0 && a.y == 2.0 && b.x == 1.0 && b.y == 3.0 && transpose(m)[0].y == 3.0 && m[1][0] == 3.0;
    ok = ok && near(determinant(m), -2.0);
    ok = ok && near(determinant(mat3x3<f32>(2.0, 0.0, 0.0, 0.0, 3.0, 0.0, 1.0, 0.0, 4.0) * one), 24.0);
    let q = mat4x4f(vec4f(1.0, 2.0, 0.0, 0.0), vec4f(0.0, 1.0, 0.0, 0.0), vec4f(0.0, 0.0, 3.0, 1.0), vec4f(0.0, 0.0, 2.0, 1.0));
    ok = ok && near(determinant(q * one), 1.0);
    let r = reflect(vec3(1.0, -1.0, 0.0) * one, vec3(0.0, 1.0, 0.0));
    ok = ok && r.x == 1.0 && r.y == 1.0 && faceForward(vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, one), vec3(0.0, 0.0, 1.0)).z == -1.0;
    ok = ok && near(length(vec3(3.0, 4.0, 12.0) * one), 13.0) && near(distance(vec2(one, 0.0), vec2(0.0, 0.0)), 1.0);
    ok = ok && cross(vec3(one, 0.0, 0.0), vec3(0.0, 1.0, 0.0)).z == 1.0 && dot(vec4f(one), vec4f(2.0)) == 8.0;
    var c = vec4<f32>(0.0);
    c.y = 2.0 * one;
    c[2] = 3.0;
    c.a += 4.0;
    var n = mat3x3<f32>();
    n[1][2] = 5.0 * one;
    ok = ok && c.y == 2.0 && c.z == 3.0 && c.w == 4.0 && c.x == 0.0 && n[1].z == 5.0 && all_zero(n[0]);
    return ok && c.rg.y == 2.0 && c.zyx.x == 3.0;
}

fn all_zero(v: vec3f) -> bool {
    return v.x == 0.0 && v.y == 0.0 && v.z == 0.0;
}

// Folded at shader creation in AbstractInt and AbstractFloat (#abstract-types).
fn abstracts() -> bool {
    let half_int: f32 = 1 / 2;
    const sum = 0.1 + 0.2;  // binary64: 0.30000000000000004
    const big = 4000000000 / 2;
    let third = 1.0 / 3.0 * one;
    return half_int == 0.0 && near(sum * one, 0.3) && big == 2000000000 && near(third, 0.33333333);
}

struct Pair {
    a: f32,
    b: vec2<f32>,
}

struct Nested {
    p: Pair,
    k: i32,
}

fn structures() -> bool {
    var n = Nested(Pair(one, vec2(2.0, 3.0)), 4);
    n.p.b.y = 5.0;
    let z = Nested();
    return n.p.a == 1.0 && n.p.b.x == 2.0 && n.p.b.y == 5.0 && n.k == 4 && z.p.a == 0.0 && z.k == 0;
}

fn loops() -> bool {
    var s = 0;
    for (var i = 0; i < 5; i++) {
        if i == 2 {
            continue;
        }
        s += i;
    }
    var j = 0;
    loop {
        j++;
        continuing {
            break if j >= 3 * i32(one);
        }
    }
    var w = 0.0;
    while w < 2.5 * one {
        w += 1.0;
    }
    var e = 0;
    loop {
        if e >= 4 {
            break;
        }
        e = e + 1;
    }
    return s == 8 && j == 3 && w == 3.0 && e == 4;
}

fn BRDF(L: vec3<f32>, V: vec3<f32>, N: vec3<f32>, X: vec3<f32>, Y: vec3<f32>) -> f32 {
    let ok = integers() && floats() && vectors_and_matrices() && abstracts() && structures() && loops();
    return select(0.0, 1.0 / PI, ok);
}
