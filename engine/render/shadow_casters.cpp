#include "render/shadow_casters.h"

#include "render/gpu_scene.h"

#include "gl/draw_state.h"

namespace bounce {

int drawShadowCasters(const GpuScene& scene, const ShadowView& view, glm::vec3 lightPosition,
                      gl::Program& depthProgram) {
  gl::clearDepth();
  gl::setDepthTest(true);
  gl::setBackFaceCulling(false);
  depthProgram.set("uViewProjection", view.viewProjection);
  depthProgram.set("uLightPosition", lightPosition);
  depthProgram.set("uFar", view.far);
  const Frustum frustum(view.viewProjection);
  int drawn = 0;
  for (const GpuInstance& instance : scene.instances()) {
    if (!frustum.overlaps(instance.worldBox)) continue;
    scene.draw(instance, depthProgram);
    ++drawn;
  }
  return drawn;
}

}  // namespace bounce
