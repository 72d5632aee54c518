// Textures as a shader samples them (docs/brdf-code.md#textures), included by glsl_prelude.hpp:
// a 2D texture of one mip level bound by --texture, sampled as a GPU's bilinear filter with
// clamp-to-edge addressing samples it, returning four channels (those the file lacks as a GPU
// fills them: 0, 0, 0, 1). GLSL's texture, texture2D and textureLod are functions of this
// namespace, which a call on a texture finds by argument-dependent lookup; HLSL's Sample and
// SampleLevel are the texture's members. The level of detail is ignored: one level is bound.
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <memory>
#include <vector>

namespace normzoo_glsl {

// HLSL's SamplerState: its filter and address modes are the texture's own here (bilinear,
// clamp to edge), whatever the engine's sampler object sets.
struct sampler_state {};

// Texel (row j, column i) holds rgba[4 * (j * width + i) + c]; row 0 is v = 0 (the rows as the
// layout puts them, brdf_textures.hpp), column 0 u = 0. A sample is N channels: 4, or those of
// HLSL's Texture2D<T> (a number for Texture2D<float>).
template <class real, bool Hlsl, int N>
struct texture2d {
    int width = 0, height = 0;
    // shared: a texture passed to a function (vec4 f(sampler2D t)) is a handle, as on a GPU
    std::shared_ptr<const std::vector<real>> rgba;

    using vec4_type = std::conditional_t<N == 1, real, std::conditional_t<Hlsl, hlsl_vec<N, real>, glm::vec<N, real>>>;

    // w x h texels of four channels, rounded once to real as a GPU holds a float texture's.
    void bind(int w, int h, const double* texels) {
        width = w, height = h;
        rgba = std::make_shared<const std::vector<real>>(texels, texels + std::size_t(4) * std::size_t(w) * std::size_t(h));
    }

    // Linear filtering as the Vulkan specification's "Texel Filtering" gives it (Direct3D's is
    // the same, texels at the centres of their cells): i0 = floor(u W - 1/2), i1 = i0 + 1, the
    // weight of i1 frac(u W - 1/2), each index clamped to the edge (clamp-to-edge addressing).
    // The weights are exact here; hardware rounds them to its sub-texel precision (8 bits in
    // Direct3D 11), which docs/brdf-code.md#textures leaves out.
    template <class U>
    vec4_type sample(const U& uv) const {
        const real u = real(uv[0]), v = real(uv[1]);
        if (!(u == u) || !(v == v) || !rgba) return vec4_type(real(NAN));  // flagged as non-finite
        const auto axis = [](real s, int n, int& i0, int& i1, real& w) {
            real x = s * real(n) - real(0.5);
            x = x < real(-1) ? real(-1) : x > real(n) ? real(n) : x;  // clamped before floor: an infinite coordinate
            const real f = std::floor(x);
            w = x - f;
            const int i = int(f);
            i0 = i < 0 ? 0 : i > n - 1 ? n - 1 : i;
            i1 = i + 1 < 0 ? 0 : i + 1 > n - 1 ? n - 1 : i + 1;
        };
        int i0, i1, j0, j1;
        real wu, wv;
        axis(u, width, i0, i1, wu);
        axis(v, height, j0, j1, wv);
        real r[4];
        for (int c = 0; c < N; ++c) {
            const real a = at(j0, i0, c) * (real(1) - wu) + at(j0, i1, c) * wu;
            const real b = at(j1, i0, c) * (real(1) - wu) + at(j1, i1, c) * wu;
            r[c] = a * (real(1) - wv) + b * wv;
        }
        if constexpr (N == 1) return r[0];
        else if constexpr (N == 2) return vec4_type(r[0], r[1]);
        else if constexpr (N == 3) return vec4_type(r[0], r[1], r[2]);
        else return vec4_type(r[0], r[1], r[2], r[3]);
    }
    real at(int j, int i, int c) const { return (*rgba)[std::size_t(4 * (j * width + i) + c)]; }

    // HLSL: t.Sample(s, uv), t.SampleLevel(s, uv, lod)
    template <class U>
    vec4_type Sample(const sampler_state&, const U& uv) const { return sample(uv); }
    template <class U, class L>
    vec4_type SampleLevel(const sampler_state&, const U& uv, const L&) const { return sample(uv); }
};

// GLSL: texture(t, uv), texture2D(t, uv) (before GLSL 1.30), textureLod(t, uv, lod); a bias
// argument is taken and ignored like the level.
template <class real, bool H, int N, class U>
auto texture(const texture2d<real, H, N>& t, const U& uv) { return t.sample(uv); }
template <class real, bool H, int N, class U, class B>
auto texture(const texture2d<real, H, N>& t, const U& uv, const B&) { return t.sample(uv); }
template <class real, bool H, int N, class U>
auto texture2D(const texture2d<real, H, N>& t, const U& uv) { return t.sample(uv); }
template <class real, bool H, int N, class U, class B>
auto texture2D(const texture2d<real, H, N>& t, const U& uv, const B&) { return t.sample(uv); }
template <class real, bool H, int N, class U, class L>
auto textureLod(const texture2d<real, H, N>& t, const U& uv, const L&) { return t.sample(uv); }
template <class real, bool H, int N, class U, class L>
auto texture2DLod(const texture2d<real, H, N>& t, const U& uv, const L&) { return t.sample(uv); }

}  // namespace normzoo_glsl
