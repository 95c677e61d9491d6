// Visibility of virtual point lights: low-resolution depth cubes at chosen VPLs, so
// the VPL term can tell whether a VPL's light reaches a point. Each of the K ≤ 64 groups
// (vpl_runtime/vpl_groups.h) is split into up to kVplShadowCubesPerGroup parts along its members'
// principal axes, and each part gets one cube, at its member nearest the part's centroid
// (vplShadowCubes). Every light of the VPL term takes the visibility of one cube:
// shaders/vpl_shadows.glsl's vplVisibility(cube, p, ng), 1 = the cube's origin sees p, 0 =
// occluded, bilinear-filtered in between. A cube stands for its members' visibility; the
// error is how differently they see a receiver (docs/vpl.md "Visibility": one cube per group
// darkened the dynamic sphere by 3-8% against exact visibility, four per group by ≤ 1%).
//
// Layout: GL 3.3 core has no cube-map arrays, so all cubes share one depth32F
// GL_TEXTURE_2D_ARRAY, layer 6·cube + face, faces in GL's cube order (+X, −X, +Y, −Y, +Z, −Z)
// with the frames of cubeFaceShadowView; the shader picks the face by the major axis. Depth
// is distance / far, one `far` for every cube, so the per-cube uniform is the map origin.
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

#include "bake_folder/vpl.h"
#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/shadow_settings.h"
#include "render/vpl_render_settings.h"
#include "vpl_runtime/vpl_groups.h"

namespace bounce {

class GpuScene;

// The groups (K ≤ kMaxVplGroups) and cubes per group; kMaxVplShadowCubes must match
// MAX_VPL_SHADOW_CUBES in shaders/vpl_shadows.glsl.
constexpr int kMaxVplShadowGroups = 64;
constexpr int kVplShadowCubesPerGroup = 4;
constexpr int kMaxVplShadowCubes = kMaxVplShadowGroups * kVplShadowCubesPerGroup;

// What fits a driver whose array textures hold `maxLayers` layers (6 per cube; GL 3.3 promises
// only 256): the cubes per group halved from `wanted` and then, at one cube per group, the groups
// reduced until 6·groups·cubesPerGroup ≤ maxLayers. `groups` 0 means none fit (maxLayers < 6).
struct VplShadowBudget {
  int groups = 0;
  int cubesPerGroup = 1;
};
VplShadowBudget vplShadowBudget(int maxLayers, int groups, int wanted);

// Where the cubes of `groups` sit and which cube each light-table entry reads (GL-free).
struct VplShadowCubes {
  std::vector<Vpl> origins;      // per cube: the member VPL it sits at (position, normal)
  std::vector<uint32_t> cubeOf;  // per light of groups.lights(): its cube
};
// Each group's members are halved at the median of their projection on the principal axis of
// their positions, recursively, into up to `cubesPerGroup` parts (a power of two; fewer when a
// group has fewer members); a part's cube sits at the member nearest its flux-weighted centroid
// (a centroid can lie inside an object, a member lies on a surface: nearestVpl). A VPL reads its
// part's cube; a tree node or group representative (many members) the cube of its group whose
// origin is nearest to it.
VplShadowCubes vplShadowCubes(const VplGroups& groups, int cubesPerGroup);

// Bit f set: cube face f (GL order) reaches the hemisphere dot(ω, normal) > 0 and is rendered.
// The face opposite an axis-aligned normal is the one skipped.
uint32_t vplShadowFaces(glm::vec3 normal);

class VplShadowMaps {
 public:
  // Needs a current GL context; compiles the depth program from `shaderDir`.
  VplShadowMaps(const VplShadowSettings& settings, const std::filesystem::path& shaderDir);

  // The cube origins (position, unit normal; VplShadowCubes::origins); at most
  // kMaxVplShadowCubes (throws std::invalid_argument beyond). The maps are re-rendered on the next
  // render() only if they differ from the last set.
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
  int cubesPerGroup() const { return settings_.cubesPerGroup; }
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
