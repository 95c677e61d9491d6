#include "ray/bvh_kernel.h"

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
  glm::vec3 origin, inverseDirection;
  bool negative[3];

  explicit SlabRay(const Ray& ray) : origin(ray.origin) {
    for (int k = 0; k < 3; ++k) {
      const float d = ray.direction[k];
      const float safe = std::abs(d) < 1e-30f ? std::copysign(1e-30f, d) : d;
      inverseDirection[k] = 1.0f / safe;
      negative[k] = inverseDirection[k] < 0.0f;
    }
  }
};

// The far distance of each slab is enlarged by 2·γ(3) (pbrt's rounding bound for the three
// operations that compute it) so that rounding never culls a box the ray touches, which would
// let rays slip through edges that lie on box faces.
constexpr float kSlabFarScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

inline bool hitsBox(const BvhNode& node, const SlabRay& r, float tmin, float tmax) {
  float near = tmin, far = tmax;
  for (int k = 0; k < 3; ++k) {
    const float entry = r.negative[k] ? node.upper[k] : node.lower[k];
    const float exit = r.negative[k] ? node.lower[k] : node.upper[k];
    near = std::max(near, (entry - r.origin[k]) * r.inverseDirection[k]);
    far = std::min(far, (exit - r.origin[k]) * r.inverseDirection[k] * kSlabFarScale);
  }
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
// ray's interval, kNoHit otherwise. Near child first: along the split axis, the child on the
// side the ray comes from is visited first and the other is pushed; closest-hit shrinks t
// as it goes, so far subtrees beyond the current hit are culled by the box test.
template <bool kAnyHit>
uint32_t BvhKernel::traverse(const Ray& ray, float& t, float& u, float& v) const {
  if (bvh_.nodes.empty()) return kNoHit;
  const SlabRay slab(ray);
  const ShearedRay sheared(ray);
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  uint32_t found = kNoHit;

  uint32_t stack[kBvhMaxDepth];
  int stackSize = 0;
  uint32_t current = 0;
  for (;;) {
    const BvhNode& node = bvh_.nodes[current];
    if (hitsBox(node, slab, tmin, tmax)) {
      if (!node.isLeaf()) {
        const bool secondIsNear = slab.negative[node.axis];
        stack[stackSize++] = secondIsNear ? current + 1 : node.offset;
        current = secondIsNear ? node.offset : current + 1;
        continue;
      }
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
    if (stackSize == 0) break;
    current = stack[--stackSize];
  }
  t = tmax;
  return found;
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
