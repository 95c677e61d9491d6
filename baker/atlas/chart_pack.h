// Packing: places rectangles (charts with their padding) without overlap in the smallest atlas
// found, with stb_rect_pack's skyline packer (libstb). Internal to the atlas.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

struct Packing {
  int width = 0, height = 0;       // texels
  std::vector<glm::ivec2> origin;  // lower corner of each rectangle, texels
};

// Tries atlas widths from the square root of the total area up to twice it and keeps the
// smallest width × height (the height is what the packer used). Nothing when the rectangles do
// not fit in maxSize × maxSize.
std::optional<Packing> packRectangles(const std::vector<glm::ivec2>& sizes, int maxSize);

}  // namespace bounce
