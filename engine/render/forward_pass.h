// The lit forward pass: every instance with its own model matrix, shaded by shaders/forward.frag
// (emission + the punctual lights with their shadow maps + the area lights of each fragment's
// view cluster (light_culling.h), the lightmap, the irradiance probes or the VPLs for
// indirect light) into a linear float target:
// outgoing radiance, W/(sr·m²).
#pragma once

#include <filesystem>

#include <glm/glm.hpp>

#include "gl/shader.h"
#include "render/render_mode.h"

namespace bounce {

class GpuScene;
class LightCulling;
class LightTable;
class LightmapPass;
class ProbePass;
class ShadowPass;
class VplPass;
class VplVertexLight;
namespace gl {
class RenderTarget;
}  // namespace gl

class ForwardPass {
 public:
  explicit ForwardPass(const std::filesystem::path& shaderDir);

  // Clears `target` to black and draws the scene seen through `viewProjection`.
  void draw(const GpuScene& scene, const LightTable& lights, const LightCulling& culling,
            const ShadowPass& shadows, const LightmapPass& lightmap, const ProbePass& probes,
            const VplPass& vpls, const VplVertexLight& vplVertexLight, RenderMode mode,
            const glm::mat4& viewProjection, gl::RenderTarget& target);

 private:
  gl::Program program_;
};

}  // namespace bounce
