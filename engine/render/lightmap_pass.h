// The lightmap stage of the lit pass (shaders/lightmap.glsl): uploads a bake's irradiance
// lightmap (RGB32F, W/m², bilinear, clamped at the borders) and its chart image, gives every
// static instance with an atlas region its per-corner atlas UVs (vertex attribute 3), and tells
// the forward shader, per frame, the mode and, per draw, whether the instance is lightmapped.
// Without a bake it binds 1×1 black stand-ins and every draw is unlit by the lightmap (the
// samplers still need textures of their type on their units). GL calls only through engine/gl.
#pragma once

#include <optional>
#include <vector>

#include "bake/bake_folder.h"
#include "gl/shader.h"
#include "gl/texture.h"
#include "render/gpu_scene.h"
#include "render/render_mode.h"

namespace bounce {

class LightmapPass {
 public:
  LightmapPass();

  // Uploads `bake` (already checked against the scene by readBake) and sets the lightmap UVs
  // of its regions' instances in `scene`. Dynamic instances never get a region.
  void attach(const Bake& bake, GpuScene& scene);
  bool attached() const { return attached_; }

  // Per frame: mode, textures, atlas size.
  void bind(gl::Program& program, RenderMode mode) const;
  // Per draw: whether instance `index` (into GpuScene::instances) reads the lightmap.
  void setInstance(gl::Program& program, std::size_t index) const;

 private:
  std::optional<gl::Texture2D> irradiance_;
  std::optional<gl::Texture2D> charts_;
  glm::vec2 size_{1.0f};
  std::vector<uint8_t> lightmapped_;  // per instance
  bool attached_ = false;
};

}  // namespace bounce
