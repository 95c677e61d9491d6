// The VPL stage of the lit pass (shaders/vpl.glsl): groups a bake's virtual point lights
// (vpl_runtime/vpl_groups.h: K ≤ 64 groups, each with a representative and a tree), builds the
// per-cell lightcuts over the static scene's bounds, gives the lights and the cuts as the light
// table's VPL sections (render/light_table.h: no fixed cap on the VPL count) and tells the forward
// shader, per draw, whether the instance takes its indirect light from the VPLs (dynamic
// instances; every surface in the vpl modes). Without VPLs its cut section is one empty cell.
// GL calls only through engine/gl.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gl/shader.h"
#include "render/frustum.h"
#include "render/light_table.h"
#include "render/vpl_render_settings.h"
#include "render/vpl_shadow_maps.h"
#include "vpl_runtime/vpl_groups.h"

namespace bounce {

class GpuScene;

class VplPass {
 public:
  // Compiles the VPL shadow maps' depth program from `shaderDir`; appends to `warnings` when the
  // driver has no texture unit for them (they are then off).
  VplPass(const std::filesystem::path& shaderDir, const VplShadowSettings& shadows,
          std::vector<std::string>& warnings);

  // Groups and uploads `vpls` (W per channel, bake_folder/vpl.h) with clamp distance r (m) over
  // `bounds` (the static scene, metres).
  void attach(std::span<const Vpl> vpls, float clampDistance, const Box& bounds,
              const VplRenderSettings& settings);
  bool attached() const { return attached_; }
  // Changes whenever what a receiver gathers may have: attach, setAlive, setShadowsEnabled.
  uint64_t version() const { return version_; }
  // Recomputes the light section's flux with only the VPLs with alive[i] ≠ 0 (input order of
  // attach; vpl_runtime/vpl_occlusion.h) shining; groups, cuts and positions are kept. The caller
  // hands lightTexels() to the light table again.
  void setAlive(std::span<const uint8_t> alive);

  // Per frame, before the lit pass: redraws the groups' shadow cubes when something moved.
  ShadowDrawCount renderShadows(const GpuScene& scene);
  // Visibility on or off (off: every VPL unoccluded), e.g. to measure what it buys.
  void setShadowsEnabled(bool enabled);
  bool shadowsEnabled() const { return shadows_ && shadows_->enabled(); }
  // Per frame: grid, clamp distance, shadow cubes (the lights are in the light table).
  void bind(gl::Program& program) const;
  // Per draw: whether instance `index` (into GpuScene::instances) is lit by the VPLs in the
  // full and indirect modes (when VPLs are attached: a dynamic instance, or a static one without
  // baked light, `baked` false: no lightmap region and no probes).
  void setInstance(gl::Program& program, const GpuScene& scene, std::size_t index,
                   bool baked) const;
  // Whether any instance of `scene` is drawn from the VPLs in `mode` (the vpl modes: all; full
  // and indirect: the dynamic ones and the static ones without baked light, baked[i] false).
  bool anyReceiver(const GpuScene& scene, std::span<const uint8_t> baked, bool everySurface) const;

  // The light table's VPL sections (render/light_table.h): 3 texels per light, then the cuts.
  const std::vector<glm::vec4>& lightTexels() const { return lightTexels_; }
  const std::vector<glm::vec4>& cutTexels() const { return cutTexels_; }

  const VplGroups& groups() const { return groups_; }
  const VplLightCuts& cuts() const { return cuts_; }
  float clampDistance() const { return clampDistance_; }

 private:
  VplGroups groups_;
  VplLightCuts cuts_;
  VplShadowCubes cubes_;  // where the shadow cubes sit, which one each light reads
  float clampDistance_ = 0.0f;
  std::vector<glm::vec4> lightTexels_;
  std::vector<glm::vec4> cutTexels_{glm::vec4(0.0f)};  // unattached: one cell, no entries
  std::optional<VplShadowMaps> shadows_;               // empty when the driver lacks kVplShadow
  // K's ceiling with shadow cubes: the driver's array layers (vplShadowBudget).
  std::size_t maxShadowGroups_ = kMaxVplShadowGroups;
  bool attached_ = false;
  uint64_t version_ = 0;
};

}  // namespace bounce
