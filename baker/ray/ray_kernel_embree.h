// The Embree 3 backend. One device and one scene per kernel (RAII), built in explicit states:
// fill (one triangle geometry over the caller's buffers, shared, not copied) → commit (BVH
// build) → trace (const, thread-safe queries). Every thread that traces gets FTZ/DAZ set, as
// Embree requires; untraceable rays (NaN/Inf, see ray_validity.h) never reach Embree.
#pragma once

#include <embree3/rtcore.h>

#include <vector>

#include "ray/ray_kernel.h"

namespace bounce {

class EmbreeKernel final : public RayKernel {
 public:
  explicit EmbreeKernel(const WorldGeometry& geometry);
  ~EmbreeKernel() override;
  EmbreeKernel(const EmbreeKernel&) = delete;
  EmbreeKernel& operator=(const EmbreeKernel&) = delete;

  Hit intersect(const Ray& ray) const override;
  bool occluded(const Ray& ray) const override;
  // 8-wide packets (the AVX2 width); invalid rays are masked off the packet.
  void intersect(std::span<const Ray> rays, std::span<Hit> hits) const override;
  void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const override;
  const char* name() const override { return "embree"; }

 private:
  void fill();
  Hit toHit(unsigned primID, float t, float u, float v) const;

  const WorldGeometry& geometry_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  // Owned buffers only where sharing the caller's is impossible: a vertex copy when the
  // caller's vector has no spare capacity for Embree's 16-byte over-read of the last vertex;
  // a compacted index list (with its map back to WorldGeometry::triangles) when degenerate
  // triangles must be left out.
  std::vector<float> paddedPositions_;
  std::vector<glm::uvec3> keptTriangles_;
  std::vector<uint32_t> keptToWorld_;
};

}  // namespace bounce
