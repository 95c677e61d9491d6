// Visibility of virtual point lights (issue 8): one low-resolution depth cube per group
// representative (engine/bake/vpl.h), so the VPL term can tell whether a group's light reaches
// a point. shaders/vpl_shadows.glsl reads them: vplVisibility(group, p, ng), 1 = the
// representative sees p, 0 = occluded, bilinear-filtered in between.
//
// Layout: GL 3.3 core has no cube-map arrays, so all cubes share one depth32F
// GL_TEXTURE_2D_ARRAY, layer 6·group + face, faces in GL's cube order (+X, −X, +Y, −Y, +Z, −Z)
// with the frames of cubeFaceShadowView; the shader picks the face by the major axis. Depth
// is distance / far, one `far` for every group, so the per-group uniform is the map origin.
//
// Bias: a VPL sits on its surface, so its map origin is lifted by `originOffset` along its
// normal, and the map holds only what lies in front of the VPL's tangent plane through that
// origin (shaders/vpl_shadow_depth.frag: nothing behind it can occlude a receiver the VPL
// lights), so the VPL's own surface never enters its map; receivers use the point maps' normal
// offset and slope-scaled depth bias (shadow_common.glsl). docs/vpl.md "Visibility".
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "bake/vpl.h"
#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/gpu_scene.h"
#include "render/shadow_settings.h"

namespace bounce {

struct VplShadowSettings {
  bool enabled = true;  // false: vplVisibility returns 1 (no maps rendered)
  int resolution = 64;  // texels per face side
  // Map origin above the VPL's surface along its normal, metres; ≤ 0: 1e-3 × the scene box's
  // diagonal.
  float originOffset = 0.0f;
};

// Must match MAX_VPL_SHADOW_GROUPS in shaders/vpl_shadows.glsl.
constexpr int kMaxVplShadowGroups = 64;

// Bit f set: cube face f (GL order) reaches the hemisphere dot(ω, normal) > 0 and is rendered.
// The face opposite an axis-aligned normal is the one skipped.
uint32_t vplShadowFaces(glm::vec3 normal);

class VplShadowMaps {
 public:
  // Needs a current GL context; compiles the depth program from `shaderDir`.
  VplShadowMaps(const VplShadowSettings& settings, const std::filesystem::path& shaderDir);

  // The group representatives (position, unit normal, flux); at most kMaxVplShadowGroups
  // (throws std::invalid_argument beyond). The maps are re-rendered on the next render() only
  // if they differ from the last set.
  void setRepresentatives(std::span<const Vpl> representatives);
  // Renders the maps when the representatives changed or an instance moved (its model matrix
  // differs from the last render) or `enabled` was turned on; otherwise draws nothing. Returns
  // what it drew.
  ShadowDrawCount render(const GpuScene& scene);
  // Binds the depth array to `firstTextureUnit` (it uses that one unit) and sets every
  // uVplShadow* uniform of `program`. Throws std::logic_error when the unit is beyond
  // gl::Texture2D::maxFragmentUnits() (GL 3.3 guarantees only 0..15).
  void bind(gl::Program& program, int firstTextureUnit) const;

  void setEnabled(bool enabled);
  bool enabled() const { return settings_.enabled; }
  int groupCount() const { return static_cast<int>(representatives_.size()); }
  // Metres: the map origin of group g is position + originOffset · normal.
  float originOffset() const { return originOffset_; }

 private:
  bool casterMoved(const GpuScene& scene) const;

  VplShadowSettings settings_;
  gl::Program depth_;
  gl::DepthTarget target_;
  std::optional<gl::DepthTextureArray> maps_;
  std::vector<Vpl> representatives_;
  std::vector<glm::vec3> origins_;         // per group: the map origin, metres
  std::vector<glm::mat4> renderedModels_;  // per instance, at the last render
  bool dirty_ = true;
  float far_ = 1.0f;  // metres: depth = distance / far
  float originOffset_ = 0.0f;
};

}  // namespace bounce
