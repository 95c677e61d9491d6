// Which surface each pixel of a camera image sees, found with the baker's ray kernel (not the
// renderer under test): for masks in renderer-vs-tracer comparisons and for classifying pixel
// pairs by lightmap chart in the seam measurement.
#pragma once

#include <cstdint>
#include <vector>

#include "bake_folder/lightmap_charts.h"
#include "bake_folder/lightmap_layout.h"
#include "image/image_compare.h"
#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/camera_render.h"

namespace bounce::test {

inline constexpr uint32_t kNoChart = 0xffffffffu;

struct PixelSurfaces {
  int width = 0, height = 0;
  std::vector<uint32_t> triangle;  // world triangle hit by the pixel-centre ray, or kNoHit
  // The pixel's whole square sees one flat piece of one instance: rays through its centre and
  // four points near its corners hit the same instance with geometric normals within ~8°.
  // (The tracer box-filters over the square; the rasterizer samples its centre: only such
  // pixels compare.)
  std::vector<uint8_t> interior;
};

inline PixelSurfaces findPixelSurfaces(const WorldGeometry& geometry, const RayKernel& kernel,
                                       const Camera& camera, int width, int height) {
  PixelSurfaces s;
  s.width = width, s.height = height;
  s.triangle.assign(static_cast<std::size_t>(width) * height, kNoHit);
  s.interior.assign(s.triangle.size(), 0);
  constexpr float kInset = 0.02f;
  const float offsets[5][2] = {{0.5f, 0.5f},
                               {kInset, kInset},
                               {1 - kInset, kInset},
                               {kInset, 1 - kInset},
                               {1 - kInset, 1 - kInset}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      Hit hits[5];
      for (int k = 0; k < 5; ++k)
        hits[k] = kernel.intersect(
            cameraRay(camera, width, height, x + offsets[k][0], y + offsets[k][1]));
      s.triangle[i] = hits[0].triangle;
      bool same = hits[0].valid();
      for (int k = 1; k < 5 && same; ++k)
        same = hits[k].valid() &&
               geometry.triangleInstance[hits[k].triangle] ==
                   geometry.triangleInstance[hits[0].triangle] &&
               glm::dot(hits[k].geometricNormal, hits[0].geometricNormal) > 0.99f;
      s.interior[i] = same ? 1 : 0;
    }
  return s;
}

// Pixels to compare the indirect frame on: interior pixels of static, non-emissive surfaces.
inline Mask staticSurfaceMask(const Scene& scene, const WorldGeometry& geometry,
                              const PixelSurfaces& surfaces) {
  Mask mask{surfaces.width, surfaces.height, std::vector<uint8_t>(surfaces.triangle.size(), 0)};
  for (std::size_t i = 0; i < mask.keep.size(); ++i) {
    if (!surfaces.interior[i]) continue;
    const uint32_t t = surfaces.triangle[i];
    const Material& m = scene.materials.at(geometry.triangleMaterial[t]);
    const Instance& instance = scene.instances.at(geometry.triangleInstance[t]);
    mask.keep[i] = !m.isEmissive() && instance.mobility == Mobility::Static;
  }
  return mask;
}

// The lightmap chart of every pixel's centre hit (kNoChart: no hit or no atlas region).
// flatten() lays the instances' triangles out one after another, each in its mesh's order.
inline std::vector<uint32_t> pixelCharts(const Scene& scene, const WorldGeometry& geometry,
                                         const LightmapLayout& layout, const LightmapCharts& charts,
                                         const PixelSurfaces& surfaces) {
  std::vector<uint32_t> firstTriangle(scene.instances.size(), 0);
  for (std::size_t t = geometry.triangleCount(); t-- > 0;)
    firstTriangle[geometry.triangleInstance[t]] = static_cast<uint32_t>(t);
  std::vector<int> region(scene.instances.size(), -1);
  for (std::size_t r = 0; r < layout.instances.size(); ++r)
    region[layout.instances[r].instance] = static_cast<int>(r);
  std::vector<uint32_t> chart(surfaces.triangle.size(), kNoChart);
  for (std::size_t i = 0; i < chart.size(); ++i) {
    const uint32_t t = surfaces.triangle[i];
    if (t == kNoHit) continue;
    const uint32_t instance = geometry.triangleInstance[t];
    if (region[instance] < 0) continue;
    chart[i] =
        charts
            .triangleChart[static_cast<std::size_t>(region[instance])][t - firstTriangle[instance]];
  }
  return chart;
}

}  // namespace bounce::test
