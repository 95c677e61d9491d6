// Draws the casters of one shadow map into the bound depth target: every instance whose world
// box overlaps the map's frustum, both faces (a wall casts whichever side the light sees), its
// distance to the light written as depth (shaders/shadow_depth.frag).
#pragma once

#include "gl/shader.h"
#include "render/shadow_map_geometry.h"

namespace bounce {

class GpuScene;

// Returns the number of instances drawn.
int drawShadowCasters(const GpuScene& scene, const ShadowView& view, glm::vec3 lightPosition,
                      gl::Program& depthProgram);

}  // namespace bounce
