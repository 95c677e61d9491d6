#include "vpl_runtime/vpl_groups.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "image/luminance.h"
#include "vpl_runtime/vpl_reduce.h"

namespace bounce {

namespace {

// Largest distance from `centre` to lights[first, first + count).
float radiusAround(std::span<const Vpl> lights, uint32_t first, uint32_t count, glm::vec3 centre) {
  float radius = 0.0f;
  for (uint32_t i = first; i < first + count; ++i)
    radius = std::max(radius, glm::length(lights[i].position - centre));
  return radius;
}

// Splits order[first, first + count) (indices into `vpls`) at the median of its box's longest
// axis, recursively, appending the nodes (a parent before its children); returns the subtree's
// root.
int32_t buildTree(std::span<const Vpl> vpls, std::vector<uint32_t>& order, uint32_t first,
                  uint32_t count, std::vector<VplNode>& nodes) {
  const auto index = static_cast<int32_t>(nodes.size());
  nodes.push_back({first, count, first, 0.0f, -1, -1});
  if (count <= kVplLeafSize) return index;
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (uint32_t i = first; i < first + count; ++i) {
    lo = glm::min(lo, vpls[order[i]].position);
    hi = glm::max(hi, vpls[order[i]].position);
  }
  const glm::vec3 e = hi - lo;
  const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
  const uint32_t half = count / 2;
  const auto begin = order.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [&](uint32_t a, uint32_t b) {
    return vpls[a].position[axis] < vpls[b].position[axis];
  });
  const int32_t left = buildTree(vpls, order, first, half, nodes);
  const int32_t right = buildTree(vpls, order, first + half, count - half, nodes);
  nodes[static_cast<std::size_t>(index)].left = left;
  nodes[static_cast<std::size_t>(index)].right = right;
  return index;
}

}  // namespace

VplGroups::VplGroups(std::span<const Vpl> vpls, std::size_t k) : vplCount_(vpls.size()) {
  if (k == 0) throw std::invalid_argument("VplGroups: k = 0 groups");
  const std::vector<std::vector<uint32_t>> clusters = groupVpls(vpls, std::min(k, kMaxVplGroups));
  order_.reserve(vpls.size());
  for (const std::vector<uint32_t>& members : clusters) {
    VplGroup group;
    group.first = static_cast<uint32_t>(order_.size());
    group.count = static_cast<uint32_t>(members.size());
    order_.insert(order_.end(), members.begin(), members.end());
    groups_.push_back(group);
  }
  for (VplGroup& group : groups_)
    group.root = static_cast<uint32_t>(buildTree(vpls, order_, group.first, group.count, nodes_));
  lights_.reserve(vpls.size() + clusters.size());
  for (const uint32_t i : order_) lights_.push_back(vpls[i]);
  // Representatives: the groups' first (N + g), then every other node of more than one VPL.
  std::vector<uint32_t> members;
  const auto represent = [&](VplNode& node) {
    members.resize(node.count);
    for (uint32_t i = 0; i < node.count; ++i) members[i] = node.first + i;
    const Vpl representative = mergeVpls(std::span(lights_).first(vplCount_), members);
    node.representative = static_cast<uint32_t>(lights_.size());
    node.radius = radiusAround(lights_, node.first, node.count, representative.position);
    lights_.push_back(representative);
  };
  for (VplGroup& group : groups_) {
    VplNode& root = nodes_[group.root];
    if (root.count > 1) {
      represent(root);
    } else {  // a lone VPL still gets its group slot N + g
      root.representative = static_cast<uint32_t>(lights_.size());
      lights_.push_back(lights_[root.first]);
    }
    group.radius = root.radius;
  }
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const bool isRoot =
        std::any_of(groups_.begin(), groups_.end(), [&](const VplGroup& g) { return g.root == n; });
    if (!isRoot && nodes_[n].count > 1) represent(nodes_[n]);
  }
  lightGroup_.assign(lights_.size(), 0);
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    for (uint32_t i = groups_[g].first; i < groups_[g].first + groups_[g].count; ++i)
      lightGroup_[i] = static_cast<uint32_t>(g);
    lightGroup_[vplCount_ + g] = static_cast<uint32_t>(g);
  }
  for (const VplNode& node : nodes_)
    if (node.count > 1) lightGroup_[node.representative] = lightGroup_[node.first];
}

std::vector<glm::vec3> VplGroups::lightFluxes(std::span<const uint8_t> alive) const {
  if (alive.size() != vplCount_)
    throw std::invalid_argument("VplGroups::lightFluxes: " + std::to_string(alive.size()) +
                                " flags for " + std::to_string(vplCount_) + " VPLs");
  std::vector<glm::vec3> flux(lights_.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i < vplCount_; ++i)
    if (alive[order_[i]] != 0) flux[i] = lights_[i].flux;
  // A representative's flux is Σ over its members (mergeVpls), now of the alive ones.
  const auto sumOf = [&](uint32_t first, uint32_t count) {
    glm::dvec3 sum(0.0);
    for (uint32_t i = first; i < first + count; ++i) sum += glm::dvec3(flux[i]);
    return glm::vec3(sum);
  };
  for (const VplNode& node : nodes_)
    if (node.count > 1) flux[node.representative] = sumOf(node.first, node.count);
  for (std::size_t g = 0; g < groups_.size(); ++g)  // lone VPLs' group slots N + g
    flux[vplCount_ + g] = sumOf(groups_[g].first, groups_[g].count);
  return flux;
}

std::size_t VplLightCuts::cellOf(glm::vec3 p) const {
  const glm::ivec3 c =
      glm::clamp(glm::ivec3(glm::floor((p - origin) / cellSize)), glm::ivec3(0), cells - 1);
  return static_cast<std::size_t>(c.x) +
         static_cast<std::size_t>(cells.x) *
             (static_cast<std::size_t>(c.y) +
              static_cast<std::size_t>(cells.y) * static_cast<std::size_t>(c.z));
}

std::size_t VplLightCuts::lightsEvaluated(std::size_t cell) const {
  std::size_t n = 0;
  const glm::uvec2 range = cellEntries[cell];
  for (uint32_t e = range.x; e < range.x + range.y; ++e) n += entries[e].y;
  return n;
}

VplLightCuts buildVplLightCuts(const VplGroups& groups, glm::vec3 lo, glm::vec3 hi,
                               const VplLightCutSettings& settings) {
  VplLightCuts cuts;
  lo = glm::min(lo, hi);
  const glm::vec3 extent = glm::max(hi - lo, glm::vec3(0.0f));
  const float longest = std::max({extent.x, extent.y, extent.z});
  const int perAxis = std::max(1, settings.maxCellsPerAxis);
  // Cubic cells: the longest axis gets perAxis of them.
  const float size = longest > 0.0f ? longest / static_cast<float>(perAxis) : 1.0f;
  cuts.origin = lo;
  for (int a = 0; a < 3; ++a) {
    cuts.cells[a] = std::clamp(static_cast<int>(std::ceil(extent[a] / size)), 1, perAxis);
    cuts.cellSize[a] = extent[a] > 0.0f ? extent[a] / static_cast<float>(cuts.cells[a]) : size;
  }
  const float halfDiagonal = 0.5f * glm::length(cuts.cellSize);
  const std::span<const Vpl> lights = groups.lights();
  const std::span<const VplNode> nodes = groups.nodes();
  const auto n = static_cast<uint32_t>(groups.vplCount());
  const std::size_t cellCount = static_cast<std::size_t>(cuts.cells.x) *
                                static_cast<std::size_t>(cuts.cells.y) *
                                static_cast<std::size_t>(cuts.cells.z);
  const uint32_t bound =
      settings.maxLights == 0
          ? std::numeric_limits<uint32_t>::max()
          : std::max(settings.maxLights, static_cast<uint32_t>(groups.groupCount()));
  // A node waiting to be refined, with its far-field error estimate lum(Φ)·s²/d⁴ (W·m⁻⁴ scale;
  // only the order matters). d is clamped to a hundredth of the cell's half-diagonal: a node
  // around the cell is refined before any node away from it.
  struct Candidate {
    double error;
    int32_t node;
    bool operator<(const Candidate& o) const {
      return error < o.error || (error == o.error && node > o.node);
    }
  };
  std::vector<Candidate> heap;
  std::vector<int32_t> cut;  // the nodes kept: far, leaves expanded (count < 0 marks a leaf's VPLs)
  cuts.cellEntries.reserve(cellCount);
  for (int z = 0; z < cuts.cells.z; ++z)
    for (int y = 0; y < cuts.cells.y; ++y)
      for (int x = 0; x < cuts.cells.x; ++x) {
        const glm::vec3 centre = lo + (glm::vec3(x, y, z) + 0.5f) * cuts.cellSize;
        const auto distanceOf = [&](const VplNode& node) {
          return glm::length(lights[node.representative].position - centre) - halfDiagonal;
        };
        const auto errorOf = [&](const VplNode& node) {
          const double d = std::max(static_cast<double>(distanceOf(node)), 0.01 * halfDiagonal);
          const double s = node.radius;
          return static_cast<double>(luminance(lights[node.representative].flux)) * s * s /
                 (d * d * d * d);
        };
        // Near: not far by κ and more than one VPL (a lone VPL is exact as itself).
        const auto near = [&](const VplNode& node) {
          return node.count > 1 && !(distanceOf(node) > settings.kappa * node.radius);
        };
        heap.clear();
        cut.clear();
        uint32_t lightsUsed = 0;
        for (const VplGroup& group : groups.groups()) {
          const VplNode& root = nodes[group.root];
          ++lightsUsed;
          if (near(root))
            heap.push_back({errorOf(root), static_cast<int32_t>(group.root)});
          else
            cut.push_back(static_cast<int32_t>(group.root));
        }
        std::make_heap(heap.begin(), heap.end());
        while (!heap.empty()) {
          std::pop_heap(heap.begin(), heap.end());
          const int32_t index = heap.back().node;
          heap.pop_back();
          const VplNode& node = nodes[static_cast<std::size_t>(index)];
          // A leaf becomes its VPLs (count lights instead of 1), an inner node its two children.
          const uint32_t more = node.left < 0 ? node.count - 1 : 1;
          if (lightsUsed + more > bound) {
            cut.push_back(index);  // stays its representative
            continue;
          }
          lightsUsed += more;
          if (node.left < 0) {
            cut.push_back(-1 - index);
            continue;
          }
          for (const int32_t child : {node.left, node.right}) {
            const VplNode& c = nodes[static_cast<std::size_t>(child)];
            if (near(c)) {
              heap.push_back({errorOf(c), child});
              std::push_heap(heap.begin(), heap.end());
            } else {
              cut.push_back(child);
            }
          }
        }
        // Light-table order (the nodes of a cut are disjoint ranges: by their first member),
        // consecutive VPL ranges merged.
        const auto nodeOf = [&](int32_t entry) -> const VplNode& {
          return nodes[static_cast<std::size_t>(entry < 0 ? -1 - entry : entry)];
        };
        std::sort(cut.begin(), cut.end(),
                  [&](int32_t a, int32_t b) { return nodeOf(a).first < nodeOf(b).first; });
        const auto first = static_cast<uint32_t>(cuts.entries.size());
        for (const int32_t entry : cut) {
          const VplNode& node = nodeOf(entry);
          // An expanded leaf is its VPLs; any other node its representative (a lone VPL's is
          // the VPL itself, or its group's slot for a group of one).
          const uint32_t begin = entry < 0 ? node.first : node.representative;
          const uint32_t count = entry < 0 ? node.count : 1u;
          if (begin < n && cuts.entries.size() > first) {
            glm::uvec2& last = cuts.entries.back();
            if (last.x < n && last.x + last.y == begin) {
              last.y += count;
              continue;
            }
          }
          cuts.entries.emplace_back(begin, count);
        }
        cuts.cellEntries.emplace_back(first, static_cast<uint32_t>(cuts.entries.size()) - first);
      }
  return cuts;
}

namespace {

void addLight(const Vpl& vpl, glm::dvec3 x, glm::dvec3 n, double r2, VplIrradiance& sum) {
  if (const std::optional<VplIrradiance> e = vplIrradiance(vpl, x, n, r2)) sum += *e;
}

}  // namespace

VplIrradiance vplCutIrradiance(const VplGroups& groups, const VplLightCuts& cuts, glm::vec3 p,
                               glm::vec3 n, float clampDistance) {
  VplIrradiance sum;
  const double r2 = static_cast<double>(clampDistance) * clampDistance;
  const std::span<const Vpl> lights = groups.lights();
  const glm::uvec2 range = cuts.cellEntries[cuts.cellOf(p)];
  for (uint32_t e = range.x; e < range.x + range.y; ++e)
    for (uint32_t i = cuts.entries[e].x; i < cuts.entries[e].x + cuts.entries[e].y; ++i)
      addLight(lights[i], glm::dvec3(p), glm::dvec3(n), r2, sum);
  return sum;
}

VplIrradiance vplIrradianceSum(std::span<const Vpl> lights, glm::vec3 p, glm::vec3 n,
                               float clampDistance) {
  VplIrradiance sum;
  const double r2 = static_cast<double>(clampDistance) * clampDistance;
  for (const Vpl& vpl : lights) addLight(vpl, glm::dvec3(p), glm::dvec3(n), r2, sum);
  return sum;
}

}  // namespace bounce
