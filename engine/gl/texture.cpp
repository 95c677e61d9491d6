#include "gl/texture.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "gl/gl_functions.h"

namespace bounce::gl {
namespace {

void requireSize(int width, int height, std::size_t count) {
  if (width <= 0 || height <= 0 ||
      count != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw std::invalid_argument("texture of " + std::to_string(width) + "x" +
                                std::to_string(height) + " with " + std::to_string(count) +
                                " texels");
}

void setSampling(GLint filter, GLint wrap) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
}

}  // namespace

Texture2D::Texture2D(int width, int height, std::span<const glm::vec3> texels, Filter filter,
                     Wrap wrap)
    : width_(width), height_(height) {
  requireSize(width, height, texels.size());
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, width, height, 0, GL_RGB, GL_FLOAT, texels.data());
  setSampling(filter == Filter::Linear ? GL_LINEAR : GL_NEAREST,
              wrap == Wrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE);
}

Texture2D::Texture2D(int width, int height, std::span<const glm::vec4> texels)
    : width_(width), height_(height) {
  requireSize(width, height, texels.size());
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, texels.data());
  setSampling(GL_NEAREST, GL_CLAMP_TO_EDGE);
}

Texture2D::~Texture2D() {
  if (id_) glDeleteTextures(1, &id_);
}

Texture2D::Texture2D(Texture2D&& other) noexcept
    : id_(std::exchange(other.id_, 0)), width_(other.width_), height_(other.height_) {}

void Texture2D::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D, id_);
}

int Texture2D::maxSize() {
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  return size;
}

int Texture2D::maxFragmentUnits() {
  GLint units = 0;
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
  return units;
}

}  // namespace bounce::gl
