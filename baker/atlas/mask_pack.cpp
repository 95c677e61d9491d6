#include "atlas/mask_pack.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include <tbb/parallel_for.h>

namespace bounce {
namespace {

// Atlas widths tried, as fractions of the square root of the padded rectangles' area (masks
// interlock, so the best is often below it: 0.79 on the Conference Room).
constexpr double kNarrowest = 0.6, kWidest = 1.2;
constexpr int kWidthSteps = 3;

// The atlas's taken texels: every placed chart's mask dilated by the padding. A chart fits where
// its own mask meets none of them.
class TakenTexels {
 public:
  TakenTexels(int width, int maxHeight)
      : width_(width),
        maxHeight_(maxHeight),
        words_((width + 63) / 64 + 1),
        summaryWords_((words_ + 63) / 64),
        lowest_(static_cast<std::size_t>(width) + 1, 0) {}

  // The highest taken column in [x0, x1] of row y, or -1 when all are free.
  int lastTaken(int y, int x0, int x1) const {
    if (y >= rows()) return -1;
    const uint64_t* row = &bits_[static_cast<std::size_t>(y) * words_];
    for (int w = x1 >> 6; w >= x0 >> 6; --w) {
      uint64_t word = row[w];
      if (w == x1 >> 6) word &= ~uint64_t{0} >> (63 - (x1 & 63));
      if (w == x0 >> 6) word &= ~uint64_t{0} << (x0 & 63);
      if (word) return 64 * w + 63 - std::countl_zero(word);
    }
    return -1;
  }
  // The first free column ≥ x in row y (width_ when none).
  int nextFree(int x, int y) const {
    if (y >= rows()) return x;
    const uint64_t* row = &bits_[static_cast<std::size_t>(y) * words_];
    const int w = x >> 6;
    if (const uint64_t free = ~row[w] & (~uint64_t{0} << (x & 63)))
      return 64 * w + std::countr_zero(free);
    // The next word with a free texel, from the row's summary of open words.
    const uint64_t* open = &open_[static_cast<std::size_t>(y) * summaryWords_];
    for (int k = w + 1; k < words_;) {
      const uint64_t candidates = open[k >> 6] & (~uint64_t{0} << (k & 63));
      if (candidates) {
        const int next = 64 * (k >> 6) + std::countr_zero(candidates);
        return 64 * next + std::countr_zero(~row[next]);
      }
      k = 64 * ((k >> 6) + 1);
    }
    return width_;
  }
  // Free texels in row y, and its longest run of free texels: a mask fits nowhere in rows with
  // fewer free texels than it has there, nor with a shorter free run than its longest there.
  int freeIn(int y) const { return y < rows() ? free_[static_cast<std::size_t>(y)] : width_; }
  int longestFreeIn(int y) const {
    return y < rows() ? longest_[static_cast<std::size_t>(y)] : width_;
  }
  // The lowest row with a free run of `length` texels or more. Rows only fill, so the answer
  // only rises and each length's search resumes where it stopped.
  int lowestRowWith(int length) {
    int& y = lowest_[static_cast<std::size_t>(length)];
    while (y < rows() && longest_[static_cast<std::size_t>(y)] < length) ++y;
    return y;
  }
  // Marks `grown` (a mask dilated by `radius`) with its texel (radius, radius) at (x, y).
  void take(const ChartMask& grown, int radius, int x, int y) {
    for (int r = 0; r < grown.height; ++r) {
      const int ty = y - radius + r;
      if (ty < 0 || ty >= maxHeight_) continue;
      if (ty >= rows()) {
        bits_.resize(static_cast<std::size_t>(ty + 1) * words_, 0);
        free_.resize(static_cast<std::size_t>(ty + 1), width_);
        longest_.resize(static_cast<std::size_t>(ty + 1), width_);
        open_.resize(static_cast<std::size_t>(ty + 1) * summaryWords_, ~uint64_t{0});
      }
      for (int c = 0; c < grown.width; ++c) {
        const int tx = x - radius + c;
        if (tx >= 0 && tx < width_ && grown.at(c, r))
          bits_[static_cast<std::size_t>(ty) * words_ + (tx >> 6)] |= uint64_t{1} << (tx & 63);
      }
      int taken = 0;
      for (int k = 0; k < words_; ++k) {
        const uint64_t word = bits_[static_cast<std::size_t>(ty) * words_ + k];
        taken += std::popcount(word);
        if (word == ~uint64_t{0})
          open_[static_cast<std::size_t>(ty) * summaryWords_ + (k >> 6)] &=
              ~(uint64_t{1} << (k & 63));
      }
      free_[static_cast<std::size_t>(ty)] = width_ - taken;
      longest_[static_cast<std::size_t>(ty)] = longestRun(ty);
    }
  }

 private:
  int rows() const { return static_cast<int>(bits_.size() / words_); }
  // The first taken column ≥ x in row y (width_ when none).
  int nextTaken(int x, int y) const {
    const uint64_t* row = &bits_[static_cast<std::size_t>(y) * words_];
    for (int w = x >> 6; 64 * w < width_; ++w)
      if (const uint64_t t = row[w] & (~uint64_t{0} << (w == x >> 6 ? x & 63 : 0)))
        return std::min(width_, 64 * w + std::countr_zero(t));
    return width_;
  }
  int longestRun(int y) const {
    int longest = 0;
    for (int x = nextFree(0, y); x < width_;) {
      const int end = nextTaken(x, y);
      longest = std::max(longest, end - x);
      x = end < width_ ? nextFree(end, y) : width_;
    }
    return longest;
  }
  int width_, maxHeight_, words_, summaryWords_;
  std::vector<uint64_t> bits_;
  std::vector<int> free_;     // per row, width_ less its taken texels
  std::vector<int> longest_;  // per row, its longest run of free texels
  std::vector<int> lowest_;   // per run length, no row below it has a free run that long
  // Per row, bit k set while word k has a free texel (summaryWords_ words a row).
  std::vector<uint64_t> open_;
};

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
