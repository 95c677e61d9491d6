// The view's clusters (froxels): the image cut into square tiles of `tilePixels` pixels and the
// view depth d (metres along the camera's −Z) into exponential slices between `nearDepth` and
// `farDepth`,
//
//     slice(d) = clamp(floor(log(d / near) · S / log(far / near)), 0, S − 1),
//
// the same expression shaders/light_grid.glsl evaluates per fragment (with gl_FragCoord for the
// tile, pixel rows counted from the bottom as GL does). A tile edge lies on a pixel edge, so a
// pixel and every sample in it share one tile. GL-free.
//
//   cluster index = (slice · tilesY + tileY) · tilesX + tileX
//
// Clusters of the first and last slice reach only to nearDepth and farDepth: the grid is made
// around the depths the scene occupies, and a fragment just outside (rounding) is clamped into
// them; light_grid.h keeps a light in every cluster it may reach within a small padding.
#pragma once

#include <glm/glm.hpp>

#include "render/frustum.h"
#include "scene/scene.h"

namespace bounce {

struct ClusterGridSize {
  int tilesAcross = 16;  // tiles along the image's width (the tiles are square)
  int slices = 24;
};

struct ClusterGrid {
  glm::mat4 view{1.0f};        // world → view (camera looks down −Z)
  glm::vec2 tanHalfFov{1.0f};  // view x/d and y/d at the image's right and top edges
  int width = 1, height = 1;   // pixels
  int tilePixels = 1;
  int tilesX = 1, tilesY = 1, slices = 1;
  float nearDepth = 0.01f, farDepth = 1.0f;  // metres

  int count() const { return tilesX * tilesY * slices; }
  int index(int x, int y, int s) const { return (s * tilesY + y) * tilesX + x; }
  // S / log(far/near) and −log(near) · S / log(far/near): slice(d) = floor(log(d)·a + b).
  glm::vec2 sliceScaleBias() const;
  int sliceOf(float depth) const;
  float sliceDepth(int s) const;  // the near depth of slice s; s = slices gives farDepth
  // The view-space box around cluster (x, y, s), padded by a relative 1e-4 of its size and depth.
  Box clusterBox(int x, int y, int s) const;
};

// The grid of `camera` for a width × height image, its slices spanning the view depths
// [nearDepth, farDepth] (clamped to the camera's znear..zfar).
ClusterGrid makeClusterGrid(const Camera& camera, int width, int height, float nearDepth,
                            float farDepth, ClusterGridSize size = {});

// The range of view depths `box` (world) covers, clamped to the camera's znear..zfar; {znear,
// zfar} when the box is empty.
glm::vec2 viewDepthRange(const Camera& camera, const Box& box);

}  // namespace bounce
