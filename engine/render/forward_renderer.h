// The forward renderer, first cut: one pass per frame into a linear float target, giving each
// pixel the outgoing radiance (W/(sr·m²)) of the visible Lambertian surface under direct,
// unshadowed light:
//   L_o = ρ/π · (Σ_punctual E_i + Σ_emitters E_j) + L_e
// (equations in shaders/lights.glsl, shaders/area_light.glsl, docs/renderer.md). Uses the GL
// layer's API only; needs a current context for its whole life.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "gl/render_target.h"
#include "image/image.h"
#include "scene/scene.h"

namespace bounce {

class ForwardRenderer {
 public:
  // Uploads the scene (world-space triangles grouped by material, textures, the emitter table,
  // the punctual lights) and builds the shaders found in `shaderDir`.
  ForwardRenderer(const Scene& scene, const std::filesystem::path& shaderDir);
  ~ForwardRenderer();
  ForwardRenderer(const ForwardRenderer&) = delete;
  ForwardRenderer& operator=(const ForwardRenderer&) = delete;

  // Draws radiance seen by `camera` into `target` (cleared to black first). Aspect = target's.
  void render(const Camera& camera, gl::RenderTarget& target);
  // Renders offscreen at width x height and reads the radiance back, rows top to bottom.
  Image renderImage(const Camera& camera, int width, int height);

  // Set-ups that make no sense or that the first cut does not support, one sentence each.
  const std::vector<std::string>& warnings() const { return warnings_; }
  std::size_t emitterTriangleCount() const;

 private:
  struct Gpu;
  std::unique_ptr<Gpu> gpu_;
  std::vector<std::string> warnings_;
};

}  // namespace bounce
