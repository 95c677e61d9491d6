// How the renderer draws a bake's VPLs: the groups, the per-cell lightcut (κ, the grid, the
// light bound) and their shadow cubes. Apart from vpl_pass.h so that the renderer's settings
// need neither the pass nor GL.
#pragma once

#include <cstddef>
#include <cstdint>

#include "vpl_runtime/vpl_groups.h"

namespace bounce {

struct VplShadowSettings {
  bool enabled = true;  // false: vplVisibility returns 1 (no maps rendered)
  int resolution = 64;  // texels per face side
  // Map origin above the VPL's surface along its normal, metres; ≤ 0: 1e-3 × the scene box's
  // diagonal.
  float originOffset = 0.0f;
  // Cubes per VPL group (a power of two ≤ kVplShadowCubesPerGroup; vplShadowCubes): 1 puts one
  // cube at each group's member nearest its centroid, a quarter of the redraw cost and up to 8%
  // darker on the dynamic sphere (docs/vpl.md "Visibility").
  int cubesPerGroup = 4;
};

struct VplRenderSettings {
  std::size_t groups = kMaxVplGroups;  // K, coarse groups (≤ kMaxVplGroups)
  // false: every VPL at every fragment (one cell, all near). Also what culling falls back to
  // when the cut would keep more than half the VPLs (few VPLs: nothing to gain).
  bool culling = true;
  float kappa = 4.0f;  // a tree node is far beyond κ node radii (vpl_groups.h)
  int maxCellsPerAxis = 16;
  // Lights a fragment evaluates at most (VplLightCutSettings::maxLights; 0: no bound), whatever
  // the VPL count: the dynamic objects' cost per pixel.
  uint32_t maxLights = VplLightCutSettings{}.maxLights;
  // Visibility: one shadow cube per group (render/vpl_shadow_maps.h); shadows.enabled = false
  // draws every VPL unoccluded.
  VplShadowSettings shadows;
  // true: the dynamic instances' pixels read the VPLs' light gathered at their vertices
  // (render/vpl_vertex_light.h) in the full and indirect modes; false: every pixel gathers them.
  bool perVertex = true;
};

}  // namespace bounce
