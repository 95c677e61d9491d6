#include "trace/emitters.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "scene/surface_rules.h"
#include "trace/sampling.h"

namespace bounce {

namespace {

glm::vec3 centroid(const WorldGeometry& geometry, uint32_t t) {
  const glm::uvec3 tri = geometry.triangles[t];
  return (geometry.positions[tri.x] + geometry.positions[tri.y] + geometry.positions[tri.z]) / 3.0f;
}

}  // namespace

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
  if (weights.empty()) return;
  table_ = AliasTable(weights);
  buildClusters(weights);
}

void EmitterTable::buildClusters(const std::vector<double>& weights) {
  // Each cluster as the emitters it holds and its bounding sphere; the widest is split next.
  std::vector<uint32_t> all(triangles_.size());
  std::iota(all.begin(), all.end(), 0u);
  std::vector<std::vector<uint32_t>> groups;
  groups.push_back(std::move(all));
  const auto sphere = [&](const std::vector<uint32_t>& members) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (uint32_t e : members) {
      const glm::uvec3 tri = geometry_.triangles[triangles_[e]];
      for (uint32_t v : {tri.x, tri.y, tri.z}) {
        lo = glm::min(lo, geometry_.positions[v]);
        hi = glm::max(hi, geometry_.positions[v]);
      }
    }
    EmitterCluster c;
    c.centre = 0.5f * (lo + hi);
    for (uint32_t e : members) {
      const glm::uvec3 tri = geometry_.triangles[triangles_[e]];
      for (uint32_t v : {tri.x, tri.y, tri.z}) {
        c.radius = std::max(c.radius, glm::length(geometry_.positions[v] - c.centre));
      }
    }
    for (uint32_t e : members) c.power += kPi * weights[e];
    return c;
  };
  std::vector<EmitterCluster> spheres{sphere(groups[0])};
  while (groups.size() < kMaxEmitterClusters) {
    std::size_t widest = groups.size();
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (groups[g].size() > 1 &&
          (widest == groups.size() || spheres[g].radius > spheres[widest].radius)) {
        widest = g;
      }
    }
    if (widest == groups.size()) break;
    std::vector<uint32_t>& members = groups[widest];
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (uint32_t e : members) {
      lo = glm::min(lo, centroid(geometry_, triangles_[e]));
      hi = glm::max(hi, centroid(geometry_, triangles_[e]));
    }
    const glm::vec3 extent = hi - lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto half = members.begin() + static_cast<std::ptrdiff_t>(members.size() / 2);
    // Ties broken by emitter index, so the split does not depend on the sort's order.
    std::nth_element(members.begin(), half, members.end(), [&](uint32_t a, uint32_t b) {
      const float ca = centroid(geometry_, triangles_[a])[axis];
      const float cb = centroid(geometry_, triangles_[b])[axis];
      return ca < cb || (ca == cb && a < b);
    });
    std::vector<uint32_t> upper(half, members.end());
    members.erase(half, members.end());
    std::sort(members.begin(), members.end());
    std::sort(upper.begin(), upper.end());
    spheres[widest] = sphere(members);
    spheres.push_back(sphere(upper));
    groups.push_back(std::move(upper));
  }
  clusters_ = std::move(spheres);
  clusterOf_.assign(triangles_.size(), 0);
  slotInCluster_.assign(triangles_.size(), 0);
  for (uint32_t c = 0; c < groups.size(); ++c) {
    std::vector<double> w;
    for (uint32_t i = 0; i < groups[c].size(); ++i) {
      clusterOf_[groups[c][i]] = c;
      slotInCluster_[groups[c][i]] = i;
      w.push_back(weights[groups[c][i]]);
    }
    clusterTables_.emplace_back(w);
  }
  clusterMembers_ = std::move(groups);
}

EmitterSample EmitterTable::sampleEmitter(uint32_t e, glm::vec2 v) const {
  const uint32_t t = triangles_[e];
  const glm::uvec3 tri = geometry_.triangles[t];
  const glm::vec2 b = sampleUniformTriangle(v);
  EmitterSample s;
  s.position = (1.0f - b.x - b.y) * geometry_.positions[tri.x] + b.x * geometry_.positions[tri.y] +
               b.y * geometry_.positions[tri.z];
  s.normal = normals_[e];
  s.radiance = radiance_[e];
  s.doubleSided = doubleSided_[e] != 0;
  s.triangle = t;
  return s;
}

EmitterSample EmitterTable::sample(glm::vec2 u, glm::vec2 v) const {
  const uint32_t e = table_.sample(u);
  EmitterSample s = sampleEmitter(e, v);
  s.pdfArea = table_.pmf(e) / areas_[e];
  return s;
}

float EmitterTable::pdfArea(uint32_t triangle) const {
  if (triangle >= emitterOfTriangle_.size()) return 0.0f;
  const uint32_t e = emitterOfTriangle_[triangle];
  return e == kNone ? 0.0f : table_.pmf(e) / areas_[e];
}

EmitterSample EmitterTable::sampleCluster(uint32_t c, glm::vec2 u, glm::vec2 v) const {
  const uint32_t slot = clusterTables_[c].sample(u);
  const uint32_t e = clusterMembers_[c][slot];
  EmitterSample s = sampleEmitter(e, v);
  s.pdfArea = clusterTables_[c].pmf(slot) / areas_[e];
  return s;
}

EmitterTable::InCluster EmitterTable::inCluster(uint32_t triangle) const {
  if (triangle >= emitterOfTriangle_.size()) return {};
  const uint32_t e = emitterOfTriangle_[triangle];
  if (e == kNone) return {};
  const uint32_t c = clusterOf_[e];
  return {c, clusterTables_[c].pmf(slotInCluster_[e]) / areas_[e]};
}

}  // namespace bounce
