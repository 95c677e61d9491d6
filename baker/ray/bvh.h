// A bounding volume hierarchy over boxes, built with the binned surface area heuristic (SAH).
//
// Layout: nodes[0] is the root. The two children of an interior node are stored side by side
// at `offset` and `offset + 1` (an even index); the array is 64-byte aligned, so both child
// boxes, which traversal always tests together, arrive in one cache line. A leaf lists `count`
// primitives starting at `offset` in Bvh::primitives. Each node is 32 bytes:
//
//   | lower.x lower.y lower.z | upper.x upper.y upper.z | offset | count | treeletPairs |
//   |        12 bytes         |        12 bytes         |   4    |   2   |      2       |
//
// Pairs are laid out in two-level treelets: at every other level, a node's child pair is
// directly followed by its grandchildren's pairs (treeletPairs of them in all), so traversal
// can request the cache lines of two levels at once; on a 1M-triangle scene, where every
// level is a cache miss, this made incoherent rays ~1.3x faster.
//
// bounds[0] is the lower corner, bounds[1] the upper one, so a ray picks its entry and exit
// planes per axis by index (bounds[directionIsNegative][axis]) without a branch.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scene/box.h"

namespace bounce {

struct BvhNode {
  float bounds[2][3];  // [lower, upper][x, y, z], metres
  uint32_t offset;     // leaf: first index into Bvh::primitives; interior: first child's index
  uint16_t count;      // primitives in a leaf; 0 for an interior node
  uint16_t treeletPairs = 0;  // child pairs stored from `offset` on that belong to its treelet

  bool isLeaf() const { return count > 0; }
  glm::vec3 lower() const { return {bounds[0][0], bounds[0][1], bounds[0][2]}; }
  glm::vec3 upper() const { return {bounds[1][0], bounds[1][1], bounds[1][2]}; }
};
static_assert(sizeof(BvhNode) == 32, "a pair of children per 64-byte cache line");

// No root-to-leaf path is longer than this (traversal stacks are sized by it).
inline constexpr int kBvhMaxDepth = 128;

struct BvhBuildOptions {
  int bins = 16;        // SAH bins per axis (bins − 1 candidate planes on each of x, y, z)
  int maxLeafSize = 4;  // ≤ 65535 (BvhNode::count)
  // SAH costs: visiting a node is a dependent cache miss on large scenes, worth about two
  // triangle tests (measured on the 1M-triangle benchmark scene, docs/ray_kernel.md).
  float traversalCost = 2.0f;
  float intersectionCost = 1.0f;
};

// Allocates on 64-byte (cache-line) boundaries.
template <typename T>
struct CacheLineAllocator {
  using value_type = T;
  static constexpr std::align_val_t kAlignment{64};
  CacheLineAllocator() = default;
  template <typename U>
  CacheLineAllocator(const CacheLineAllocator<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlignment)); }
  void deallocate(T* p, std::size_t) { ::operator delete(p, kAlignment); }
  bool operator==(const CacheLineAllocator&) const { return true; }
};

struct Bvh {
  // nodes[0] is the root (empty when there is nothing); nodes[1] is unused, so that every
  // child pair starts at an even index, i.e. at a cache-line boundary.
  std::vector<BvhNode, CacheLineAllocator<BvhNode>> nodes;
  std::vector<uint32_t> primitives;  // the caller's primitive ids in leaf order
};

// Builds over primitives with bounds `boxes[i]` and ids `ids[i]` (the same length). The
// result does not depend on thread timing: the same input gives the same tree.
Bvh buildBvh(std::span<const Box> boxes, std::span<const uint32_t> ids,
             const BvhBuildOptions& options = {});

}  // namespace bounce
