#include "trace/emitters.h"

#include <cmath>

#include "scene/surface_rules.h"
#include "trace/sampling.h"

namespace bounce {

EmitterTable::EmitterTable(const Scene& scene, const WorldGeometry& geometry)
    : geometry_(geometry), emitterOfTriangle_(geometry.triangleCount(), kNone) {
  std::vector<double> weights;
  for (uint32_t t = 0; t < geometry.triangleCount(); ++t) {
    const Material& material = materialOf(scene, geometry.triangleMaterial[t]);
    if (!isEmitterTriangle(material, geometry.triangleCross(t))) continue;
    const float area = 0.5f * glm::length(geometry.triangleCross(t));
    const glm::vec3 le = emittedRadiance(material);
    const float sides = material.doubleSided ? 2.0f : 1.0f;
    // Sampling weight ∝ flux π·A·luminance(Le) (×2 double-sided); the π cancels.
    const double weight = static_cast<double>(area) * sides * static_cast<double>(luminance(le));
    if (!(weight > 0.0) || !std::isfinite(weight)) continue;
    emitterOfTriangle_[t] = static_cast<uint32_t>(triangles_.size());
    triangles_.push_back(t);
    areas_.push_back(area);
    normals_.push_back(glm::normalize(geometry.triangleCross(t)));
    radiance_.push_back(le);
    doubleSided_.push_back(material.doubleSided ? 1 : 0);
    weights.push_back(weight);
    power_ += kPi * area * sides * le;
  }
  if (!weights.empty()) table_ = AliasTable(weights);
}

EmitterSample EmitterTable::sample(glm::vec2 u, glm::vec2 v) const {
  const uint32_t e = table_.sample(u);
  const uint32_t t = triangles_[e];
  const glm::uvec3 tri = geometry_.triangles[t];
  const glm::vec2 b = sampleUniformTriangle(v);
  EmitterSample s;
  s.position = (1.0f - b.x - b.y) * geometry_.positions[tri.x] + b.x * geometry_.positions[tri.y] +
               b.y * geometry_.positions[tri.z];
  s.normal = normals_[e];
  s.radiance = radiance_[e];
  s.doubleSided = doubleSided_[e] != 0;
  s.pdfArea = table_.pmf(e) / areas_[e];
  s.triangle = t;
  return s;
}

float EmitterTable::pdfArea(uint32_t triangle) const {
  if (triangle >= emitterOfTriangle_.size()) return 0.0f;
  const uint32_t e = emitterOfTriangle_[triangle];
  return e == kNone ? 0.0f : table_.pmf(e) / areas_[e];
}

}  // namespace bounce
