// KHR_materials_transmission, thin-walled (docs/materials.md, "KHR_materials_transmission"):
// the dielectric's base becomes mix(diffuse_brdf(baseColor), specular_btdf(alpha) baseColor,
// transmission) (KhronosGroup/glTF, extensions/2.0/Khronos/KHR_materials_transmission/README.md,
// "Transmission BTDF"), with specular_btdf "the same specular lobe ... sampled along the line of
// sight through the surface": for L below the surface, specular_brdf at L's mirror through the
// tangent plane, L' = L - 2 (N.L) N, whose half vector with V is the extension's H_T =
// normalize(V - 2 (N.L) N + L); the Fresnel weight of the base read at V.H_T. So the transmitted
// albedo is an integral over the upper hemisphere in L' like the reflected one, and reflection
// and transmission together cover the whole sphere of L: the material's albedo is R + T.
#pragma once
#include "../geometry.hpp"

namespace normzoo::material {

// L's mirror through the tangent plane: the direction specular_btdf reads specular_brdf at.
inline vec3<double> through_surface(const vec3<double>& l) { return {l.x(), l.y(), -l.z()}; }

}  // namespace normzoo::material
