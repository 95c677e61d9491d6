#include "atlas/chart_merge.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "atlas/chart_join.h"
#include "atlas/uv_geometry.h"

namespace bounce {
namespace {

// Every triangle's UV area / world area within [1/bound, bound] of the chart's (1 in metres).
bool areaScalesBounded(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                       const std::vector<glm::vec2>& uv, double bound) {
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const double world = mesh.area(triangles[k]);
    const double flat =
        std::abs(static_cast<double>(signedArea(uv[3 * k], uv[3 * k + 1], uv[3 * k + 2])));
    if (flat < world / bound || flat > bound * world) return false;
  }
  return true;
}

// Runs of a shared boundary tried, longest first, where the welded union fails (chart_join.h).
constexpr std::size_t kRunsTried = 3;
// A chart under this many times MergeLimits::smallArea is medium.
constexpr double kMediumFactor = 16.0;

// Texels of the chart's bounding rectangle with one texel more on every side: what it costs in
// the atlas with padding 2 (each chart's mask grown by one texel must not meet another's).
double paddedTexels(glm::dvec2 sides, double texelSize) {
  const auto cells = [&](double side) { return std::max(1.0, std::ceil(side / texelSize - 0.01)); };
  return (cells(sides.x) + 2.0) * (cells(sides.y) + 2.0);
}

// One conformal map of both charts (d's triangles, then c's): welded wherever they share
// positions, else joined along the longest run of their shared boundary (chart_join.h); one map
// when that run is all they share.
FlatGroup flattenUnion(const WorldMesh& mesh, const FlatGroup& d, const FlatGroup& c,
                       double areaBound) {
  FlatGroup both{d.triangles, {}};
  both.triangles.insert(both.triangles.end(), c.triangles.begin(), c.triangles.end());
  const std::vector<JoinedCharts> joins =
      joinAlongRuns(mesh, d.triangles, d.flat.cornerUv, c.triangles, c.flat.cornerUv, kRunsTried);
  if (joins.empty() || !joins.front().everyEdge) {
    both.flat = flattenConformal(mesh, both.triangles, 1.0f);
    if (!both.flat.cornerUv.empty() &&
        areaScalesBounded(mesh, both.triangles, both.flat.cornerUv, areaBound))
      return both;
  }
  for (const JoinedCharts& joined : joins) {
    both.flat = flattenConformal(mesh, joined.triangles, joined.cornerVertex, 1.0f);
    if (!both.flat.cornerUv.empty() &&
        areaScalesBounded(mesh, both.triangles, both.flat.cornerUv, areaBound))
      return both;
  }
  both.flat.cornerUv.clear();
  return both;
}

}  // namespace

glm::dvec2 boundingSides(const std::vector<glm::vec2>& cornerUv) {
  std::vector<glm::vec2> turned = cornerUv;
  orientChart(turned);
  glm::vec2 hi(0.0f);
  for (const glm::vec2 p : turned) hi = glm::max(hi, p);
  return {std::min(hi.x, hi.y), std::max(hi.x, hi.y)};
}

namespace {

// The merge pass's state: the charts as merged so far, what each covers and whom it touches.
class MergePass {
 public:
  MergePass(const WorldMesh& mesh, std::vector<FlatGroup> groups,
            const std::vector<ChartContact>& contacts, const MergeLimits& limits)
      : mesh_(mesh), limits_(limits), groups_(std::move(groups)) {
    const std::size_t n = groups_.size();
    area_.assign(n, 0.0);
    sides_.assign(n, glm::dvec2(0.0));
    alive_.assign(n, true);
    touching_.resize(n);
    for (std::size_t c = 0; c < n; ++c) {
      for (const uint32_t t : groups_[c].triangles) area_[c] += mesh.area(t);
      if (!groups_[c].flat.cornerUv.empty()) sides_[c] = boundingSides(groups_[c].flat.cornerUv);
    }
    for (const ChartContact& contact : contacts) {
      touching_[contact.a][contact.b] = {contact.length, contact.fold};
      touching_[contact.b][contact.a] = {contact.length, contact.fold};
    }
  }

  std::size_t size() const { return groups_.size(); }
  double area(std::size_t c) const { return area_[c]; }

  // The neighbour chart c joins and their union, as the serial pass decides it on the present
  // state (into == kNone: c stays). Reads only c's and its neighbours' charts and c's contacts.
  struct Choice {
    static constexpr uint32_t kNone = UINT32_MAX;
    uint32_t into = kNone;
    FlatGroup both;
    glm::dvec2 sides{0.0};
  };
  Choice choose(uint32_t c) const {
    Choice choice;
    if (!alive_[c] || groups_[c].flat.cornerUv.empty()) return choice;
    std::vector<std::pair<double, uint32_t>> candidates;  // (−shared length, neighbour)
    for (const auto& [d, shared] : touching_[c])
      if (alive_[d] && !groups_[d].flat.cornerUv.empty() && rule(c, d, shared) > 0)
        candidates.emplace_back(-shared.length, d);
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [negativeLength, d] : candidates) {
      const bool byTinyRule = rule(c, d, touching_[c].at(d)) == 1;
      FlatGroup both = flattenUnion(mesh_, groups_[d], groups_[c], byTinyRule ? 3.0 : 2.0);
      if (both.flat.cornerUv.empty()) continue;
      const glm::dvec2 bothSides = boundingSides(both.flat.cornerUv);
      if (!byTinyRule && paddedTexels(bothSides, limits_.texelSize) >
                             paddedTexels(sides_[c], limits_.texelSize) +
                                 paddedTexels(sides_[d], limits_.texelSize))
        continue;
      choice.into = d;
      choice.both = std::move(both);
      choice.sides = bothSides;
      return choice;
    }
    return choice;
  }

  // Carries out c's choice. Every chart whose choose() could now answer otherwise gets
  // known[chart] = 0: c and its target d (their charts changed), and every neighbour of either
  // (its contacts, or a neighbour's chart, changed).
  void apply(uint32_t c, Choice choice, std::vector<uint8_t>& known) {
    if (choice.into == Choice::kNone) return;
    const uint32_t d = choice.into;
    for (const uint32_t x : {c, d}) {
      known[x] = 0;
      for (const auto& [e, shared] : touching_[x]) known[e] = 0;
    }
    groups_[d] = std::move(choice.both);
    area_[d] += area_[c];
    sides_[d] = choice.sides;
    alive_[c] = false;
    for (const auto& [e, shared] : touching_[c]) {
      if (e == d) continue;
      touching_[e].erase(c);
      Shared& de = touching_[d][e];
      de.length += shared.length;
      de.fold = std::max(de.fold, shared.fold);
      touching_[e][d] = de;
    }
    touching_[d].erase(c);
  }

  std::vector<FlatGroup> kept() {
    std::vector<FlatGroup> kept;
    for (std::size_t c = 0; c < groups_.size(); ++c)
      if (alive_[c]) kept.push_back(std::move(groups_[c]));
    return kept;
  }

 private:
  struct Shared {
    double length = 0.0, fold = 0.0;  // metres of shared edges; radians, the sharpest fold
  };
  // Which rule lets c join d: 0 none, 1 tiny, 2 narrow or medium (padding must shrink).
  int rule(std::size_t c, std::size_t d, const Shared& shared) const {
    if (area_[c] < limits_.smallArea && area_[d] < 8.0 * limits_.smallArea) return 1;
    const bool narrow = sides_[c].x <= limits_.texelSize;
    const bool medium = area_[c] < kMediumFactor * limits_.smallArea;
    if ((narrow && shared.fold <= limits_.narrowFold) ||
        (medium && shared.fold <= limits_.mediumFold))
      return 2;
    return 0;
  }

  const WorldMesh& mesh_;
  MergeLimits limits_;
  std::vector<FlatGroup> groups_;
  std::vector<double> area_;  // m²
  std::vector<glm::dvec2> sides_;
  std::vector<bool> alive_;
  std::vector<std::map<uint32_t, Shared>> touching_;  // chart → neighbour → shared edges
};

}  // namespace

// Smallest chart first, each chart's choice made on the charts as the earlier ones left them: a
// serial pass. Run as one: the choices of the next `window` charts are made in parallel on the
// present state, then carried out in order until one was made stale by an earlier one in the
// window (apply() says which); from there the next window begins, reusing the choices still
// known. Each choice carried out is the one the serial pass makes, so the charts are the same at
// any thread count and window.
std::vector<FlatGroup> mergeSmallCharts(const WorldMesh& mesh, std::vector<FlatGroup> groups,
                                        const std::vector<ChartContact>& contacts,
                                        const MergeLimits& limits) {
  MergePass pass(mesh, std::move(groups), contacts, limits);
  const std::size_t n = pass.size();
  std::vector<uint32_t> order(n);
  for (std::size_t c = 0; c < n; ++c) order[c] = static_cast<uint32_t>(c);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return pass.area(a) < pass.area(b); });
  // As many choices as threads can make at once (the arena's, within a global_control's bound
  // such as bounce-bake's --threads): one thread makes one choice at a time, wasting none.
  const std::size_t window = std::max<std::size_t>(
      1, std::min(static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()),
                  tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
  std::vector<MergePass::Choice> choice(n);
  std::vector<uint8_t> known(n, 0);
  for (std::size_t next = 0; next < n;) {
    const std::size_t end = std::min(n, next + window);
    tbb::parallel_for(next, end, [&](std::size_t k) {
      const uint32_t c = order[k];
      if (known[c]) return;
      choice[c] = pass.choose(c);
      known[c] = 1;
    });
    for (; next < end && known[order[next]]; ++next)
      pass.apply(order[next], std::move(choice[order[next]]), known);
  }
  return pass.kept();
}

}  // namespace bounce
