// The GLSL functions the translation adds, each computing what WGSL defines where GLSL 1.20 has
// no such function or defines it otherwise (https://www.w3.org/TR/WGSL/):
//   idiv, imod    integer / and % (#arithmetic-expr): e1 / 0 is e1 and e1 % 0 is 0, as is the
//                 most negative value divided by -1; otherwise truncating
//   fmod          the float % : e1 - e2 * trunc(e1 / e2) (GLSL's mod floors instead)
//   trunc, round  #trunc-builtin, #round-builtin (round: halfway cases to even)
//   f2i, f2u      a float converted to an integer (#floating-point-conversion): truncated and
//                 clamped to the values the f32 can hold, NaN as 0 (u32 within the subset's
//                 range, below 2^31)
//   iabs, imin, imax, iclamp, isign   the integer forms of the built-ins
//   determinant   #determinant-builtin, for mat2x2, mat3x3 and mat4x4
#include <map>

#include "wgsl_checker.hpp"

namespace verify::wgsl {

namespace {

// Each text is one line; P stands for the helper's prefix (the translation's prefix and 'h').
const std::map<std::string, std::string>& texts() {
    static const std::map<std::string, std::string> t{
        {"idiv", "int Pidiv(int a, int b) { return (b == 0 || (a == -2147483647 - 1 && b == -1)) ? a : a / b; }"},
        {"imod", "int Pimod(int a, int b) { return (b == 0 || b == -1) ? 0 : a - b * (a / b); }"},
        {"trunc", "float Ptrunc(float x) { return x < 0.0 ? ceil(x) : floor(x); } "
                  "vec2 Ptrunc(vec2 x) { return vec2(Ptrunc(x.x), Ptrunc(x.y)); } "
                  "vec3 Ptrunc(vec3 x) { return vec3(Ptrunc(x.x), Ptrunc(x.y), Ptrunc(x.z)); } "
                  "vec4 Ptrunc(vec4 x) { return vec4(Ptrunc(x.x), Ptrunc(x.y), Ptrunc(x.z), Ptrunc(x.w)); }"},
        {"fmod", "float Pfmod(float a, float b) { return a - b * Ptrunc(a / b); } "
                 "vec2 Pfmod(vec2 a, vec2 b) { return a - b * Ptrunc(a / b); } "
                 "vec3 Pfmod(vec3 a, vec3 b) { return a - b * Ptrunc(a / b); } "
                 "vec4 Pfmod(vec4 a, vec4 b) { return a - b * Ptrunc(a / b); }"},
        {"round", "float Pround(float x) { float f = floor(x); float d = x - f; "
                  "return d > 0.5 ? f + 1.0 : (d < 0.5 ? f : (floor(f * 0.5) * 2.0 == f ? f : f + 1.0)); } "
                  "vec2 Pround(vec2 x) { return vec2(Pround(x.x), Pround(x.y)); } "
                  "vec3 Pround(vec3 x) { return vec3(Pround(x.x), Pround(x.y), Pround(x.z)); } "
                  "vec4 Pround(vec4 x) { return vec4(Pround(x.x), Pround(x.y), Pround(x.z), Pround(x.w)); }"},
        {"f2i", "int Pf2i(float x) { return x != x ? 0 : int(clamp(x, -2147483648.0, 2147483520.0)); }"},
        {"f2u", "int Pf2u(float x) { return x != x ? 0 : int(clamp(x, 0.0, 2147483520.0)); }"},
        {"iabs", "int Piabs(int a) { return (a < 0 && a != -2147483647 - 1) ? -a : a; }"},
        {"imin", "int Pimin(int a, int b) { return a < b ? a : b; }"},
        {"imax", "int Pimax(int a, int b) { return a < b ? b : a; }"},
        {"iclamp", "int Piclamp(int e, int lo, int hi) { return Pimin(Pimax(e, lo), hi); }"},
        {"isign", "int Pisign(int a) { return a > 0 ? 1 : (a < 0 ? -1 : 0); }"},
        {"determinant",
         "float Pdeterminant(mat2 m) { return m[0][0] * m[1][1] - m[1][0] * m[0][1]; } "
         "float Pdeterminant(mat3 m) { return m[0][0] * (m[1][1] * m[2][2] - m[2][1] * m[1][2]) "
         "- m[1][0] * (m[0][1] * m[2][2] - m[2][1] * m[0][2]) + m[2][0] * (m[0][1] * m[1][2] - m[1][1] * m[0][2]); } "
         "float Pdeterminant(mat4 m) { float s = 0.0; for (int c = 0; c < 4; ++c) { "
         "int a = c == 0 ? 1 : 0; int b = c <= 1 ? 2 : 1; int d = c <= 2 ? 3 : 2; "
         "float minor = m[a][1] * (m[b][2] * m[d][3] - m[d][2] * m[b][3]) - m[b][1] * (m[a][2] * m[d][3] - m[d][2] * m[a][3]) "
         "+ m[d][1] * (m[a][2] * m[b][3] - m[b][2] * m[a][3]); "
         "s += (c == 1 || c == 3 ? -1.0 : 1.0) * m[c][0] * minor; } return s; }"}};
    return t;
}

}  // namespace

std::string helper_text(const std::string& helper, const std::string& p) {
    std::string t = texts().at(helper);
    for (std::size_t at = t.find('P'); at != std::string::npos; at = t.find('P', at)) {
        // only the P that begins a helper's name: after a space or a '(' and before a lower-case letter
        const bool name = (at == 0 || t[at - 1] == ' ' || t[at - 1] == '(') && at + 1 < t.size() && t[at + 1] >= 'a' && t[at + 1] <= 'z';
        if (!name) {
            ++at;
            continue;
        }
        t.replace(at, 1, p + "h");
        at += p.size() + 1;
    }
    return t;
}

std::vector<std::string> helper_dependencies(const std::string& helper) {
    if (helper == "fmod") return {"trunc"};
    if (helper == "iclamp") return {"imin", "imax"};
    return {};
}

}  // namespace verify::wgsl
