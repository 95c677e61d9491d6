// Each light's reach under the cut-off rule (render/light_cutoff.h) as light_grid.h takes it.
// GL-free.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "render/light_grid.h"
#include "scene/area_lights.h"
#include "scene/scene.h"

namespace bounce {

// A punctual light drawn with `power` (W/sr, or W/m² for directional; its table power, 0 when
// its direct light is baked): a sphere of radius sqrt(max channel / floor), a spot's also cut
// to its outer cone (spotFalloff is 0 beyond it); directional: everywhere; no power: nowhere.
LightReach punctualReach(const Light& light, glm::vec3 power, float floor);

// Every area light of `set`: the box around its triangles, grown by sqrt(Σ_t L_t·A_t / floor),
// L_t a triangle's brightest channel of radiance and A_t its area. Why that is enough: E at p is
// Σ_t L_t · (projected solid angle of t) ≤ Σ_t L_t · Ω_t, and Ω_t = ∫ cos/r² dA ≤ A_t / d² when
// every point of t is at least d from p.
std::vector<LightReach> areaReaches(const AreaLightSet& set, float floor);

}  // namespace bounce
