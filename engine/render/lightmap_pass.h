// The lightmap stage of the lit pass (shaders/lightmap.glsl): uploads a bake's irradiance
// lightmap (RGB32F, W/m², bilinear, clamped at the borders), its chart image and, when the bake
// has it, the static area lights' visibility per texel (shaders/baked_visibility.glsl), gives every
// static instance with an atlas region its per-corner atlas UVs (vertex attribute 3), and tells
// the forward shader, per frame, the mode and, per draw, whether the instance is lightmapped.
// Without a bake it binds 1×1 black stand-ins and every draw is unlit by the lightmap (the
// samplers still need textures of their type on their units). GL calls only through engine/gl.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gl/shader.h"
#include "gl/texture.h"
#include "gl/texture_array.h"
#include "render/gpu_scene.h"
#include "render/render_mode.h"

namespace bounce {

struct Bake;  // bake_folder/bake_folder.h

class LightmapPass {
 public:
  LightmapPass();

  // Uploads `bake` (already checked against the scene by readBake) and sets the lightmap UVs
  // of its regions' instances in `scene`. Dynamic instances never get a region.
  void attach(const Bake& bake, GpuScene& scene);
  // Whether the static lights' direct light can be read from texels: the bake has visibility
  // and the driver unit kStaticDirect.
  bool canReadStaticDirect() const;
  // Uploads the static lights' irradiance vectors per texel (static_direct_texels.h: 3 layers of
  // the atlas's size), which lightmapped draws read instead of evaluating those lights; empty:
  // none (every light per pixel).
  void setStaticDirect(std::span<const glm::vec3> texels);
  bool hasStaticDirectTexels() const { return staticDirect_.has_value(); }
  bool attached() const { return attached_; }
  bool hasErrorMap() const { return errorColours_.has_value(); }
  // Whether static surfaces read the static area lights' visibility from the bake; when the
  // bake has some but this is false, `why` says why not (for a renderer warning).
  bool hasBakedVisibility() const { return visibility_.has_value(); }
  // The instances without an atlas region that read the same lights' visibility per triangle
  // corner (ProbePass::cornerVisibility), by instance index: they count as reading the bake's
  // visibility below.
  void setCornerVisibility(std::vector<uint8_t> perInstance) {
    cornerVisibility_ = std::move(perInstance);
  }
  // Whether every instance of `scene` reads the baked visibility (static, with an atlas region
  // or corner visibility): then no surface needs the area lights' all-caster cubes.
  bool visibilityCoversEveryInstance(const GpuScene& scene) const;
  const std::string& visibilityRefusal() const { return visibilityRefusal_; }
  // Whether every static instance of `scene` reads the bake's visibility (false without one).
  bool visibilityOnEveryStaticInstance(const GpuScene& scene) const;
  // The static area lights [0, n) whose visibility every static instance of `scene` reads from
  // the bake (0 when some static instance has neither an atlas region nor corner visibility, or
  // without visibility).
  std::size_t bakedVisibilityLights(const GpuScene& scene) const;
  // The visibility's area lights (its first indices) and the punctual lights that follow them;
  // 0 and 0 without visibility.
  int bakedLightCount() const { return bakedLights_; }
  std::size_t bakedPunctualCount() const { return bakedPunctual_; }

  // Per frame: mode, textures, atlas size.
  void bind(gl::Program& program, RenderMode mode) const;
  // Per draw: whether instance `index` (into GpuScene::instances) reads the lightmap.
  void setInstance(gl::Program& program, std::size_t index) const;
  // Whether instance `index` has an atlas region in the attached bake.
  bool lightmapped(std::size_t index) const {
    return index < lightmapped_.size() && lightmapped_[index] != 0;
  }

 private:
  void attachVisibility(const Bake& bake);
  // Instance `index` reads the visibility: from the table (a region) or per corner.
  bool readsVisibility(std::size_t index) const;

  std::optional<gl::Texture2D> irradiance_;
  std::optional<gl::Texture2D> charts_;
  std::optional<gl::Texture2D>
      errorColours_;  // bake_folder/texel_error.h per texel, with error.exr
  std::optional<gl::Texture2D> validityColours_;  // the same, sampled / filled / padding
  std::optional<gl::Texture2D> visibility_;  // bake_folder/light_visibility.h as 2·W × H RGBA32F
  // static_direct_texels.h: F_r, F_g, F_b as 3 layers of W × H RGB32F, W/m²
  std::optional<gl::TextureArray2D> staticDirect_;
  int bakedLights_ = 0;            // static area lights the visibility names
  std::size_t bakedPunctual_ = 0;  // punctual lights it names after them
  glm::vec2 size_{1.0f};
  float targetTexelsPerMetre_ = 1.0f;      // 1 / the layout's texel size (the texel-density view)
  std::vector<uint8_t> lightmapped_;       // per instance
  std::vector<uint8_t> cornerVisibility_;  // per instance: visibility per corner (probe-lit)
  bool attached_ = false;
  std::string visibilityRefusal_;
};

}  // namespace bounce
