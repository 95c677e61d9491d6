// The exact unshadowed irradiance an area light gives a Lambertian receiver, on the CPU: the
// twin of shaders/area_light.glsl (Lambert's contour integral over each emissive triangle
// clipped to the receiver's upper hemisphere n·(x − p) ≥ 0),
//   E = L · n·Φ,   Φ = ½ · Σ_i γ_i · (q_i × q_{i+1}) / |q_i × q_{i+1}|,   q_i = v_i − p,
// γ_i = atan2(|q_i × q_{i+1}|, q_i·q_{i+1}), the loop's winding taken so that n·Φ ≥ 0. Φ (sr)
// is the clipped polygon's vector form factor times π (Arvo's irradiance vector per unit
// radiance): for another normal n' whose horizon cuts none of the clipped polygon, n'·Φ is its
// irradiance per radiance too. A triangle gives light only to the side its front face
// (counter-clockwise) looks at, or both sides when double-sided; a receiver on its plane sees it
// edge-on and gets nothing. Metres, W/(sr·m²) in, W/m² out, per linear-RGB channel.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "scene/area_lights.h"

namespace bounce {

// Φ of one emissive triangle at p (metres), clipped to the horizon of unit normal n (sr, n·Φ ≥ 0;
// 0 where it gives p nothing).
glm::vec3 emitterTriangleVector(const EmitterTriangle& triangle, glm::vec3 p, glm::vec3 n);

// E = L · n·Φ of one emissive triangle at p on a receiver of unit normal n, unshadowed.
glm::vec3 emitterTriangleIrradiance(const EmitterTriangle& triangle, glm::vec3 p, glm::vec3 n);

// E of light `light` of `set` (the sum over its triangles) at p, unshadowed.
glm::vec3 areaLightIrradiance(const AreaLightSet& set, std::size_t light, glm::vec3 p, glm::vec3 n);

// The irradiance vectors F_c = Σ L_c · Φ of light `light`'s triangles at p (W/m², one vector per
// linear-RGB channel c), clipped to n's horizon: E_c = n·F_c, and n'·F_c for nearby normals.
std::array<glm::vec3, 3> areaLightIrradianceVectors(const AreaLightSet& set, std::size_t light,
                                                    glm::vec3 p, glm::vec3 n);

// The same for a punctual light (shaders/lights.glsl's E without its visibility): F_c = P_c·w·l,
// l the unit direction to the light, w = spotFalloff/r² (point: falloff 1) or 1 (directional,
// P = E⊥), P the intensity (W/sr) or irradiance (W/m²); 0 when the light is below n's horizon.
std::array<glm::vec3, 3> punctualIrradianceVectors(const Light& light, glm::vec3 p, glm::vec3 n);

}  // namespace bounce
