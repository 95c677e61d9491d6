// A bounding volume hierarchy over boxes, built with the binned surface area heuristic (SAH).
//
// Layout: nodes in depth-first order; an interior node's first child directly follows it, its
// second child is at `offset`. A leaf lists `count` primitives starting at `offset` in
// Bvh::primitives. Each node is 32 bytes, two to a 64-byte cache line:
//
//   | lower.x lower.y lower.z | offset | upper.x upper.y upper.z | count | axis | pad |
//   |        12 bytes         |   4    |        12 bytes         |   2   |  1   |  1  |
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

struct Box {
  glm::vec3 lower{std::numeric_limits<float>::infinity()};
  glm::vec3 upper{-std::numeric_limits<float>::infinity()};

  void grow(glm::vec3 p) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
  void grow(const Box& b) {
    lower = glm::min(lower, b.lower);
    upper = glm::max(upper, b.upper);
  }
  bool empty() const { return lower.x > upper.x; }
  glm::vec3 centre() const { return 0.5f * (lower + upper); }
  // Surface area in m² (0 for an empty box); proportional to the chance a random ray hits it.
  float surfaceArea() const {
    if (empty()) return 0.0f;
    const glm::vec3 d = upper - lower;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

struct BvhNode {
  glm::vec3 lower;
  uint32_t offset;  // leaf: first index into Bvh::primitives; interior: second child's index
  glm::vec3 upper;
  uint16_t count;  // primitives in a leaf; 0 for an interior node
  uint8_t axis;    // interior: the split axis (0 x, 1 y, 2 z), for near-child-first traversal
  uint8_t pad = 0;

  bool isLeaf() const { return count > 0; }
};
static_assert(sizeof(BvhNode) == 32, "two nodes per cache line");

// No root-to-leaf path is longer than this (traversal stacks are sized by it).
inline constexpr int kBvhMaxDepth = 128;

struct BvhBuildOptions {
  int bins = 16;               // SAH bins per axis (bins − 1 candidate planes on each of x, y, z)
  int maxLeafSize = 8;         // ≤ 65535 (BvhNode::count)
  float traversalCost = 1.0f;  // SAH cost of visiting one node, relative to...
  float intersectionCost = 1.0f;  // ...the cost of one primitive test
};

struct Bvh {
  std::vector<BvhNode> nodes;        // nodes[0] is the root (empty when there is nothing)
  std::vector<uint32_t> primitives;  // the caller's primitive ids in leaf order
};

// Builds over primitives with bounds `boxes[i]` and ids `ids[i]` (the same length). The
// result does not depend on thread timing: the same input gives the same tree.
Bvh buildBvh(std::span<const Box> boxes, std::span<const uint32_t> ids,
             const BvhBuildOptions& options = {});

}  // namespace bounce
