// Area emitters: the triangles whose material emits. One is chosen with probability
// proportional to its power Φ ∝ area × luminance(Le) (× 2 when double-sided), then a point
// uniformly on it, so the area density of a sampled point is pmf(triangle) / area.
// The triangles are also grouped by place into at most kMaxEmitterClusters clusters, each with
// its bounding sphere and power, so that a light sampler can choose a cluster by what it brings
// to a point (trace/light_sampler.h) and then a triangle in it by power.
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
  float pdfArea = 0.0f;  // per m² of the set sampled from (all emitters, or one cluster)
  uint32_t triangle = 0;
};

// Emitter triangles near one another: starting from one cluster of all of them, the cluster with
// the largest bounding sphere is split at the median of its triangles' centroids along their
// widest axis, until there are kMaxEmitterClusters or every cluster is one triangle.
struct EmitterCluster {
  glm::vec3 centre{0.0f};  // of the sphere bounding its triangles, m
  float radius = 0.0f;     // m
  double power = 0.0;      // luminance of Σ π·A·Le (× 2 double-sided), W
};

inline constexpr uint32_t kMaxEmitterClusters = 32;

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

  const std::vector<EmitterCluster>& clusters() const { return clusters_; }
  // As sample(), among cluster c's triangles only (pdfArea within the cluster).
  EmitterSample sampleCluster(uint32_t c, glm::vec2 u, glm::vec2 v) const;
  // The cluster holding `triangle` and the area density with which sampleCluster() of that
  // cluster produces a point on it; {0, 0} when not an emitter.
  struct InCluster {
    uint32_t cluster = 0;
    float pdfArea = 0.0f;
  };
  InCluster inCluster(uint32_t triangle) const;

 private:
  EmitterSample sampleEmitter(uint32_t e, glm::vec2 v) const;
  void buildClusters(const std::vector<double>& weights);

  const WorldGeometry& geometry_;
  std::vector<uint32_t> triangles_;  // emitter index -> triangle
  std::vector<float> areas_;         // m²
  std::vector<glm::vec3> normals_;   // unit front-face normals
  std::vector<glm::vec3> radiance_;  // Le
  std::vector<uint8_t> doubleSided_;
  std::vector<uint32_t> emitterOfTriangle_;  // triangle -> emitter index or kNone
  AliasTable table_;
  glm::vec3 power_{0.0f};
  // Clusters: each one's emitters (in clusterMembers_) and the alias table over them.
  std::vector<EmitterCluster> clusters_;
  std::vector<std::vector<uint32_t>> clusterMembers_;
  std::vector<AliasTable> clusterTables_;
  std::vector<uint32_t> clusterOf_, slotInCluster_;  // per emitter

  static constexpr uint32_t kNone = 0xffffffffu;
};

}  // namespace bounce
