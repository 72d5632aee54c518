// Constants and helpers the engine's shaders share (an include guard, as engines write them).
#ifndef ENGINE_COMMON_MATH_GLSL
#define ENGINE_COMMON_MATH_GLSL

#define PI 3.14159265359

// The largest finite binary16 value: where a GPU runs mediump as half precision (mobile
// targets), a value that may exceed it is clamped before it overflows to Inf.
#define MEDIUMP_FLT_MAX 65504.0
#if defined(TARGET_MOBILE)
#define saturateMediump(x) min(x, MEDIUMP_FLT_MAX)
#else
#define saturateMediump(x) x
#endif

float sq(float x) {
    return x * x;
}

#endif
