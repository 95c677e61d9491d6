// The forward renderer: a short sequence of passes per frame,
//   1. shadow maps   (shadow_pass.h: spot and point lights' depth maps),
//   2. lit pass      (forward_pass.h: outgoing radiance, W/(sr·m²), of the visible Lambertian
//                     surface into a linear float target,
//                       L_o = ρ/π · (Σ_punctual V_i·E_i + Σ_emitters E_j) + L_e,
//                     equations in shaders/lights.glsl, shaders/area_light.glsl, docs/renderer.md),
//   3. tone mapping  (tonemap_pass.h, by the viewer; files are tone-mapped by image_io),
// over a GpuScene (gpu_scene.h) uploaded once: instances keep their own model matrices. Later
// passes (lightmap, VPLs, debug views) slot in by RenderMode. Uses the GL layer's API only;
// needs a current context for its whole life.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "bake/bake_folder.h"
#include "gl/render_target.h"
#include "image/image.h"
#include "render/render_mode.h"
#include "render/shadow_settings.h"
#include "scene/scene.h"

namespace bounce {

struct RendererSettings {
  RenderMode mode = RenderMode::Direct;
  ShadowSettings shadows;
};

class ForwardRenderer {
 public:
  // Uploads the scene (per-mesh buffers, per-instance matrices, textures, the emitter table,
  // the punctual lights, shadow maps) and builds the shaders found in `shaderDir`. `scene` must
  // outlive the renderer.
  // With `bake` (read by readBake for this scene), as setBake; a mode that needs a bake
  // (renderModeNeedsBake) without one throws std::invalid_argument.
  ForwardRenderer(const Scene& scene, const std::filesystem::path& shaderDir,
                  const RendererSettings& settings = {}, const Bake* bake = nullptr);
  ~ForwardRenderer();
  ForwardRenderer(const ForwardRenderer&) = delete;
  ForwardRenderer& operator=(const ForwardRenderer&) = delete;

  // Draws radiance seen by `camera` into `target` (cleared to black first). Aspect = target's.
  void render(const Camera& camera, gl::RenderTarget& target);
  // Renders offscreen at width x height and reads the radiance back, rows top to bottom.
  Image renderImage(const Camera& camera, int width, int height);

  // Moves instance `index` (object → world) without re-uploading its mesh.
  void setInstanceTransform(std::size_t index, const glm::mat4& transform);
  // Per-corner lightmap UVs of instance `index` (vertex attribute 3, gl/vertex_attributes.h);
  // empty removes them.
  void setLightmapUv(std::size_t index, std::span<const glm::vec2> cornerUv);

  // Adds the baked light of `bake` (read by readBake for this scene): uploads the lightmap and
  // gives its static instances their atlas UVs. Modes other than Direct need one.
  void setBake(const Bake& bake);
  bool hasBake() const;
  // Switches what the lit pass draws; throws std::invalid_argument for a mode that needs a bake
  // when none is set.
  void setMode(RenderMode mode);

  const RendererSettings& settings() const { return settings_; }
  // Set-ups that make no sense or that the renderer does not support, one sentence each.
  const std::vector<std::string>& warnings() const { return warnings_; }
  std::size_t emitterTriangleCount() const;

 private:
  struct Passes;
  RendererSettings settings_;
  std::vector<std::string> warnings_;
  std::unique_ptr<Passes> passes_;
};

}  // namespace bounce
