#include "ray/ray_kernel_bvh.h"

#include <algorithm>
#include <cmath>

#include "ray/ray_validity.h"
#include "ray/triangle_checks.h"
#include "ray/watertight_triangle.h"

namespace bounce {
namespace {

// Slab test constants per ray. A zero direction component would give 0·∞ = NaN in the slab
// test when the origin lies on a slab plane; replacing it by ±1e-30 keeps 1/d finite (±1e30)
// and the ray still parallel to that axis for any scene smaller than 1e8 m.
struct SlabRay {
  float origin[3], inverseDirection[3];
  int negative[3];  // 1 where the direction is negative: the ray enters through bounds[1]

  explicit SlabRay(const Ray& ray) : origin{ray.origin.x, ray.origin.y, ray.origin.z} {
    const float d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    for (int k = 0; k < 3; ++k) {
      const float safe = std::abs(d[k]) < 1e-30f ? std::copysign(1e-30f, d[k]) : d[k];
      inverseDirection[k] = 1.0f / safe;
      negative[k] = inverseDirection[k] < 0.0f ? 1 : 0;
    }
  }
};

// The far distance of each slab is enlarged by 2·γ(3) (pbrt's rounding bound for the three
// operations that compute it) so that rounding never culls a box the ray touches, which would
// let rays slip through edges that lie on box faces.
constexpr float kSlabFarScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

// Whether the ray meets the node's box within [tmin, tmax]; `entry` is where it enters.
inline bool hitsBox(const BvhNode& node, const SlabRay& r, float tmin, float tmax, float& entry) {
  float near = tmin, far = tmax;
  for (int k = 0; k < 3; ++k) {
    const float in = (node.bounds[r.negative[k]][k] - r.origin[k]) * r.inverseDirection[k];
    const float out = (node.bounds[1 - r.negative[k]][k] - r.origin[k]) * r.inverseDirection[k];
    near = std::max(near, in);
    far = std::min(far, out * kSlabFarScale);
  }
  entry = near;
  return near <= far;
}

}  // namespace

BvhKernel::BvhKernel(const WorldGeometry& geometry, const BvhBuildOptions& options)
    : geometry_(geometry) {
  std::vector<Box> boxes;
  std::vector<uint32_t> ids;
  boxes.reserve(geometry.triangles.size());
  ids.reserve(geometry.triangles.size());
  for (std::size_t t = 0; t < geometry.triangles.size(); ++t) {
    if (!isHittableTriangle(geometry, t)) continue;  // degenerate triangles never hit
    Box box;
    for (int k = 0; k < 3; ++k) box.grow(geometry.positions[geometry.triangles[t][k]]);
    boxes.push_back(box);
    ids.push_back(static_cast<uint32_t>(t));
  }
  bvh_ = buildBvh(boxes, ids, options);
  triangles_.reserve(bvh_.primitives.size());
  for (const uint32_t t : bvh_.primitives) {
    const glm::uvec3 tri = geometry.triangles[t];
    triangles_.push_back(LeafTriangle{geometry.positions[tri.x], geometry.positions[tri.y],
                                      geometry.positions[tri.z]});
  }
}

// Returns the leaf-order index of the closest (or, kAnyHit, of any) triangle within the
// ray's interval, kNoHit otherwise. At an interior node both children's boxes are tested;
// the nearer one (by entry distance) is visited first and the farther one is pushed with its
// entry distance, so that it is skipped on its turn if a closer hit has been found meanwhile.
template <bool kAnyHit>
uint32_t BvhKernel::traverse(const Ray& ray, float& t, float& u, float& v) const {
  const SlabRay slab(ray);
  const ShearedRay sheared(ray);
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  uint32_t found = kNoHit;

  struct Pending {
    uint32_t node;
    float entry;
  };
  Pending stack[kBvhMaxDepth];
  int stackSize = 0;
  float rootEntry = 0.0f;
  if (bvh_.nodes.empty() || !hitsBox(bvh_.nodes[0], slab, tmin, tmax, rootEntry)) return kNoHit;
  uint32_t current = 0;
  for (;;) {
    const BvhNode& node = bvh_.nodes[current];
    if (!node.isLeaf()) {
      for (uint32_t pair = 1; pair < node.treeletPairs; ++pair)  // the deeper levels' lines
        __builtin_prefetch(&bvh_.nodes[node.offset + 2 * pair]);
      uint32_t near = node.offset, far = node.offset + 1;
      float nearEntry = 0.0f, farEntry = 0.0f;
      const bool hitNear = hitsBox(bvh_.nodes[near], slab, tmin, tmax, nearEntry);
      const bool hitFar = hitsBox(bvh_.nodes[far], slab, tmin, tmax, farEntry);
      if (hitNear && hitFar) {
        if (farEntry < nearEntry) std::swap(near, far), std::swap(nearEntry, farEntry);
        stack[stackSize++] = Pending{far, farEntry};
        prefetch(bvh_.nodes[far]);
        current = near;
        continue;
      }
      if (hitNear || hitFar) {
        current = hitNear ? near : far;
        continue;
      }
    } else {
      for (uint32_t i = node.offset; i < node.offset + node.count; ++i) {
        const LeafTriangle& tri = triangles_[i];
        TriangleHit hit;
        if (!intersectTriangle(sheared, tri.p0, tri.p1, tri.p2, tmin, tmax, hit)) continue;
        found = i;
        if constexpr (kAnyHit) return found;
        tmax = hit.t;
        u = hit.u;
        v = hit.v;
      }
    }
    // Next: the nearest pending subtree that still starts before the closest hit so far.
    do {
      if (stackSize == 0) {
        t = tmax;
        return found;
      }
      --stackSize;
    } while (stack[stackSize].entry > tmax);
    current = stack[stackSize].node;
  }
}

Hit BvhKernel::intersect(const Ray& ray) const {
  if (!isTraceable(ray)) return {};
  Hit hit;
  const uint32_t found = traverse<false>(ray, hit.t, hit.u, hit.v);
  if (found == kNoHit) return {};
  hit.triangle = bvh_.primitives[found];
  hit.geometricNormal = glm::normalize(geometry_.triangleCross(hit.triangle));
  return hit;
}

bool BvhKernel::occluded(const Ray& ray) const {
  if (!isTraceable(ray)) return false;
  float t = 0.0f, u = 0.0f, v = 0.0f;
  return traverse<true>(ray, t, u, v) != kNoHit;
}

}  // namespace bounce
