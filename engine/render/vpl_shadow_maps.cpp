#include "render/vpl_shadow_maps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "gl/draw_state.h"
#include "gl/texture.h"
#include "render/gpu_scene.h"
#include "render/shader_constants.h"
#include "render/shadow_casters.h"
#include "render/shadow_map_geometry.h"

namespace bounce {
namespace {

// GL's cube faces: forward axis and up vector as cubeFaceShadowView renders them.
const glm::vec3 kFaceForward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
const glm::vec3 kFaceUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                              {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

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

namespace {

// Halves `members` (indices into vpls) recursively as vplShadowCubes describes, appending one
// cube per part to `cubes` and recording it in cubeOf.
void splitIntoCubes(std::span<const Vpl> vpls, std::span<uint32_t> members, int parts,
                    VplShadowCubes& cubes) {
  if (parts <= 1 || members.size() < 2) {
    glm::dvec3 weighted(0.0);
    double weight = 0.0;
    for (const uint32_t i : members) {
      // Flux-weighted (luminance-free: the channel sum); a part of black VPLs by position.
      const double w =
          static_cast<double>(vpls[i].flux.r + vpls[i].flux.g + vpls[i].flux.b) + 1e-30;
      weighted += w * glm::dvec3(vpls[i].position);
      weight += w;
    }
    const glm::vec3 centroid(weighted / weight);
    uint32_t best = members[0];
    float bestDistance = std::numeric_limits<float>::infinity();
    for (const uint32_t i : members) {
      const glm::vec3 d = vpls[i].position - centroid;
      if (glm::dot(d, d) < bestDistance) best = i, bestDistance = glm::dot(d, d);
    }
    const auto cube = static_cast<uint32_t>(cubes.origins.size());
    cubes.origins.push_back(vpls[best]);
    for (const uint32_t i : members) cubes.cubeOf[i] = cube;
    return;
  }
  glm::dvec3 mean(0.0);
  for (const uint32_t i : members) mean += glm::dvec3(vpls[i].position);
  mean /= static_cast<double>(members.size());
  glm::dmat3 covariance(0.0);
  for (const uint32_t i : members) {
    const glm::dvec3 d = glm::dvec3(vpls[i].position) - mean;
    covariance += glm::outerProduct(d, d);
  }
  // Principal axis by power iteration, started on the coordinate axis of largest variance (never
  // orthogonal to the answer when that axis dominates; deterministic).
  glm::dvec3 axis(0.0);
  int largest = 0;
  for (int a = 1; a < 3; ++a)
    if (covariance[a][a] > covariance[largest][largest]) largest = a;
  axis[largest] = 1.0;
  for (int k = 0; k < 32; ++k) {
    const glm::dvec3 next = covariance * axis;
    const double length = glm::length(next);
    if (!(length > 0.0)) break;
    axis = next / length;
  }
  std::stable_sort(members.begin(), members.end(), [&](uint32_t a, uint32_t b) {
    return glm::dot(glm::dvec3(vpls[a].position), axis) <
           glm::dot(glm::dvec3(vpls[b].position), axis);
  });
  const std::size_t half = members.size() / 2;
  splitIntoCubes(vpls, members.first(half), parts / 2, cubes);
  splitIntoCubes(vpls, members.subspan(half), parts / 2, cubes);
}

}  // namespace

VplShadowBudget vplShadowBudget(int maxLayers, int groups, int wanted) {
  VplShadowBudget budget{std::max(groups, 0), std::max(wanted, 1)};
  while (budget.cubesPerGroup > 1 && 6 * budget.groups * budget.cubesPerGroup > maxLayers)
    budget.cubesPerGroup /= 2;
  budget.groups = std::min(budget.groups, std::max(maxLayers, 0) / (6 * budget.cubesPerGroup));
  return budget;
}

VplShadowCubes vplShadowCubes(const VplGroups& groups, int cubesPerGroup) {
  if (cubesPerGroup < 1 || (cubesPerGroup & (cubesPerGroup - 1)) != 0)
    throw std::invalid_argument(std::to_string(cubesPerGroup) +
                                " VPL shadow cubes per group (must be a power of two)");
  VplShadowCubes cubes;
  const std::span<const Vpl> lights = groups.lights();
  cubes.cubeOf.assign(lights.size(), 0);
  std::vector<uint32_t> firstCube;  // per group
  for (const VplGroup& group : groups.groups()) {
    firstCube.push_back(static_cast<uint32_t>(cubes.origins.size()));
    std::vector<uint32_t> members(group.count);
    for (std::size_t i = 0; i < group.count; ++i)
      members[i] = static_cast<uint32_t>(group.first + i);
    splitIntoCubes(groups.vpls(), members, cubesPerGroup, cubes);
  }
  firstCube.push_back(static_cast<uint32_t>(cubes.origins.size()));
  for (std::size_t light = groups.vplCount(); light < lights.size(); ++light) {
    const uint32_t g = groups.groupOf(light);
    float bestDistance = std::numeric_limits<float>::infinity();
    for (uint32_t c = firstCube[g]; c < firstCube[g + 1]; ++c) {
      const glm::vec3 d = cubes.origins[c].position - lights[light].position;
      if (glm::dot(d, d) < bestDistance) cubes.cubeOf[light] = c, bestDistance = glm::dot(d, d);
    }
  }
  return cubes;
}

VplShadowMaps::VplShadowMaps(const VplShadowSettings& settings,
                             const std::filesystem::path& shaderDir)
    : settings_(settings),
      depth_(shaderDir / "shadow_depth.vert", shaderDir / "vpl_shadow_depth.frag",
             shaderConstants()) {
  if (settings_.resolution <= 0)
    throw std::invalid_argument("VPL shadow map resolution " +
                                std::to_string(settings_.resolution) + " (must be positive)");
  const int perGroup = settings_.cubesPerGroup;
  if (perGroup < 1 || perGroup > kVplShadowCubesPerGroup || (perGroup & (perGroup - 1)) != 0)
    throw std::invalid_argument("VPL shadow cubes per group " + std::to_string(perGroup) +
                                " (must be 1, 2 or 4)");
  maps_.emplace(settings_.resolution, 6);
}

void VplShadowMaps::setRepresentatives(std::span<const Vpl> representatives) {
  if (representatives.size() > static_cast<std::size_t>(kMaxVplShadowCubes))
    throw std::invalid_argument(std::to_string(representatives.size()) +
                                " VPL shadow cubes (at most " + std::to_string(kMaxVplShadowCubes) +
                                ")");
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
  originOffset_ =
      settings_.originOffset > 0.0f
          ? settings_.originOffset
          : (sceneBox.empty() ? 1e-3f : 1e-3f * glm::length(sceneBox.upper - sceneBox.lower));
  // One reach for every cube (the depth is distance / far_ in all of them).
  far_ = 1e-3f;
  origins_.clear();
  for (const Vpl& vpl : representatives_) {
    const glm::vec3 origin = vpl.position + originOffset_ * vpl.normal;
    far_ = std::max(far_, farDistance(origin, sceneBox));
    origins_.push_back(origin);
  }
  ShadowDrawCount count;
  for (int group = 0; group < groups; ++group) {
    const glm::vec3 origin = origins_[static_cast<std::size_t>(group)];
    const glm::vec3 normal = representatives_[static_cast<std::size_t>(group)].normal;
    const uint32_t faces = vplShadowFaces(normal);
    depth_.set("uVplNormal", normal);
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
  const bool on = settings_.enabled && !origins_.empty();
  program.set("uVplShadowEnabled", on ? 1 : 0);
  program.set("uVplShadowCount", on ? static_cast<int>(origins_.size()) : 0);
  if (on) program.set("uVplShadowOrigin", std::span<const glm::vec3>(origins_));
  program.set("uVplShadowParams",
              glm::vec4(2.0f / static_cast<float>(settings_.resolution), far_, originOffset_,
                        static_cast<float>(settings_.resolution)));
}

}  // namespace bounce
