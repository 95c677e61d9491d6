#include "atlas/mask_pack.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>

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
        summaryWords_((words_ + 63) / 64) {}

  // 64 texels of row y from column x on (bit i is column x + i).
  uint64_t run(int x, int y) const {
    if (y >= rows()) return 0;
    const uint64_t* row = &bits_[static_cast<std::size_t>(y) * words_];
    const int w = x >> 6, s = x & 63;
    if (s == 0) return row[w];
    return (row[w] >> s) | (row[w + 1] << (64 - s));
  }
  bool fits(const ChartMask& mask, int x, int y) const {
    for (int r = 0; r < mask.height; ++r)
      for (int k = 0; k < mask.words; ++k)
        if (run(x + 64 * k, y + r) & mask.bits[static_cast<std::size_t>(r) * mask.words + k])
          return false;
    return true;
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
  // Free texels in row y: a mask fits nowhere in rows with fewer free texels than it has there.
  int freeIn(int y) const { return y < rows() ? free_[static_cast<std::size_t>(y)] : width_; }
  // Marks `grown` (a mask dilated by `radius`) with its texel (radius, radius) at (x, y).
  void take(const ChartMask& grown, int radius, int x, int y) {
    for (int r = 0; r < grown.height; ++r) {
      const int ty = y - radius + r;
      if (ty < 0 || ty >= maxHeight_) continue;
      if (ty >= rows()) {
        bits_.resize(static_cast<std::size_t>(ty + 1) * words_, 0);
        free_.resize(static_cast<std::size_t>(ty + 1), width_);
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
    }
  }

 private:
  int rows() const { return static_cast<int>(bits_.size() / words_); }
  int width_, maxHeight_, words_, summaryWords_;
  std::vector<uint64_t> bits_;
  std::vector<int> free_;  // per row, width_ less its taken texels
  // Per row, bit k set while word k has a free texel (summaryWords_ words a row).
  std::vector<uint64_t> open_;
};

struct Spot {
  int x = 0, y = 0;
  bool found = false;
};

// The lowest, then leftmost, position where `mask` fits with its texels in columns
// [lo, width - hi) and rows ≥ lo, below maxTop - hi.
Spot lowestFit(const TakenTexels& taken, const ChartMask& mask, int width, int lo, int hi,
               int maxTop) {
  // A texel the mask surely has: its first set texel, which must land on a free one.
  int ax = 0, ay = 0;
  for (int i = 0; i < mask.width * mask.height; ++i)
    if (mask.at(i % mask.width, i / mask.width)) {
      ax = i % mask.width;
      ay = i / mask.width;
      break;
    }
  std::vector<int> count(static_cast<std::size_t>(mask.height), 0);  // texels per mask row
  for (int r = 0; r < mask.height; ++r)
    for (int k = 0; k < mask.words; ++k)
      count[static_cast<std::size_t>(r)] +=
          std::popcount(mask.bits[static_cast<std::size_t>(r) * mask.words + k]);
  const auto roomFor = [&](int y) {
    for (int r = 0; r < mask.height; ++r)
      if (taken.freeIn(y + r) < count[static_cast<std::size_t>(r)]) return false;
    return true;
  };
  const int lastX = width - hi - mask.width;
  for (int y = lo; y + mask.height + hi <= maxTop; ++y) {
    if (!roomFor(y)) continue;
    for (int x = lo; x <= lastX; ++x) {
      x = taken.nextFree(x + ax, y + ay) - ax;
      if (x > lastX) break;
      if (taken.fits(mask, x, y)) return {x, y, true};
    }
  }
  return {};
}

std::optional<MaskPacking> packInto(const std::vector<std::vector<ChartMask>>& turns,
                                    const std::vector<std::vector<ChartMask>>& grown,
                                    const std::vector<std::size_t>& order, int padding, int width,
                                    int maxHeight) {
  const int lo = padding / 2, hi = padding - padding / 2;
  TakenTexels taken(width, maxHeight);
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
      const Spot s = lowestFit(taken, mask, width, lo, hi, maxTop);
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
  double area = 0.0;
  int narrowest = 1;  // the widest chart's narrowest width, with the padding
  for (std::size_t c = 0; c < turns.size(); ++c) {
    int w = turns[c][0].width;
    for (const ChartMask& mask : turns[c]) {
      grown[c].push_back(dilateMask(mask, padding));
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
  std::optional<MaskPacking> best;
  for (int step = 0; step <= kWidthSteps; ++step) {
    const int width = std::min(
        maxSize, std::max(narrowest,
                          static_cast<int>(std::ceil(
                              side * (kNarrowest + (kWidest - kNarrowest) * step / kWidthSteps)))));
    std::optional<MaskPacking> packing = packInto(turns, grown, order, padding, width, maxSize);
    if (packing) {
      const auto cost = [](const MaskPacking& p) {
        return static_cast<double>(p.width) * p.height;
      };
      if (!best || cost(*packing) < cost(*best)) best = std::move(packing);
    }
    if (width == maxSize) break;
  }
  return best;
}

}  // namespace bounce
