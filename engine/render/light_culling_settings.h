// What light culling is set to (the irradiance floor, the cluster grid's size) and what its
// last frame's lists held: apart from light_culling.h so that the renderer's settings need
// neither the culling nor GL.
#pragma once

#include <cstddef>

#include "render/cluster_grid.h"
#include "render/light_cutoff.h"

namespace bounce {

struct LightCullingSettings {
  bool enabled = true;
  // E_floor, W/m²: below it a light is left out (light_cutoff.h); the default is EV 0's.
  float irradianceFloor = irradianceFloorForExposure(0.0f);
  ClusterGridSize grid;
};

// What the last frame's lists held.
struct LightGridStats {
  int clusters = 0;
  std::size_t punctualEntries = 0, areaEntries = 0;  // Σ over clusters of their list lengths
  std::size_t maxPunctual = 0, maxArea = 0;          // the longest lists
};

}  // namespace bounce
