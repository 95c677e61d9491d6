// 2D float textures: material images (linear RGB) and data tables that shaders read with
// texelFetch (one RGBA32F texel per entry). Row 0 of the data is texture row t = 0, so an image
// stored top row first is sampled with glTF's convention (uv (0,0) = top-left) unflipped.
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace bounce::gl {

enum class Filter { Nearest, Linear };
// Repeat for material textures (UVs may leave [0,1]); ClampToEdge for atlases (a lightmap's
// bilinear lookups must not wrap to the opposite border).
enum class Wrap { Repeat, ClampToEdge };

class Texture2D {
 public:
  // RGB32F texels, width*height, rows as given (material textures, lightmaps).
  Texture2D(int width, int height, std::span<const glm::vec3> texels, Filter filter,
            Wrap wrap = Wrap::Repeat);
  // RGBA32F table, width*height, nearest and clamped (data for texelFetch).
  Texture2D(int width, int height, std::span<const glm::vec4> texels);
  ~Texture2D();
  Texture2D(Texture2D&& other) noexcept;
  Texture2D& operator=(Texture2D&&) = delete;
  Texture2D(const Texture2D&) = delete;
  Texture2D& operator=(const Texture2D&) = delete;

  void bind(int unit) const;
  int width() const { return width_; }
  int height() const { return height_; }
  static int maxSize();  // GL_MAX_TEXTURE_SIZE of the current context
  // GL_MAX_TEXTURE_IMAGE_UNITS of the current context: texture units a fragment shader can
  // read (GL 3.3 guarantees 16, most drivers give 32).
  static int maxFragmentUnits();

 private:
  friend class RenderTarget;
  Texture2D() = default;
  uint32_t id_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace bounce::gl
