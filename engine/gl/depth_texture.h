// Depth textures for shadow maps (32-bit float depth in [0,1]) that shaders read with hardware
// comparison: `sampler2DShadow` / `samplerCubeShadow` / `sampler2DArrayShadow` return the
// fraction of the 2×2 nearest texels whose stored depth d satisfies ref ≤ d (bilinearly
// weighted: GL_LINEAR comparison), i.e. 1 = lit. Outside a 2D map the border depth is 1 (the far
// plane): lit.
#pragma once

#include <cstdint>

namespace bounce::gl {

class DepthTexture2D {
 public:
  DepthTexture2D(int width, int height);
  ~DepthTexture2D();
  DepthTexture2D(DepthTexture2D&& other) noexcept;
  // The moved-from texture takes this one's name and deletes it.
  DepthTexture2D& operator=(DepthTexture2D&& other) noexcept;
  DepthTexture2D(const DepthTexture2D&) = delete;
  DepthTexture2D& operator=(const DepthTexture2D&) = delete;

  void bind(int unit) const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  friend class DepthTarget;
  friend class RenderTarget;
  uint32_t id_ = 0;
  int width_ = 0, height_ = 0;
};

// Six square faces in GL's cube-map order (+X, −X, +Y, −Y, +Z, −Z).
class DepthCubeMap {
 public:
  explicit DepthCubeMap(int size);
  ~DepthCubeMap();
  DepthCubeMap(DepthCubeMap&& other) noexcept;
  DepthCubeMap& operator=(DepthCubeMap&& other) noexcept;
  DepthCubeMap(const DepthCubeMap&) = delete;
  DepthCubeMap& operator=(const DepthCubeMap&) = delete;

  void bind(int unit) const;
  int size() const { return size_; }

 private:
  friend class DepthTarget;
  uint32_t id_ = 0;
  int size_ = 0;
};

// `layers` square layers of `size`² texels (GL_TEXTURE_2D_ARRAY): many small maps in one
// texture unit, read by a `sampler2DArrayShadow` with the layer as the third coordinate
// (GL 3.3 core has no cube-map arrays). Clamped to the edge of each layer.
class DepthTextureArray {
 public:
  DepthTextureArray(int size, int layers);
  static int maxLayers();  // GL_MAX_ARRAY_TEXTURE_LAYERS of the current context (GL 3.3: ≥ 256)
  ~DepthTextureArray();
  DepthTextureArray(DepthTextureArray&& other) noexcept;
  DepthTextureArray& operator=(DepthTextureArray&&) = delete;
  DepthTextureArray(const DepthTextureArray&) = delete;
  DepthTextureArray& operator=(const DepthTextureArray&) = delete;

  void bind(int unit) const;
  int size() const { return size_; }
  int layers() const { return layers_; }

 private:
  friend class DepthTarget;
  uint32_t id_ = 0;
  int size_ = 0, layers_ = 0;
};

// A depth-only framebuffer (no colour): a pass renders into one depth texture or one cube face.
class DepthTarget {
 public:
  DepthTarget();
  ~DepthTarget();
  DepthTarget(const DepthTarget&) = delete;
  DepthTarget& operator=(const DepthTarget&) = delete;

  // Attaches the texture (or cube face 0..5), binds for drawing, sets the viewport to cover it.
  // Throws std::runtime_error if the driver cannot render to it.
  void bind(const DepthTexture2D& texture);
  void bind(const DepthCubeMap& cube, int face);
  void bind(const DepthTextureArray& array, int layer);

 private:
  void check();
  uint32_t framebuffer_ = 0;
};

}  // namespace bounce::gl
