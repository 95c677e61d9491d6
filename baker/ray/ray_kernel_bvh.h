// bounce's own ray kernel backend: a binned-SAH BVH (bvh.h) over the scene's non-degenerate
// triangles, traversed near child first with a slab test per node and the watertight
// triangle test (watertight_triangle.h) in the leaves. Scalar, one ray at a time: it is the
// portable fallback and the cross-check for Embree, written to be read.
#pragma once

#include <vector>

#include "ray/bvh.h"
#include "ray/ray_kernel.h"

namespace bounce {

class BvhKernel final : public RayKernel {
 public:
  explicit BvhKernel(const WorldGeometry& geometry, const BvhBuildOptions& options = {});

  using RayKernel::intersect;
  using RayKernel::occluded;
  Hit intersect(const Ray& ray) const override;
  bool occluded(const Ray& ray) const override;
  const char* name() const override { return "bvh"; }

  const Bvh& bvh() const { return bvh_; }

 private:
  // A triangle's vertices, stored in leaf order so a leaf reads one contiguous block.
  struct LeafTriangle {
    glm::vec3 p0, p1, p2;
  };

  // Starts loading what visiting `node` will read first (its child pair or its leaf's
  // triangles), so that the load overlaps the traversal of the nearer subtree.
  void prefetch(const BvhNode& node) const {
    if (node.isLeaf())
      __builtin_prefetch(&triangles_[node.offset]);
    else
      __builtin_prefetch(&bvh_.nodes[node.offset]);
  }

  template <bool kAnyHit>
  uint32_t traverse(const Ray& ray, float& t, float& u, float& v) const;

  const WorldGeometry& geometry_;
  Bvh bvh_;                              // primitives: indices into WorldGeometry::triangles
  std::vector<LeafTriangle> triangles_;  // triangles_[i] = vertices of bvh_.primitives[i]
};

}  // namespace bounce
