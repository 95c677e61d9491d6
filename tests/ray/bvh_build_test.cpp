// Structural invariants of the SAH build: every primitive in exactly one leaf, children inside
// their parent, leaves within the size limit, bounded depth, and the same tree for the same
// input whatever the thread schedule.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "ray/bvh.h"

namespace bounce {
namespace {

bool contains(const BvhNode& outer, const BvhNode& inner) {
  return glm::all(glm::lessThanEqual(outer.lower(), inner.lower())) &&
         glm::all(glm::greaterThanEqual(outer.upper(), inner.upper()));
}

// Walks the tree; returns its depth and checks each invariant on the way.
int checkNode(const Bvh& bvh, const std::vector<Box>& boxes, uint32_t index, std::vector<int>& seen,
              int maxLeafSize) {
  const BvhNode& node = bvh.nodes.at(index);
  if (node.isLeaf()) {
    EXPECT_LE(node.count, maxLeafSize);
    for (uint32_t i = node.offset; i < node.offset + node.count; ++i) {
      const uint32_t id = bvh.primitives.at(i);
      ++seen.at(id);
      EXPECT_TRUE(glm::all(glm::lessThanEqual(node.lower(), boxes[id].lower)) &&
                  glm::all(glm::greaterThanEqual(node.upper(), boxes[id].upper)));
    }
    return 1;
  }
  const uint32_t first = node.offset, second = node.offset + 1;
  EXPECT_GT(first, index);
  EXPECT_EQ(first % 2, 0u);  // pairs share a cache line
  EXPECT_EQ(reinterpret_cast<uintptr_t>(&bvh.nodes[first]) % 64, 0u);
  EXPECT_LE(node.offset + 2u * node.treeletPairs, bvh.nodes.size());  // prefetches stay inside
  EXPECT_TRUE(contains(node, bvh.nodes.at(first)) && contains(node, bvh.nodes.at(second)));
  return 1 + std::max(checkNode(bvh, boxes, first, seen, maxLeafSize),
                      checkNode(bvh, boxes, second, seen, maxLeafSize));
}

void checkBvh(const std::vector<Box>& boxes, const BvhBuildOptions& options = {}) {
  std::vector<uint32_t> ids(boxes.size());
  for (uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
  const Bvh bvh = buildBvh(boxes, ids, options);
  std::vector<int> seen(boxes.size(), 0);
  const int depth = checkNode(bvh, boxes, 0, seen, options.maxLeafSize);
  EXPECT_LE(depth, kBvhMaxDepth);
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(boxes.size()));

  const Bvh again = buildBvh(boxes, ids, options);  // parallel build: same bytes again
  ASSERT_EQ(again.nodes.size(), bvh.nodes.size());
  EXPECT_EQ(std::memcmp(again.nodes.data(), bvh.nodes.data(), bvh.nodes.size() * sizeof(BvhNode)),
            0);
  EXPECT_EQ(again.primitives, bvh.primitives);
}

Box boxAround(glm::vec3 p, float halfSize) {
  Box b;
  b.grow(p - halfSize);
  b.grow(p + halfSize);
  return b;
}

TEST(BvhBuild, RandomBoxesLargeEnoughForParallelBuild) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f);
  std::vector<Box> boxes;
  for (int i = 0; i < 150000; ++i) boxes.push_back(boxAround({u(rng), u(rng), u(rng)}, 0.05f));
  checkBvh(boxes);
}

TEST(BvhBuild, CoincidentCentresAreSplitByCount) {
  std::vector<Box> boxes(20000, boxAround({1, 2, 3}, 0.5f));
  checkBvh(boxes, BvhBuildOptions{.maxLeafSize = 4});
}

TEST(BvhBuild, GeometricallyGrowingSpacingKeepsTheDepthBounded) {
  // Positions 2^k·1e-30: SAH would peel off one primitive per level.
  std::vector<Box> boxes;
  float x = 1e-30f;
  for (int i = 0; i < 200; ++i, x *= 1.9f) boxes.push_back(boxAround({x, 0, 0}, 0.0f));
  checkBvh(boxes, BvhBuildOptions{.maxLeafSize = 1});
}

TEST(BvhBuild, EmptyAndSingle) {
  EXPECT_TRUE(buildBvh({}, {}).nodes.empty());
  checkBvh({boxAround({0, 0, 0}, 1.0f)});
}

}  // namespace
}  // namespace bounce
