// Buffer textures (GL 3.3 core GL_TEXTURE_BUFFER): a 1D table of any length up to
// GL_MAX_TEXTURE_BUFFER_SIZE texels, read in shaders with texelFetch(samplerBuffer, i) or
// texelFetch(usamplerBuffer, i). Used for light tables with no fixed cap (the VPLs).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace bounce::gl {

class TextureBuffer {
 public:
  // RGBA32F texels (samplerBuffer). An empty span makes one zero texel (the sampler needs a
  // texture of its type even when nothing is read).
  explicit TextureBuffer(std::span<const glm::vec4> texels);
  // RG32UI texels (usamplerBuffer), the same way.
  explicit TextureBuffer(std::span<const glm::uvec2> texels);
  ~TextureBuffer();
  TextureBuffer(TextureBuffer&& other) noexcept;
  TextureBuffer& operator=(TextureBuffer&&) = delete;
  TextureBuffer(const TextureBuffer&) = delete;
  TextureBuffer& operator=(const TextureBuffer&) = delete;

  void bind(int unit) const;
  std::size_t size() const { return size_; }  // texels
  // GL_MAX_TEXTURE_BUFFER_SIZE of the current context (texels; ≥ 65536 in GL 3.3).
  static std::size_t maxTexels();

 private:
  void create(const void* data, std::size_t bytes, std::size_t texels, uint32_t format);
  uint32_t buffer_ = 0;
  uint32_t texture_ = 0;
  std::size_t size_ = 0;
};

}  // namespace bounce::gl
