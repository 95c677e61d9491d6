// Binned SAH build (Wald 2007; the structure follows pbrt-v4's BVHAggregate). Each node bins
// its primitives' centres into `bins` slabs per axis, evaluates the SAH cost
//   C(split) = traversalCost + intersectionCost · (A_L·N_L + A_R·N_R) / A
// at every bin boundary, and splits at the cheapest one unless a leaf (intersectionCost · N)
// is cheaper and small enough. Subtrees build in parallel; because each node's primitives are
// partitioned in place and the tree is flattened afterwards (in treelets, see bvh.h), the result
// is identical for any thread schedule.
#include <tbb/blocked_range.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <stdexcept>

#include "ray/bvh.h"

namespace bounce {
namespace {

struct BuildPrimitive {
  Box box;
  glm::vec3 centre;
  uint32_t id;
};

struct BuildNode {
  Box box;
  uint32_t first = 0, count = 0;  // leaf: its range in the primitive array
  std::unique_ptr<BuildNode> children[2];
};

constexpr int kMaxBins = 64;
constexpr std::size_t kParallelSubtree = 4096;  // fewer primitives: build on this thread
constexpr std::size_t kParallelBinning = 65536;
constexpr int kTreeletDepth = 2;  // levels of child pairs stored together (bvh.h)
// Below this depth SAH chooses the planes; deeper nodes (only reached by pathological inputs
// where SAH keeps peeling off a few primitives) split at the median, so the tree depth stays
// under kMaxSahDepth + 32 = kBvhMaxDepth.
constexpr int kMaxSahDepth = kBvhMaxDepth - 32;

struct Bin {
  Box box;
  uint32_t count = 0;
};

// Bins of all three axes for one node; min/max and integer counts make the reduction exact,
// so a parallel reduction gives the same bins as a serial loop.
struct Binning {
  std::array<std::array<Bin, kMaxBins>, 3> bins{};

  void add(const BuildPrimitive& p, const Box& centres, int binCount) {
    for (int axis = 0; axis < 3; ++axis) {
      Bin& bin = bins[axis][binIndex(p.centre, centres, axis, binCount)];
      bin.box.grow(p.box);
      ++bin.count;
    }
  }
  void merge(const Binning& other, int binCount) {
    for (int axis = 0; axis < 3; ++axis)
      for (int b = 0; b < binCount; ++b) {
        bins[axis][b].box.grow(other.bins[axis][b].box);
        bins[axis][b].count += other.bins[axis][b].count;
      }
  }
  static int binIndex(glm::vec3 centre, const Box& centres, int axis, int binCount) {
    const float extent = centres.upper[axis] - centres.lower[axis];
    if (!(extent > 0.0f)) return 0;
    const int b = static_cast<int>(binCount * ((centre[axis] - centres.lower[axis]) / extent));
    return std::clamp(b, 0, binCount - 1);
  }
};

class Builder {
 public:
  Builder(std::vector<BuildPrimitive>& primitives, const BvhBuildOptions& options)
      : primitives_(primitives), options_(options) {}

  std::unique_ptr<BuildNode> build(uint32_t first, uint32_t count, int depth) {
    auto node = std::make_unique<BuildNode>();
    Box centres;
    for (uint32_t i = first; i < first + count; ++i) {
      node->box.grow(primitives_[i].box);
      centres.grow(primitives_[i].centre);
    }
    nodeCount_ += 1;
    const uint32_t mid = split(first, count, depth, node->box, centres);
    if (mid == first) {  // a leaf
      node->first = first;
      node->count = count;
      return node;
    }
    const uint32_t leftCount = mid - first, rightCount = first + count - mid;
    if (count >= kParallelSubtree) {
      tbb::parallel_invoke([&] { node->children[0] = build(first, leftCount, depth + 1); },
                           [&] { node->children[1] = build(mid, rightCount, depth + 1); });
    } else {
      node->children[0] = build(first, leftCount, depth + 1);
      node->children[1] = build(mid, rightCount, depth + 1);
    }
    return node;
  }

 private:
  // Partitions [first, first + count) and returns the first index of the right half, or
  // `first` when the node should be a leaf.
  uint32_t split(uint32_t first, uint32_t count, int depth, const Box& box, const Box& centres) {
    const auto maxLeaf = static_cast<uint32_t>(options_.maxLeafSize);
    if (count <= 1) return first;
    const glm::vec3 extent = centres.upper - centres.lower;
    if (!(extent.x > 0.0f || extent.y > 0.0f || extent.z > 0.0f)) {
      // All centres coincide: no plane separates them; halve by index if too many.
      if (count <= maxLeaf) return first;
      return first + count / 2;
    }

    const int binCount = std::clamp(options_.bins, 2, kMaxBins);
    const Binning binning = depth < kMaxSahDepth ? bin(first, count, centres, binCount) : Binning{};

    // Sweep each axis: right-to-left suffix areas/counts, then left-to-right candidates.
    float bestCost = std::numeric_limits<float>::infinity();
    int bestAxis = -1, bestBin = 0;
    for (int axis = 0; axis < 3 && depth < kMaxSahDepth; ++axis) {
      if (!(extent[axis] > 0.0f)) continue;
      const auto& bins = binning.bins[axis];
      std::array<float, kMaxBins> rightArea{};
      std::array<uint32_t, kMaxBins> rightCount{};
      Box right;
      uint32_t n = 0;
      for (int b = binCount - 1; b > 0; --b) {
        right.grow(bins[b].box);
        n += bins[b].count;
        rightArea[b] = right.surfaceArea();
        rightCount[b] = n;
      }
      Box left;
      uint32_t leftN = 0;
      for (int b = 1; b < binCount; ++b) {  // plane between bin b − 1 and bin b
        left.grow(bins[b - 1].box);
        leftN += bins[b - 1].count;
        if (leftN == 0 || rightCount[b] == 0) continue;
        const float cost = left.surfaceArea() * static_cast<float>(leftN) +
                           rightArea[b] * static_cast<float>(rightCount[b]);
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestBin = b;
        }
      }
    }

    const float area = box.surfaceArea();
    const float leafCost = options_.intersectionCost * static_cast<float>(count);
    const float splitCost =
        bestAxis < 0 ? std::numeric_limits<float>::infinity()
                     : options_.traversalCost + options_.intersectionCost * bestCost / area;
    if (count <= maxLeaf && leafCost <= splitCost) return first;

    auto begin = primitives_.begin() + first, end = begin + count;
    if (bestAxis >= 0) {
      const auto mid = std::partition(begin, end, [&](const BuildPrimitive& p) {
        return Binning::binIndex(p.centre, centres, bestAxis, binCount) < bestBin;
      });
      if (mid != begin && mid != end) return static_cast<uint32_t>(mid - primitives_.begin());
    }
    // No useful plane (e.g. every centre in one bin): median split on the widest axis.
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto mid = begin + count / 2;
    std::nth_element(begin, mid, end, [axis](const BuildPrimitive& a, const BuildPrimitive& b) {
      return a.centre[axis] < b.centre[axis] || (a.centre[axis] == b.centre[axis] && a.id < b.id);
    });
    return static_cast<uint32_t>(mid - primitives_.begin());
  }

  Binning bin(uint32_t first, uint32_t count, const Box& centres, int binCount) const {
    if (count < kParallelBinning) {
      Binning binning;
      for (uint32_t i = first; i < first + count; ++i)
        binning.add(primitives_[i], centres, binCount);
      return binning;
    }
    return tbb::parallel_reduce(
        tbb::blocked_range<uint32_t>(first, first + count), Binning{},
        [&](const tbb::blocked_range<uint32_t>& range, Binning binning) {
          for (uint32_t i = range.begin(); i != range.end(); ++i)
            binning.add(primitives_[i], centres, binCount);
          return binning;
        },
        [binCount](Binning a, const Binning& b) {
          a.merge(b, binCount);
          return a;
        });
  }

  std::vector<BuildPrimitive>& primitives_;
  const BvhBuildOptions& options_;
  std::atomic<std::size_t> nodeCount_{0};

 public:
  std::size_t nodeCount() const { return nodeCount_; }
};

BvhNode toNode(const BuildNode& node) {
  const glm::vec3 lo = node.box.lower, hi = node.box.upper;
  return BvhNode{
      {{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}}, node.first, static_cast<uint16_t>(node.count), 0};
}

// Treelets: the child pairs of the top kTreeletDepth levels below the node at `index`, in
// breadth-first order, one after the other. A ray that reaches the node can request all of
// their cache lines at once instead of one level after the other (treeletPairs says how many).
template <typename Nodes>
void flattenTreelet(const BuildNode& top, uint32_t index, Nodes& nodes) {
  struct Placed {
    const BuildNode* node;
    uint32_t index;
  };
  std::vector<Placed> frontier = {{&top, index}}, next;
  const auto firstPair = static_cast<uint32_t>(nodes.size());
  for (int level = 0; level < kTreeletDepth; ++level) {
    next.clear();
    for (const Placed& p : frontier) {
      if (p.node->count > 0) continue;
      const auto pair = static_cast<uint32_t>(nodes.size());
      nodes[p.index].offset = pair;
      for (uint32_t k = 0; k < 2; ++k) {
        nodes.push_back(toNode(*p.node->children[k]));
        next.push_back({p.node->children[k].get(), pair + k});
      }
    }
    frontier.swap(next);
  }
  nodes[index].treeletPairs = static_cast<uint16_t>((nodes.size() - firstPair) / 2);
  for (const Placed& p : frontier) flattenTreelet(*p.node, p.index, nodes);
}

}  // namespace

Bvh buildBvh(std::span<const Box> boxes, std::span<const uint32_t> ids,
             const BvhBuildOptions& options) {
  if (boxes.size() != ids.size()) throw std::invalid_argument("buildBvh: boxes/ids mismatch");
  if (options.maxLeafSize < 1 || options.maxLeafSize > 65535)
    throw std::invalid_argument("buildBvh: maxLeafSize must be in [1, 65535]");
  if (boxes.size() >= std::numeric_limits<uint32_t>::max())
    throw std::invalid_argument("buildBvh: too many primitives");
  Bvh bvh;
  if (boxes.empty()) return bvh;

  std::vector<BuildPrimitive> primitives(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    primitives[i] = BuildPrimitive{boxes[i], boxes[i].centre(), ids[i]};
  Builder builder(primitives, options);
  const std::unique_ptr<BuildNode> root = builder.build(0, static_cast<uint32_t>(boxes.size()), 0);

  bvh.nodes.reserve(builder.nodeCount() + 1);
  bvh.nodes.push_back(toNode(*root));
  bvh.nodes.push_back(BvhNode{});  // unused: child pairs start at even indices
  flattenTreelet(*root, 0, bvh.nodes);
  bvh.primitives.resize(primitives.size());
  for (std::size_t i = 0; i < primitives.size(); ++i) bvh.primitives[i] = primitives[i].id;
  return bvh;
}

}  // namespace bounce
