#include "layout_checks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "atlas/uv_geometry.h"

namespace bounce::test {
namespace {

glm::vec2 atlasSize(const Atlas& atlas) {
  return {static_cast<float>(atlas.layout.width), static_cast<float>(atlas.layout.height)};
}

// Calls visit(chart, texel) for every texel every triangle touches.
template <class Visit>
void forEachTexel(const Atlas& atlas, Visit&& visit) {
  const glm::vec2 size = atlasSize(atlas);
  for (std::size_t r = 0; r < atlas.layout.instances.size(); ++r) {
    const auto& uv = atlas.layout.instances[r].cornerUv;
    for (std::size_t t = 0; 3 * t < uv.size(); ++t)
      forEachTouchedTexel(uv[3 * t] * size, uv[3 * t + 1] * size, uv[3 * t + 2] * size,
                          atlas.layout.width, atlas.layout.height,
                          [&](int x, int y) { visit(atlas.triangleChart[r][t], x, y); });
  }
}

}  // namespace

std::string regionProblem(const Scene& scene, const Atlas& atlas) {
  std::ostringstream problem;
  const LightmapLayout& layout = atlas.layout;
  if (atlas.triangleChart.size() != layout.instances.size())
    return "triangleChart is not parallel to the layout's instances";
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    const std::size_t triangles = scene.meshes[instance.mesh].triangleCount();
    const InstanceLightmapUv* region = layout.find(i);
    const bool vplLit = std::find(atlas.vplLitInstances.begin(), atlas.vplLitInstances.end(), i) !=
                        atlas.vplLitInstances.end();
    const bool wanted = instance.mobility == Mobility::Static && triangles > 0 && !vplLit;
    if (wanted != (region != nullptr)) {
      problem << "instance " << i << (wanted ? " has no region" : " has a region");
      return problem.str();
    }
    if (!region) continue;
    if (region->cornerUv.size() != 3 * triangles) {
      problem << "instance " << i << " has " << region->cornerUv.size() << " UVs for " << triangles
              << " triangles";
      return problem.str();
    }
    const std::size_t slot = static_cast<std::size_t>(region - layout.instances.data());
    for (std::size_t t = 0; t < triangles; ++t)
      if (atlas.triangleChart[slot][t] >= static_cast<uint32_t>(layout.chartCount)) {
        problem << "instance " << i << " triangle " << t << " has chart id out of range";
        return problem.str();
      }
    for (const glm::vec2 uv : region->cornerUv)
      if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
        problem << "instance " << i << " has UV (" << uv.x << ", " << uv.y << ") outside [0,1]";
        return problem.str();
      }
  }
  return "";
}

std::string overlapProblem(const Atlas& atlas) {
  std::ostringstream problem;
  const glm::vec2 size = atlasSize(atlas);
  // Within a chart: the exact test, per chart.
  std::map<uint32_t, std::vector<glm::vec2>> chartUv;
  for (std::size_t r = 0; r < atlas.layout.instances.size(); ++r) {
    const auto& uv = atlas.layout.instances[r].cornerUv;
    for (std::size_t t = 0; 3 * t < uv.size(); ++t)
      for (int k = 0; k < 3; ++k)
        chartUv[atlas.triangleChart[r][t]].push_back(uv[3 * t + k] * size);
  }
  for (const auto& [chart, uv] : chartUv)
    if (const auto pair = findOverlappingTriangles(uv, 1e-3f)) {
      problem << "chart " << chart << ": its triangles " << pair->first << " and " << pair->second
              << " overlap";
      return problem.str();
    }
  // Between charts: texel sets kept `padding` texels apart.
  const int w = atlas.layout.width, h = atlas.layout.height, pad = atlas.layout.padding;
  std::vector<int64_t> owner(static_cast<std::size_t>(w) * h, -1);
  std::string found;
  forEachTexel(atlas, [&](uint32_t chart, int x, int y) {
    if (!found.empty()) return;
    for (int yy = std::max(0, y - pad); yy <= std::min(h - 1, y + pad); ++yy)
      for (int xx = std::max(0, x - pad); xx <= std::min(w - 1, x + pad); ++xx) {
        const int64_t other = owner[static_cast<std::size_t>(yy) * w + xx];
        if (other >= 0 && other != chart) {
          std::ostringstream s;
          s << "texel (" << x << ", " << y << ") of chart " << chart << " is within " << pad
            << " texels of texel (" << xx << ", " << yy << ") of chart " << other;
          found = s.str();
          return;
        }
      }
    owner[static_cast<std::size_t>(y) * w + x] = chart;
  });
  return found;
}

double recountUtilisation(const Atlas& atlas) {
  const int w = atlas.layout.width, h = atlas.layout.height;
  if (w == 0 || h == 0) return 0.0;
  std::vector<uint8_t> covered(static_cast<std::size_t>(w) * h, 0);
  forEachTexel(atlas,
               [&](uint32_t, int x, int y) { covered[static_cast<std::size_t>(y) * w + x] = 1; });
  std::size_t count = 0;
  for (const uint8_t c : covered) count += c;
  return static_cast<double>(count) / static_cast<double>(covered.size());
}

}  // namespace bounce::test
