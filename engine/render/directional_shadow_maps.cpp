#include "render/directional_shadow_maps.h"

#include "gl/draw_state.h"
#include "render/gpu_scene.h"
#include "render/shader_constants.h"
#include "render/texture_units.h"

namespace bounce {

DirectionalShadowMaps::DirectionalShadowMaps(const ShadowSettings& settings,
                                             const std::filesystem::path& shaderDir)
    : settings_(settings), shaderDir_(shaderDir) {
  // Per cascade: the override, else 2048 texels (the covered depth, hence each texel's size,
  // follows the scene's extent: render/cascades.h).
  cascadeSettings_.resolution = settings.resolution > 0 ? settings.resolution : 2048;
}

int DirectionalShadowMaps::add(const Light& light) {
  if (!settings_.enabled || light_) return -1;
  light_ = light;
  depth_.emplace(shaderDir_ / "shadow_depth.vert", shaderDir_ / "shadow_directional_depth.frag",
                 shaderConstants());
  atlas_.emplace(2 * cascadeSettings_.resolution, 2 * cascadeSettings_.resolution);
  return 0;
}

ShadowDrawCount DirectionalShadowMaps::render(const GpuScene& scene, const Camera& camera,
                                              float aspect, gl::DepthTarget& target) {
  ShadowDrawCount count;
  if (!light_ || released_) {
    cascades_.clear();
    return count;
  }
  const Box box = scene.bounds();
  const Bounds bounds{box.lower, box.upper, box.empty()};
  camera_ = camera;
  cascades_ = fitCascades(camera, aspect, light_->direction, bounds, cascadeSettings_);
  bool still = drawn_.size() == cascades_.size();
  for (std::size_t i = 0; still && i < cascades_.size(); ++i)
    still = drawn_[i].matches(cascades_[i].worldToClip, scene.instances());
  if (still) return count;
  drawn_.assign(cascades_.size(), ShadowMapStamp{});
  for (std::size_t i = 0; i < cascades_.size(); ++i)
    drawn_[i].set(cascades_[i].worldToClip, scene.instances());
  target.bind(*atlas_);
  gl::clearDepth();
  gl::setDepthTest(true);
  gl::setBackFaceCulling(false);
  const int r = cascadeSettings_.resolution;
  for (std::size_t i = 0; i < cascades_.size(); ++i) {
    gl::setViewport(static_cast<int>(i & 1u) * r, static_cast<int>(i >> 1u) * r, r, r);
    depth_->set("uViewProjection", cascades_[i].worldToClip);
    const Frustum frustum(cascades_[i].worldToClip);
    ++count.views;
    for (const GpuInstance& instance : scene.instances()) {
      if (!frustum.overlaps(instance.worldBox)) continue;
      scene.draw(instance, *depth_);
      ++count.casters;
    }
  }
  return count;
}

void DirectionalShadowMaps::bind(gl::Program& forward) const {
  forward.set("uCascadeMap", TextureUnit::kDirectionalShadow);
  forward.set("uCascadeCount", static_cast<int>(cascades_.size()));
  if (cascades_.empty()) return;
  atlas_->bind(TextureUnit::kDirectionalShadow);
  std::vector<glm::mat4> matrices;
  std::vector<glm::vec4> depths, params;
  for (const Cascade& c : cascades_) {
    matrices.push_back(c.worldToClip);
    depths.emplace_back(c.nearDepth, c.blendStart, c.splitDepth, 0.0f);
    params.emplace_back(static_cast<float>(c.texelSize),
                        static_cast<float>(c.depthFar - c.depthNear), settings_.filterRadius,
                        static_cast<float>(cascadeSettings_.resolution));
  }
  forward.set("uCascadeWorldToClip", std::span<const glm::mat4>(matrices));
  forward.set("uCascadeDepths", std::span<const glm::vec4>(depths));
  forward.set("uCascadeParams", std::span<const glm::vec4>(params));
  forward.set("uViewPosition", camera_.position());
  forward.set("uViewForward", camera_.forward());
}

}  // namespace bounce
