#include "vpl_runtime/vpl_occlusion.h"

#include <algorithm>
#include <cmath>

namespace bounce {
namespace {

constexpr float kSegmentEpsilon = 1e-4f;

// Möller–Trumbore: does the segment o + t·d, t in (ε, 1 − ε), cross triangle (a, b, c)?
bool segmentCrossesTriangle(glm::vec3 o, glm::vec3 d, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 e1 = b - a, e2 = c - a;
  const glm::vec3 p = glm::cross(d, e2);
  const float det = glm::dot(e1, p);
  if (std::abs(det) < 1e-20f) return false;
  const float inv = 1.0f / det;
  const glm::vec3 s = o - a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return false;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(d, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return false;
  const float t = glm::dot(e2, q) * inv;
  return t > kSegmentEpsilon && t < 1.0f - kSegmentEpsilon;
}

// Whether the segment o + t·d, t in [0, 1], comes within the occluder's bounding sphere.
bool segmentNearSphere(glm::vec3 o, glm::vec3 d, const VplOccluder& occluder) {
  const float dd = glm::dot(d, d);
  const float t = dd > 0.0f ? std::clamp(glm::dot(occluder.centre - o, d) / dd, 0.0f, 1.0f) : 0.0f;
  const glm::vec3 closest = o + t * d - occluder.centre;
  return glm::dot(closest, closest) <= occluder.radius * occluder.radius;
}

bool segmentBlocked(glm::vec3 from, glm::vec3 to, std::span<const VplOccluder> occluders) {
  const glm::vec3 d = to - from;
  for (const VplOccluder& occluder : occluders) {
    if (!segmentNearSphere(from, d, occluder)) continue;
    for (std::size_t i = 0; i + 2 < occluder.corners.size(); i += 3)
      if (segmentCrossesTriangle(from, d, occluder.corners[i], occluder.corners[i + 1],
                                 occluder.corners[i + 2]))
        return true;
  }
  return false;
}

}  // namespace

VplOccluder makeVplOccluder(const Mesh& mesh, const glm::mat4& objectToWorld) {
  VplOccluder out;
  out.corners.reserve(mesh.indices.size());
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    bool valid = true;
    for (int k = 0; k < 3; ++k) valid = valid && mesh.indices[i + k] < mesh.positions.size();
    if (!valid) continue;
    for (int k = 0; k < 3; ++k)
      out.corners.push_back(
          glm::vec3(objectToWorld * glm::vec4(mesh.positions[mesh.indices[i + k]], 1.0f)));
  }
  if (out.corners.empty()) return out;
  glm::vec3 lo = out.corners.front(), hi = lo;
  for (const glm::vec3& p : out.corners) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  out.centre = 0.5f * (lo + hi);
  for (const glm::vec3& p : out.corners)
    out.radius = std::max(out.radius, glm::length(p - out.centre));
  out.radius *= 1.0001f;  // rounding: the sphere must hold every corner
  return out;
}

std::vector<VplOccluder> dynamicVplOccluders(const Scene& scene) {
  std::vector<VplOccluder> out;
  for (const Instance& instance : scene.instances)
    if (instance.mobility == Mobility::Dynamic && instance.mesh < scene.meshes.size())
      out.push_back(makeVplOccluder(scene.meshes[instance.mesh], instance.transform));
  return out;
}

std::vector<uint8_t> vplAliveMask(std::span<const Vpl> vpls,
                                  std::span<const VplOccluder> occluders) {
  std::vector<uint8_t> alive(vpls.size(), 1);
  if (occluders.empty()) return alive;
  bool blocked = false;
  for (std::size_t i = 0; i < vpls.size(); ++i) {
    if (i == 0 || vpls[i].path != vpls[i - 1].path) blocked = false;  // a new path
    if (!blocked) blocked = segmentBlocked(vpls[i].from, vpls[i].position, occluders);
    alive[i] = blocked ? 0 : 1;
  }
  return alive;
}

}  // namespace bounce
