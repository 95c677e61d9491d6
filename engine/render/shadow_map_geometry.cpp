#include "render/shadow_map_geometry.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace bounce {

float spotMapHalfAngle(const Light& spot, int resolution, float marginTexels) {
  const float cone = std::min(spot.outerConeAngle, glm::radians(80.0f));
  // A margin of m texels at the rim: tan grows by the factor (1 + 2m/res).
  const float widen = 1.0f + 2.0f * marginTexels / static_cast<float>(std::max(resolution, 1));
  return std::atan(std::tan(cone) * widen);
}

float farDistance(glm::vec3 position, const Box& sceneBox) {
  if (sceneBox.empty()) return 1e-3f;
  const glm::vec3 far =
      glm::max(glm::abs(sceneBox.lower - position), glm::abs(sceneBox.upper - position));
  return std::max(glm::length(far) * 1.01f, 1e-3f);
}

int defaultShadowResolution(glm::vec3 position, const Box& sceneBox, float span, int lo, int hi) {
  if (sceneBox.empty()) return lo;
  const float diagonal = glm::length(sceneBox.upper - sceneBox.lower);
  const float distance =
      std::max(glm::length(0.5f * (sceneBox.lower + sceneBox.upper) - position), 0.25f * diagonal);
  const float texel = diagonal / 2048.0f;
  int resolution = lo;
  while (resolution < hi && span * distance / static_cast<float>(resolution) > texel)
    resolution *= 2;
  return std::min(resolution, hi);
}

namespace {

glm::vec3 anyUp(glm::vec3 direction) {
  return std::abs(direction.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

// The far clip plane's depth along `axis` (unit): just beyond the scene box's deepest corner,
// so the frustum (and the box around it that culling uses) ends where the scene does. Depth
// stored in the map is still distance / `far` (the radial reach).
float farPlane(glm::vec3 position, glm::vec3 axis, const Box& sceneBox, float far) {
  float deepest = 0.0f;
  for (int i = 0; i < 8 && !sceneBox.empty(); ++i) {
    const glm::vec3 corner((i & 1) ? sceneBox.upper.x : sceneBox.lower.x,
                           (i & 2) ? sceneBox.upper.y : sceneBox.lower.y,
                           (i & 4) ? sceneBox.upper.z : sceneBox.lower.z);
    deepest = std::max(deepest, glm::dot(corner - position, axis));
  }
  return std::clamp(deepest * 1.01f, far * 2e-4f, far);
}

}  // namespace

ShadowView spotShadowView(const Light& spot, const Box& sceneBox, int resolution,
                          float marginTexels) {
  const glm::vec3 direction = glm::normalize(spot.direction);
  const float half = spotMapHalfAngle(spot, resolution, marginTexels);
  ShadowView view;
  view.far = farDistance(spot.position, sceneBox);
  view.resolution = resolution;
  view.texelAngle = 2.0f * std::tan(half) / static_cast<float>(resolution);
  // The near plane only clips: depth is distance/far, written per fragment.
  view.viewProjection = glm::perspective(2.0f * half, 1.0f, view.far * 1e-4f,
                                         farPlane(spot.position, direction, sceneBox, view.far)) *
                        glm::lookAt(spot.position, spot.position + direction, anyUp(direction));
  return view;
}

ShadowView cubeFaceShadowView(glm::vec3 position, int face, const Box& sceneBox, int resolution) {
  // GL's cube map faces as seen from the centre (its sampling flips s and t per face).
  static const glm::vec3 kForward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                        {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  static const glm::vec3 kUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                   {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  ShadowView view;
  view.far = farDistance(position, sceneBox);
  view.resolution = resolution;
  view.texelAngle = 2.0f / static_cast<float>(resolution);
  view.viewProjection = glm::perspective(glm::radians(90.0f), 1.0f, view.far * 1e-4f,
                                         farPlane(position, kForward[face], sceneBox, view.far)) *
                        glm::lookAt(position, position + kForward[face], kUp[face]);
  return view;
}

ShadowView spotShadowViewFor(const Light& spot, const Box& sceneBox,
                             const ShadowSettings& settings) {
  const float margin = settings.filterRadius + 2.0f;
  int resolution = settings.resolution;
  if (resolution <= 0) {
    const float span = 2.0f * std::tan(spotMapHalfAngle(spot, 2048, margin));
    resolution = defaultShadowResolution(spot.position, sceneBox, span, 512, 2048);
  }
  return spotShadowView(spot, sceneBox, resolution, margin);
}

int pointShadowResolutionFor(glm::vec3 position, const Box& sceneBox,
                             const ShadowSettings& settings) {
  if (settings.resolution > 0) return settings.resolution;
  return defaultShadowResolution(position, sceneBox, 2.0f, 256, 1024);
}

}  // namespace bounce
