// The mask packer's atlas (mask_pack.h): which texels placed charts take, as 64-bit rows with
// the per-row counts its search skips by; all inline, as the search calls them ~10⁸ times on
// Šibenik. Internal to the atlas.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "atlas/chart_mask.h"

namespace bounce {

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

}  // namespace bounce
