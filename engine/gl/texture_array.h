// A 2D array of RGB32F images of one size, sampled bilinearly per layer (sampler2DArray): one
// texture unit for several maps of the same atlas (render/static_direct_texels.h: one layer per
// colour channel).
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace bounce::gl {

class TextureArray2D {
 public:
  // `layers` images of width × height texels each, one after the other, rows as given; linear
  // filtering within a layer, clamped at the borders (an atlas's lookups must not wrap).
  TextureArray2D(int width, int height, int layers, std::span<const glm::vec3> texels);
  ~TextureArray2D();
  TextureArray2D(TextureArray2D&& other) noexcept;
  TextureArray2D& operator=(TextureArray2D&&) = delete;
  TextureArray2D(const TextureArray2D&) = delete;
  TextureArray2D& operator=(const TextureArray2D&) = delete;

  void bind(int unit) const;

 private:
  uint32_t id_ = 0;
};

}  // namespace bounce::gl
