#include "atlas/chart_pack.h"

#include <algorithm>
#include <cmath>

#include <stb/stb_rect_pack.h>

namespace bounce {
namespace {

std::optional<Packing> packInto(const std::vector<glm::ivec2>& sizes, int width, int maxHeight) {
  std::vector<stbrp_rect> rects(sizes.size());
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    rects[i].id = static_cast<int>(i);
    rects[i].w = sizes[i].x;
    rects[i].h = sizes[i].y;
  }
  std::vector<stbrp_node> nodes(static_cast<std::size_t>(width));
  stbrp_context context;
  stbrp_init_target(&context, width, maxHeight, nodes.data(), width);
  stbrp_setup_heuristic(&context, STBRP_HEURISTIC_Skyline_BL_sortHeight);
  if (!stbrp_pack_rects(&context, rects.data(), static_cast<int>(rects.size())))
    return std::nullopt;
  Packing packing;
  packing.width = width;
  packing.origin.assign(sizes.size(), glm::ivec2(0));
  for (const stbrp_rect& r : rects) {
    packing.origin[r.id] = glm::ivec2(r.x, r.y);
    packing.height = std::max(packing.height, r.y + r.h);
  }
  return packing;
}

}  // namespace

std::optional<Packing> packRectangles(const std::vector<glm::ivec2>& sizes, int maxSize) {
  if (sizes.empty()) return Packing{1, 1, {}};
  double area = 0.0;
  int widest = 1;
  for (const glm::ivec2 s : sizes) {
    area += static_cast<double>(s.x) * s.y;
    widest = std::max(widest, s.x);
  }
  const int start = std::max(widest, static_cast<int>(std::ceil(std::sqrt(area))));
  std::optional<Packing> best;
  for (int step = 0; step <= 16; ++step) {
    const int width = std::min(maxSize, static_cast<int>(std::ceil(start * (1.0 + step / 16.0))));
    std::optional<Packing> packing = packInto(sizes, width, maxSize);
    if (packing) {
      const auto cost = [](const Packing& p) { return static_cast<double>(p.width) * p.height; };
      // Smaller atlases win; among equal ones the squarer (first tried).
      if (!best || cost(*packing) < cost(*best)) best = std::move(packing);
    }
    if (width == maxSize) break;
  }
  return best;
}

}  // namespace bounce
