#include "bake/vpl_groups.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bake/vpl_reduce.h"

namespace bounce {

VplGroups::VplGroups(std::span<const Vpl> vpls, std::size_t k) : vplCount_(vpls.size()) {
  if (k == 0) throw std::invalid_argument("VplGroups: k = 0 groups");
  const std::vector<std::vector<uint32_t>> clusters = groupVpls(vpls, std::min(k, kMaxVplGroups));
  lights_.reserve(vpls.size() + clusters.size());
  for (const std::vector<uint32_t>& members : clusters) {
    VplGroup group;
    group.first = static_cast<uint32_t>(lights_.size());
    group.count = static_cast<uint32_t>(members.size());
    for (const uint32_t i : members) {
      lights_.push_back(vpls[i]);
      lightGroup_.push_back(static_cast<uint32_t>(groups_.size()));
    }
    groups_.push_back(group);
  }
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    VplGroup& group = groups_[g];
    const Vpl representative = mergeVpls(vpls, clusters[g]);
    for (uint32_t i = group.first; i < group.first + group.count; ++i)
      group.radius =
          std::max(group.radius, glm::length(lights_[i].position - representative.position));
    lights_.push_back(representative);
    lightGroup_.push_back(static_cast<uint32_t>(g));
  }
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
  const std::span<const Vpl> representatives = groups.representatives();
  const auto n = static_cast<uint32_t>(groups.vplCount());
  const std::size_t cellCount = static_cast<std::size_t>(cuts.cells.x) *
                                static_cast<std::size_t>(cuts.cells.y) *
                                static_cast<std::size_t>(cuts.cells.z);
  cuts.cellEntries.reserve(cellCount);
  for (int z = 0; z < cuts.cells.z; ++z)
    for (int y = 0; y < cuts.cells.y; ++y)
      for (int x = 0; x < cuts.cells.x; ++x) {
        const glm::vec3 centre = lo + (glm::vec3(x, y, z) + 0.5f) * cuts.cellSize;
        const auto first = static_cast<uint32_t>(cuts.entries.size());
        for (std::size_t g = 0; g < groups.groupCount(); ++g) {
          const VplGroup& group = groups.groups()[g];
          const float distance = glm::length(representatives[g].position - centre) - halfDiagonal;
          const bool far = distance > settings.kappa * group.radius;
          if (far)
            cuts.entries.emplace_back(n + static_cast<uint32_t>(g), 1u);
          else
            cuts.entries.emplace_back(group.first, group.count);
        }
        cuts.cellEntries.emplace_back(first, static_cast<uint32_t>(cuts.entries.size()) - first);
      }
  return cuts;
}

namespace {

void addLight(const Vpl& vpl, glm::dvec3 x, glm::dvec3 n, double r2, VplIrradianceSum& sum) {
  const glm::dvec3 d = glm::dvec3(vpl.position) - x;
  const double d2 = glm::dot(d, d);
  if (!(d2 > 0.0)) return;
  const double dist = std::sqrt(d2);
  const double cosX = glm::dot(n, d) / dist;
  const double cosY = -glm::dot(glm::dvec3(vpl.normal), d) / dist;
  if (cosX <= 0.0 || cosY <= 0.0) return;
  // I(ω) = Φ/π · cosθ_y (W/sr); E = I · cosθ_x / max(d², r²).
  const glm::dvec3 intensity = glm::dvec3(vpl.flux) * (cosY / std::numbers::pi);
  sum.irradiance += intensity * (cosX / std::max(d2, r2));
  sum.removed += intensity * (cosX / d2 - cosX / std::max(d2, r2));
}

}  // namespace

VplIrradianceSum vplCutIrradiance(const VplGroups& groups, const VplLightCuts& cuts, glm::vec3 p,
                                  glm::vec3 n, float clampDistance) {
  VplIrradianceSum sum;
  const double r2 = static_cast<double>(clampDistance) * clampDistance;
  const std::span<const Vpl> lights = groups.lights();
  const glm::uvec2 range = cuts.cellEntries[cuts.cellOf(p)];
  for (uint32_t e = range.x; e < range.x + range.y; ++e)
    for (uint32_t i = cuts.entries[e].x; i < cuts.entries[e].x + cuts.entries[e].y; ++i)
      addLight(lights[i], glm::dvec3(p), glm::dvec3(n), r2, sum);
  return sum;
}

VplIrradianceSum vplIrradianceSum(std::span<const Vpl> lights, glm::vec3 p, glm::vec3 n,
                                  float clampDistance) {
  VplIrradianceSum sum;
  const double r2 = static_cast<double>(clampDistance) * clampDistance;
  for (const Vpl& vpl : lights) addLight(vpl, glm::dvec3(p), glm::dvec3(n), r2, sum);
  return sum;
}

}  // namespace bounce
