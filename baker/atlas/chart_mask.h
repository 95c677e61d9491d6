// A chart's texel mask: which texels of its whole-texel rectangle its triangles touch (the texels
// the baker samples and bilinear lookups read). Internal to the atlas.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

struct ChartMask {
  int width = 0, height = 0;   // texels
  int words = 0;               // 64-bit words per row
  std::vector<uint64_t> bits;  // row-major, bit x of row y is texel (x, y)
  bool at(int x, int y) const {
    return (bits[static_cast<std::size_t>(y) * words + (x >> 6)] >> (x & 63)) & 1u;
  }
  void set(int x, int y) {
    bits[static_cast<std::size_t>(y) * words + (x >> 6)] |= uint64_t{1} << (x & 63);
  }
};

ChartMask emptyMask(glm::ivec2 cells);

// The texels of `cells` that the triangles (3 corners each, texel units) touch, with half the
// atlas's coverage epsilon, so the mask holds every texel the atlas later counts for the chart
// (a superset by float round-off at most). A chart that touches nothing gets all its cells.
ChartMask rasteriseChart(const std::vector<glm::vec2>& cornerUv, glm::ivec2 cells);

// The mask grown by `radius` texels in Chebyshev distance (a square), `radius` more on every
// side: texel (x, y) of the result is texel (x - radius, y - radius) of the source's frame.
ChartMask dilateMask(const ChartMask& mask, int radius);

// Number of set texels.
std::size_t setTexels(const ChartMask& mask);

}  // namespace bounce
