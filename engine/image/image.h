// A linear-RGB float image, rows top to bottom. Pixel values are whatever the producer states
// (radiance in W/(sr·m²) for camera renders, irradiance in W/m² for lightmaps).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> pixels;  // width*height, row-major, top row first

  Image() = default;
  Image(int w, int h, glm::vec3 fill = glm::vec3(0))
      : width(w),
        height(h),
        pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}

  glm::vec3& at(int x, int y) { return pixels[index(x, y)]; }
  const glm::vec3& at(int x, int y) const { return pixels[index(x, y)]; }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
  }
  bool allFinite() const;
};

// Each k×k block of `image` averaged into one pixel (a box-filtered supersample: the rasterizer
// samples points, the path tracer averages each pixel's area); the size is rounded down to
// whole blocks. k ≥ 1.
Image boxDownsample(const Image& image, int k);

}  // namespace bounce
