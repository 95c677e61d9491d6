#include "gl/texture_buffer.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "gl/gl_functions.h"

namespace bounce::gl {

TextureBuffer::TextureBuffer(std::span<const glm::vec4> texels) {
  const glm::vec4 zero(0.0f);
  if (texels.empty()) texels = std::span(&zero, 1);
  create(texels.data(), texels.size_bytes(), texels.size(), GL_RGBA32F);
}

TextureBuffer::TextureBuffer(std::span<const glm::uvec2> texels) {
  const glm::uvec2 zero(0u);
  if (texels.empty()) texels = std::span(&zero, 1);
  create(texels.data(), texels.size_bytes(), texels.size(), GL_RG32UI);
}

void TextureBuffer::create(const void* data, std::size_t bytes, std::size_t texels,
                           uint32_t format) {
  if (texels > maxTexels())
    throw std::runtime_error("texture buffer of " + std::to_string(texels) +
                             " texels: the driver's limit is " + std::to_string(maxTexels()));
  size_ = texels;
  glGenBuffers(1, &buffer_);
  glBindBuffer(GL_TEXTURE_BUFFER, buffer_);
  glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_BUFFER, texture_);
  glTexBuffer(GL_TEXTURE_BUFFER, format, buffer_);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

TextureBuffer::~TextureBuffer() {
  if (texture_) glDeleteTextures(1, &texture_);
  if (buffer_) glDeleteBuffers(1, &buffer_);
}

TextureBuffer::TextureBuffer(TextureBuffer&& other) noexcept
    : buffer_(std::exchange(other.buffer_, 0)),
      texture_(std::exchange(other.texture_, 0)),
      size_(other.size_) {}

void TextureBuffer::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_BUFFER, texture_);
}

std::size_t TextureBuffer::maxTexels() {
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &size);
  return static_cast<std::size_t>(size);
}

}  // namespace bounce::gl
