// Area emitters: the triangles whose material emits. One is chosen with probability
// proportional to its power Φ ∝ area × luminance(Le) (× 2 when double-sided), then a point
// uniformly on it, so the area density of a sampled point is pmf(triangle) / area.
// Which triangles emit, and their Le, is scene/surface_rules.h's rule (isEmitterTriangle,
// emittedRadiance), shared with the renderer.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/alias_table.h"

namespace bounce {

struct EmitterSample {
  glm::vec3 position{0.0f};  // world, metres
  glm::vec3 normal{0.0f};    // unit geometric normal of the front face
  glm::vec3 radiance{0.0f};  // Le, W/(sr·m²)
  bool doubleSided = false;
  float pdfArea = 0.0f;  // per m² of the whole emitter set (pmf / triangle area)
  uint32_t triangle = 0;
};

class EmitterTable {
 public:
  EmitterTable(const Scene& scene, const WorldGeometry& geometry);

  bool empty() const { return triangles_.empty(); }
  std::size_t size() const { return triangles_.size(); }
  // Total emitted flux Σ π·A·Le (×2 double-sided), W per channel.
  glm::vec3 power() const { return power_; }

  // u picks the triangle (alias table), v the point on it.
  EmitterSample sample(glm::vec2 u, glm::vec2 v) const;
  // Area density with which sample() produces a point on `triangle` (0 when not an emitter).
  float pdfArea(uint32_t triangle) const;

 private:
  const WorldGeometry& geometry_;
  std::vector<uint32_t> triangles_;  // emitter index -> triangle
  std::vector<float> areas_;         // m²
  std::vector<glm::vec3> normals_;   // unit front-face normals
  std::vector<glm::vec3> radiance_;  // Le
  std::vector<uint8_t> doubleSided_;
  std::vector<uint32_t> emitterOfTriangle_;  // triangle -> emitter index or kNone
  AliasTable table_;
  glm::vec3 power_{0.0f};

  static constexpr uint32_t kNone = 0xffffffffu;
};

}  // namespace bounce
