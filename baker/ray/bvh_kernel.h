// bounce's own BVH backend (binned SAH build, ordered traversal, watertight triangles).
#pragma once

#include <stdexcept>

#include "ray/ray_kernel.h"

namespace bounce {

class BvhKernel final : public RayKernel {
 public:
  explicit BvhKernel(const WorldGeometry&) {
    throw std::runtime_error("the 'bvh' ray backend is not built yet; use 'embree'");
  }
  using RayKernel::intersect;
  using RayKernel::occluded;
  Hit intersect(const Ray&) const override { return {}; }
  bool occluded(const Ray&) const override { return false; }
  const char* name() const override { return "bvh"; }
};

}  // namespace bounce
