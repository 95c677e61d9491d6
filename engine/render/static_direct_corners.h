// The static lights' direct light at the triangle corners of the probe-lit instances (static
// objects too small or thin for the lightmap), computed once when a bake is attached: what the
// lightmap's texels are to a lightmapped surface (static_direct_texels.h), the corners are to
// these, whose baked visibility is per corner already (bake_folder/irradiance_probes.h,
// ProbeVisibility). Per corner k and linear-RGB channel c, the irradiance vector (W/m²)
//   F_c(k) = Σ_l V_l(k) · F_l,c(x_k, n_k),
// V_l(k) the corner's visible fraction of static light l (as the shader reads it), F_l,c its
// irradiance vector clipped to n_k's horizon (static_direct_texels.h), x_k and n_k the corner's
// vertex in world space and its unit shading normal. A pixel reads
// F = Σ_k b_k F(k) with its barycentric weights b_k and E_c = max(n·F_c, 0): the light a
// triangle's corners receive, interpolated over it, as Gouraud shading is. That is off where E
// curves within the triangle, which grows as (h/d)², h its longest edge and d its distance to the
// light: a triangle whose h exceeds kMaxEdgeOverDistance · d (d to the nearest precomputed light:
// an area light's bounding sphere, a point or spot light's position) is left to the per-pixel
// evaluation. At ½, on the Conference Room's
// default view (docs/renderer_measured.md), the chairs' frames and their 45 cm pads 2 m from the
// panels are read from their corners and the whiteboard's two triangles are not; the direct frame
// is 1.58 % off the per-pixel one (mean |a − b|/(|b| + 0.01), the texels included), against
// 1.55 % at 0.15 (pads per pixel too) and a visible error pattern on the whiteboard at ∞.
// GL-free.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/irradiance_probes.h"
#include "render/static_direct_texels.h"
#include "scene/area_lights.h"
#include "scene/scene.h"

namespace bounce {

inline constexpr float kMaxEdgeOverDistance = 0.5f;

// F_c per corner of `probes.visibility` (3 entries per corner, F_r, F_g, F_b in xyz, at 3k + c)
// of `lights` (static_direct_texels.h); w = 1 on every entry of a triangle read from its corners,
// 0 (and F = 0) on one left per pixel and on corners of no grid (none in a valid bake).
// Instances are at their Scene transforms.
std::vector<glm::vec4> staticDirectCorners(const Scene& scene, const IrradianceProbes& probes,
                                           const PrecomputedLights& lights);

}  // namespace bounce
