#include "atlas/mask_pack.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include <tbb/parallel_for.h>

#include "atlas/taken_texels.h"

namespace bounce {
namespace {

// Atlas widths tried, as fractions of the square root of the padded rectangles' area (masks
// interlock, so the best is often below it: 0.79 on the Conference Room).
constexpr double kNarrowest = 0.6, kWidest = 1.2;
constexpr int kWidthSteps = 3;

// A mask as runs of set texels: it fits at (x, y) exactly when every run lies on free texels.
struct Run {
  int row, first, last;  // mask row, first and last column
};
struct MaskRuns {
  std::vector<Run> runs;       // longest first: they collide most and skip furthest
  std::vector<int> count;      // per mask row, its texels
  std::vector<int> longest;    // per mask row, its longest run
  std::vector<int> selective;  // mask rows, longest run first
  int shape = 0;               // equal masks (of any charts and turns) share it
};

MaskRuns runsOf(const ChartMask& mask) {
  MaskRuns m;
  m.count.assign(static_cast<std::size_t>(mask.height), 0);
  m.longest.assign(static_cast<std::size_t>(mask.height), 0);
  for (int r = 0; r < mask.height; ++r)
    for (int x = 0; x < mask.width; ++x) {
      if (!mask.at(x, r)) continue;
      const int first = x;
      while (x + 1 < mask.width && mask.at(x + 1, r)) ++x;
      m.runs.push_back({r, first, x});
      m.count[static_cast<std::size_t>(r)] += x - first + 1;
      m.longest[static_cast<std::size_t>(r)] =
          std::max(m.longest[static_cast<std::size_t>(r)], x - first + 1);
    }
  std::stable_sort(m.runs.begin(), m.runs.end(),
                   [](const Run& a, const Run& b) { return a.last - a.first > b.last - b.first; });
  m.selective.resize(static_cast<std::size_t>(mask.height));
  std::iota(m.selective.begin(), m.selective.end(), 0);
  std::stable_sort(m.selective.begin(), m.selective.end(), [&](int a, int b) {
    return m.longest[static_cast<std::size_t>(a)] > m.longest[static_cast<std::size_t>(b)];
  });
  return m;
}

// The leftmost x in [x, lastX] where every run of the mask lies on free texels of rows from y
// on, or lastX + 1. A run meeting a taken texel t rules out every x that puts t inside it and
// every x that puts its first texel on the taken texels after t, so x jumps past them.
int leftmostFit(const TakenTexels& taken, const std::vector<Run>& runs, int y, int x, int lastX) {
  std::size_t i = 0, clear = 0;  // the last `clear` runs tested are free at x
  while (clear < runs.size() && x <= lastX) {
    const Run& run = runs[i];
    const int t = taken.lastTaken(y + run.row, x + run.first, x + run.last);
    if (t < 0) {
      ++clear;
      i = (i + 1) % runs.size();
    } else {
      x = taken.nextFree(t + 1, y + run.row) - run.first;
      clear = 0;
    }
  }
  return x;
}

struct Spot {
  int x = 0, y = 0;
  bool found = false;
};

// The lowest, then leftmost, position from `from` on (row, then column) where `mask` fits with
// its texels in columns [lo, width - hi) and rows ≥ lo, below maxTop - hi. Texels only get taken,
// so a position where a mask did not fit never fits it again: `from` becomes the position found,
// or the first row not searched, and the next search for an equal mask resumes there.
Spot lowestFit(TakenTexels& taken, const ChartMask& mask, const MaskRuns& m, int width, int lo,
               int hi, int maxTop, glm::ivec2& from) {
  const auto roomFor = [&](int y) {
    for (const int r : m.selective)
      if (taken.longestFreeIn(y + r) < m.longest[static_cast<std::size_t>(r)] ||
          taken.freeIn(y + r) < m.count[static_cast<std::size_t>(r)])
        return false;
    return true;
  };
  const int lastX = width - hi - mask.width;
  if (lastX < lo) return {};
  int firstY = std::max(lo, from.y);  // below it, no fit is left
  for (int r = 0; r < mask.height; ++r)
    if (m.longest[static_cast<std::size_t>(r)] > 0)
      firstY = std::max(firstY, taken.lowestRowWith(m.longest[static_cast<std::size_t>(r)]) - r);
  int y = firstY;
  for (; y + mask.height + hi <= maxTop; ++y) {
    if (!roomFor(y)) continue;
    const int x = leftmostFit(taken, m.runs, y, y == from.y ? std::max(lo, from.x) : lo, lastX);
    if (x <= lastX) {
      from = {x, y};
      return {x, y, true};
    }
  }
  from = {lo, y};
  return {};
}

std::optional<MaskPacking> packInto(const std::vector<std::vector<ChartMask>>& turns,
                                    const std::vector<std::vector<ChartMask>>& grown,
                                    const std::vector<std::vector<MaskRuns>>& runs,
                                    std::size_t shapes, const std::vector<std::size_t>& order,
                                    int padding, int width, int maxHeight) {
  const int lo = padding / 2, hi = padding - padding / 2;
  TakenTexels taken(width, maxHeight);
  std::vector<glm::ivec2> resume(shapes, glm::ivec2(lo));  // per shape, lowestFit's `from`
  MaskPacking packing;
  packing.width = width;
  packing.origin.assign(turns.size(), glm::ivec2(0));
  packing.turn.assign(turns.size(), 0);
  for (const std::size_t c : order) {
    Spot best;
    int bestTurn = 0, bestTop = 0;
    for (std::size_t k = 0; k < turns[c].size(); ++k) {
      const ChartMask& mask = turns[c][k];
      // A lower top than the best so far needs y < bestTop - height.
      const int maxTop = best.found ? std::min(maxHeight, bestTop - 1 + hi) : maxHeight;
      const MaskRuns& m = runs[c][k];
      const Spot s = lowestFit(taken, mask, m, width, lo, hi, maxTop,
                               resume[static_cast<std::size_t>(m.shape)]);
      if (s.found && (!best.found || s.y + mask.height < bestTop)) {
        best = s;
        bestTurn = static_cast<int>(k);
        bestTop = s.y + mask.height;
      }
    }
    if (!best.found) return std::nullopt;
    taken.take(grown[c][bestTurn], padding, best.x, best.y);
    packing.origin[c] = glm::ivec2(best.x, best.y);
    packing.turn[c] = bestTurn;
    packing.height = std::max(packing.height, bestTop + hi);
  }
  return packing;
}

}  // namespace

std::optional<MaskPacking> packMasks(const std::vector<std::vector<ChartMask>>& turns, int padding,
                                     int maxSize) {
  if (turns.empty()) return MaskPacking{1, 1, {}, {}};
  std::vector<std::vector<ChartMask>> grown(turns.size());
  std::vector<std::vector<MaskRuns>> runs(turns.size());
  std::map<std::tuple<int, int, std::vector<uint64_t>>, int> shapes;
  double area = 0.0;
  int narrowest = 1;  // the widest chart's narrowest width, with the padding
  for (std::size_t c = 0; c < turns.size(); ++c) {
    int w = turns[c][0].width;
    for (const ChartMask& mask : turns[c]) {
      grown[c].push_back(dilateMask(mask, padding));
      runs[c].push_back(runsOf(mask));
      const auto [it, added] = shapes.try_emplace(std::tuple(mask.width, mask.height, mask.bits),
                                                  static_cast<int>(shapes.size()));
      runs[c].back().shape = it->second;
      w = std::min(w, mask.width);
    }
    const ChartMask& m = turns[c][0];
    area += static_cast<double>(m.width + padding) * (m.height + padding);
    narrowest = std::max(narrowest, w + padding);
  }
  std::vector<std::size_t> order(turns.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Largest padded rectangle first, then the one with the longer short side.
  const auto size = [&](std::size_t c) {
    const ChartMask& m = turns[c][0];
    return static_cast<int64_t>(m.width + padding) * (m.height + padding);
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (size(a) != size(b)) return size(a) > size(b);
    return std::min(turns[a][0].width, turns[a][0].height) >
           std::min(turns[b][0].width, turns[b][0].height);
  });
  const double side = std::sqrt(area);
  std::vector<int> widths;
  for (int step = 0; step <= kWidthSteps; ++step) {
    widths.push_back(
        std::min(maxSize, std::max(narrowest, static_cast<int>(std::ceil(
                                                  side * (kNarrowest + (kWidest - kNarrowest) *
                                                                           step / kWidthSteps))))));
    if (widths.back() == maxSize) break;
  }
  // Each width packs on its own; the first of the smallest atlases wins, whatever the threads.
  std::vector<std::optional<MaskPacking>> packings(widths.size());
  tbb::parallel_for(std::size_t{0}, widths.size(), [&](std::size_t i) {
    packings[i] = packInto(turns, grown, runs, shapes.size(), order, padding, widths[i], maxSize);
  });
  std::optional<MaskPacking> best;
  const auto cost = [](const MaskPacking& p) { return static_cast<double>(p.width) * p.height; };
  for (std::optional<MaskPacking>& packing : packings)
    if (packing && (!best || cost(*packing) < cost(*best))) best = std::move(packing);
  return best;
}

}  // namespace bounce
