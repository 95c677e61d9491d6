#include "render/shadow_receivers.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace bounce {
namespace {

// Where the segment from `from` to `to` first meets a surface of `box` (the parameter in [0, 1]:
// the exit when `from` is inside, else the entry), or a negative value when it misses.
float firstBoxSurface(glm::vec3 from, glm::vec3 to, const Box& box) {
  const glm::vec3 d = to - from;
  float enter = 0.0f, leave = 1.0f;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-12f) {
      if (from[a] < box.lower[a] || from[a] > box.upper[a]) return -1.0f;
      continue;
    }
    float t0 = (box.lower[a] - from[a]) / d[a], t1 = (box.upper[a] - from[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  if (enter > leave) return -1.0f;
  return enter > 0.0f ? enter : leave;
}

std::vector<glm::vec3> rayPoints(const GpuScene& scene, const ViewVolume& view) {
  std::vector<Box> boxes;
  for (const GpuInstance& instance : scene.instances())
    if (instance.mobility == Mobility::Static &&
        scene.materials()[instance.material].emission == glm::vec3(0.0f) &&
        !intersect(instance.worldBox, view.box).empty())
      boxes.push_back(instance.worldBox);
  std::vector<glm::vec3> points;
  constexpr int kRays = 5;
  for (int i = 0; i < kRays; ++i)
    for (int j = 0; j < kRays; ++j) {
      const glm::vec2 ndc((2.0f * static_cast<float>(i) + 1.0f) / kRays - 1.0f,
                          (2.0f * static_cast<float>(j) + 1.0f) / kRays - 1.0f);
      const glm::vec4 n = view.clipToWorld * glm::vec4(ndc, -1.0f, 1.0f);
      const glm::vec4 f = view.clipToWorld * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 from = glm::vec3(n) / n.w, to = glm::vec3(f) / f.w;
      float nearest = 2.0f;
      for (const Box& box : boxes) {
        const float t = firstBoxSurface(from, to, box);
        if (t >= 0.0f && t < nearest) nearest = t;
      }
      if (nearest <= 1.0f) points.push_back(from + nearest * (to - from));
    }
  return points;
}

}  // namespace

ShadowReceivers shadowReceivers(const GpuScene& scene, const ViewVolume& view, bool viewPoints,
                                glm::vec3 eye) {
  ShadowReceivers where;
  const std::span<const GpuInstance> instances = scene.instances();
  for (std::size_t i = 0; i < instances.size(); ++i)
    if (instances[i].mobility == Mobility::Dynamic &&
        !intersect(instances[i].worldBox, view.box).empty())
      where.dynamics.push_back({instances[i].worldBox, static_cast<uint32_t>(i)});
  if (viewPoints)
    for (const GpuInstance& instance : instances) {
      if (instance.mobility != Mobility::Static ||
          scene.materials()[instance.material].emission != glm::vec3(0.0f))
        continue;
      const Box visible = intersect(instance.worldBox, view.box);
      if (visible.empty() || !view.frustum.overlaps(visible)) continue;
      const glm::vec3 cell = (visible.upper - visible.lower) / 3.0f;
      const float area = std::max({cell.x * cell.y, cell.y * cell.z, cell.z * cell.x});
      for (const glm::vec3& p : viewSamplePoints(view.frustum, visible, 3)) {
        where.viewPoints.push_back(p);
        where.viewWeights.push_back(viewPointWeight(eye, p, area));
      }
    }
  // A close-up sees a few square centimetres between the grid's points: then the points where
  // rays through a 5 × 5 grid of the image first meet a visible static instance's box (leaving
  // a box the camera is in, as a room's walls, entering the others), each the same share of the
  // screen.
  if (viewPoints && where.viewPoints.empty())
    for (const glm::vec3& p : rayPoints(scene, view)) {
      where.viewPoints.push_back(p);
      where.viewWeights.push_back(1.0f);
    }
  // Every frame costs lights × points irradiance evaluations: a scene of many instances keeps
  // an even spread of at most kMaxViewPoints.
  constexpr std::size_t kMaxViewPoints = 512;
  if (where.viewPoints.size() > kMaxViewPoints) {
    std::vector<glm::vec3> spread;
    std::vector<float> weights;
    for (std::size_t k = 0; k < kMaxViewPoints; ++k) {
      const std::size_t i = k * where.viewPoints.size() / kMaxViewPoints;
      spread.push_back(where.viewPoints[i]);
      weights.push_back(where.viewWeights[i]);
    }
    where.viewPoints = std::move(spread);
    where.viewWeights = std::move(weights);
  }
  return where;
}

}  // namespace bounce
