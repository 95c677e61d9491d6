#include "render/cluster_grid.h"

#include <algorithm>
#include <cmath>

namespace bounce {

glm::vec2 ClusterGrid::sliceScaleBias() const {
  const float scale = static_cast<float>(slices) / std::log(farDepth / nearDepth);
  return {scale, -std::log(nearDepth) * scale};
}

int ClusterGrid::sliceOf(float depth) const {
  const glm::vec2 ab = sliceScaleBias();
  const float s = std::floor(std::log(std::max(depth, 1e-30f)) * ab.x + ab.y);
  return static_cast<int>(std::clamp(s, 0.0f, static_cast<float>(slices - 1)));
}

float ClusterGrid::sliceDepth(int s) const {
  if (s <= 0) return nearDepth;
  if (s >= slices) return farDepth;
  return nearDepth * std::pow(farDepth / nearDepth, static_cast<float>(s) / slices);
}

Box ClusterGrid::clusterBox(int x, int y, int s) const {
  // Pixel edges → view x/d, y/d (glm::perspective: x_ndc = (x/d) / (aspect · tan(fov/2))).
  const auto across = [](int pixel, int size, float tanHalf) {
    return (2.0f * static_cast<float>(std::min(pixel, size)) / static_cast<float>(size) - 1.0f) *
           tanHalf;
  };
  const float x0 = across(x * tilePixels, width, tanHalfFov.x);
  const float x1 = across((x + 1) * tilePixels, width, tanHalfFov.x);
  const float y0 = across(y * tilePixels, height, tanHalfFov.y);
  const float y1 = across((y + 1) * tilePixels, height, tanHalfFov.y);
  const float d0 = sliceDepth(s), d1 = sliceDepth(s + 1);
  Box box;
  for (float d : {d0, d1})
    for (float u : {x0, x1})
      for (float v : {y0, y1}) box.grow(glm::vec3(u * d, v * d, -d));
  const glm::vec3 pad = 1e-4f * (box.upper - box.lower) + glm::vec3(1e-4f * d1);
  box.lower -= pad;
  box.upper += pad;
  return box;
}

ClusterGrid makeClusterGrid(const Camera& camera, int width, int height, float nearDepth,
                            float farDepth, ClusterGridSize size) {
  ClusterGrid grid;
  grid.view = glm::inverse(camera.cameraToWorld);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const float tanY = std::tan(0.5f * camera.yfov);
  grid.tanHalfFov = {aspect * tanY, tanY};
  grid.width = width;
  grid.height = height;
  grid.tilePixels = std::max(1, (width + size.tilesAcross - 1) / size.tilesAcross);
  grid.tilesX = (width + grid.tilePixels - 1) / grid.tilePixels;
  grid.tilesY = (height + grid.tilePixels - 1) / grid.tilePixels;
  grid.slices = std::max(1, size.slices);
  grid.nearDepth = std::clamp(nearDepth, camera.znear, camera.zfar);
  grid.farDepth = std::clamp(farDepth, camera.znear, camera.zfar);
  // A grid needs far > near (a flat scene facing the camera has one depth).
  if (!(grid.farDepth > grid.nearDepth * 1.001f)) grid.farDepth = grid.nearDepth * 1.001f;
  return grid;
}

glm::vec2 viewDepthRange(const Camera& camera, const Box& box) {
  if (box.empty()) return {camera.znear, camera.zfar};
  const Box view = transformBox(box, glm::inverse(camera.cameraToWorld));
  return {std::clamp(-view.upper.z, camera.znear, camera.zfar),
          std::clamp(-view.lower.z, camera.znear, camera.zfar)};
}

}  // namespace bounce
