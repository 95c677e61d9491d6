#include "render/vpl_shadow_maps.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gl/draw_state.h"
#include "gl/texture.h"
#include "render/shadow_casters.h"
#include "render/shadow_map_geometry.h"

namespace bounce {
namespace {

// GL's cube faces: forward axis and up vector as cubeFaceShadowView renders them.
const glm::vec3 kFaceForward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
const glm::vec3 kFaceUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                              {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

glm::vec2 signNotZero(glm::vec2 v) {
  return {v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f};
}

constexpr float kOctahedralSteps = 4095.0f;  // 12 bits per coordinate

}  // namespace

uint32_t vplShadowFaces(glm::vec3 normal) {
  uint32_t faces = 0;
  for (int face = 0; face < 6; ++face) {
    // The face is the cone of directions F + s·R + t·U, |s|, |t| ≤ 1; its largest dot with the
    // normal is at a corner.
    const glm::vec3 f = kFaceForward[face];
    const glm::vec3 r = glm::cross(f, kFaceUp[face]);
    const glm::vec3 u = glm::cross(r, f);
    const float reach =
        glm::dot(f, normal) + std::abs(glm::dot(r, normal)) + std::abs(glm::dot(u, normal));
    if (reach > 1e-6f) faces |= 1u << face;
  }
  return faces;
}

float vplShadowPackNormal(glm::vec3 normal) {
  const float l1 = std::abs(normal.x) + std::abs(normal.y) + std::abs(normal.z);
  if (!(l1 > 0.0f)) normal = {0.0f, 0.0f, 1.0f};
  glm::vec3 n = normal / (l1 > 0.0f ? l1 : 1.0f);
  glm::vec2 o(n.x, n.y);
  if (n.z < 0.0f) o = (1.0f - glm::abs(glm::vec2(o.y, o.x))) * signNotZero(o);
  const glm::vec2 q = glm::round((glm::clamp(o, -1.0f, 1.0f) * 0.5f + 0.5f) * kOctahedralSteps);
  return q.x * 4096.0f + q.y;
}

glm::vec3 vplShadowUnpackNormal(float packed) {
  const float qx = std::floor(packed / 4096.0f);
  const float qy = packed - qx * 4096.0f;
  const glm::vec2 o = glm::vec2(qx, qy) / kOctahedralSteps * 2.0f - 1.0f;
  glm::vec3 n(o.x, o.y, 1.0f - std::abs(o.x) - std::abs(o.y));
  if (n.z < 0.0f) {
    const glm::vec2 folded = (1.0f - glm::abs(glm::vec2(n.y, n.x))) * signNotZero({n.x, n.y});
    n.x = folded.x;
    n.y = folded.y;
  }
  return glm::normalize(n);
}

VplShadowMaps::VplShadowMaps(const VplShadowSettings& settings,
                             const std::filesystem::path& shaderDir)
    : settings_(settings),
      depth_(shaderDir / "shadow_depth.vert", shaderDir / "shadow_depth.frag") {
  if (settings_.resolution <= 0)
    throw std::invalid_argument("VPL shadow map resolution " +
                                std::to_string(settings_.resolution) + " (must be positive)");
  maps_.emplace(settings_.resolution, 6);
}

void VplShadowMaps::setRepresentatives(std::span<const Vpl> representatives) {
  if (representatives.size() > static_cast<std::size_t>(kMaxVplShadowGroups))
    throw std::invalid_argument(std::to_string(representatives.size()) +
                                " VPL groups for shadow maps (at most " +
                                std::to_string(kMaxVplShadowGroups) + ")");
  const bool same = std::equal(
      representatives.begin(), representatives.end(), representatives_.begin(),
      representatives_.end(),
      [](const Vpl& a, const Vpl& b) { return a.position == b.position && a.normal == b.normal; });
  representatives_.assign(representatives.begin(), representatives.end());
  if (!same) dirty_ = true;
}

void VplShadowMaps::setEnabled(bool enabled) {
  if (enabled && !settings_.enabled) dirty_ = true;
  settings_.enabled = enabled;
}

bool VplShadowMaps::casterMoved(const GpuScene& scene) const {
  const auto instances = scene.instances();
  if (instances.size() != renderedModels_.size()) return true;
  for (std::size_t i = 0; i < instances.size(); ++i)
    if (instances[i].model != renderedModels_[i]) return true;
  return false;
}

ShadowDrawCount VplShadowMaps::render(const GpuScene& scene) {
  if (!settings_.enabled || (!dirty_ && !casterMoved(scene))) return {};
  const Box sceneBox = scene.bounds();
  const int groups = groupCount();
  if (maps_->layers() < 6 * groups) maps_.emplace(settings_.resolution, 6 * groups);
  originOffset_ = settings_.originOffset > 0.0f
                      ? settings_.originOffset
                      : (sceneBox.empty() ? 1e-3f : 1e-3f * glm::length(sceneBox.hi - sceneBox.lo));
  // One reach for every cube (the depth is distance / far_ in all of them).
  far_ = 1e-3f;
  groupUniforms_.clear();
  for (const Vpl& vpl : representatives_) {
    const glm::vec3 origin = vpl.position + originOffset_ * vpl.normal;
    far_ = std::max(far_, farDistance(origin, sceneBox));
    groupUniforms_.emplace_back(origin, vplShadowPackNormal(vpl.normal));
  }
  ShadowDrawCount count;
  for (int group = 0; group < groups; ++group) {
    const glm::vec3 origin(groupUniforms_[static_cast<std::size_t>(group)]);
    const uint32_t faces = vplShadowFaces(representatives_[static_cast<std::size_t>(group)].normal);
    for (int face = 0; face < 6; ++face) {
      target_.bind(*maps_, 6 * group + face);
      if (!(faces & (1u << face))) {
        gl::clearDepth();  // never looked up (behind the VPL); far = lit
        continue;
      }
      ShadowView view = cubeFaceShadowView(origin, face, sceneBox, settings_.resolution);
      view.far = far_;
      count += {1, drawShadowCasters(scene, view, origin, depth_)};
    }
  }
  renderedModels_.clear();
  for (const GpuInstance& instance : scene.instances()) renderedModels_.push_back(instance.model);
  dirty_ = false;
  gl::checkErrors("VPL shadow maps");
  return count;
}

void VplShadowMaps::bind(gl::Program& program, int firstTextureUnit) const {
  if (firstTextureUnit < 0 || firstTextureUnit >= gl::Texture2D::maxFragmentUnits())
    throw std::logic_error("VPL shadow maps on texture unit " + std::to_string(firstTextureUnit) +
                           ": the driver gives fragment shaders units 0 to " +
                           std::to_string(gl::Texture2D::maxFragmentUnits() - 1));
  maps_->bind(firstTextureUnit);
  program.set("uVplShadowMap", firstTextureUnit);
  const bool on = settings_.enabled && !groupUniforms_.empty();
  program.set("uVplShadowEnabled", on ? 1 : 0);
  program.set("uVplShadowCount", on ? static_cast<int>(groupUniforms_.size()) : 0);
  if (on) program.set("uVplShadowGroup", std::span<const glm::vec4>(groupUniforms_));
  program.set("uVplShadowParams",
              glm::vec4(2.0f / static_cast<float>(settings_.resolution), far_, originOffset_,
                        static_cast<float>(settings_.resolution)));
}

}  // namespace bounce
