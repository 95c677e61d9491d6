// The light of a VPL set at a point, GL-free: the estimate the renderer's VPL term is checked
// against (bake_folder/vpl.h, docs/vpl.md). Irradiance at x with unit normal n:
//   E(x) = Σ_i Φ_i/π · cosθ_i · cosθ_x / max(d_i², r²) · V(x, y_i)        [W/m²]
// with r the clamp distance: the geometry term 1/d² is capped at 1/r² near a VPL, which
// removes the spikes (d → 0 at concave corners) at the cost of energy that is reported.
// The clamp distance is tied to the VPL density: r = sqrt(A / (π·N)), the radius of the disc
// each of N VPLs covers when spread evenly over the scene's surface area A, so a point never
// counts one VPL more than a disc of its own neighbourhood would.
#pragma once

#include <span>

#include <glm/glm.hpp>

#include "bake_folder/vpl.h"
#include "bake_folder/vpl_clamp.h"  // vplClampDistance, surfaceArea (moved to engine/bake_folder)
#include "ray/ray_kernel.h"
#include "scene/world_geometry.h"

namespace bounce {

// kernel: visibility between x and each VPL (nullptr: every VPL visible). r = 0: no clamp.
VplIrradiance gatherVplIrradiance(std::span<const Vpl> vpls, glm::vec3 position, glm::vec3 normal,
                                  const RayKernel* kernel, float clampDistance);

}  // namespace bounce
