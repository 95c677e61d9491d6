#include "gl/texture_array.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "gl/gl_functions.h"

namespace bounce::gl {

TextureArray2D::TextureArray2D(int width, int height, int layers,
                               std::span<const glm::vec3> texels) {
  if (width <= 0 || height <= 0 || layers <= 0 ||
      texels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                           static_cast<std::size_t>(layers))
    throw std::invalid_argument("texture array of " + std::to_string(width) + "x" +
                                std::to_string(height) + "x" + std::to_string(layers) + " with " +
                                std::to_string(texels.size()) + " texels");
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGB32F, width, height, layers, 0, GL_RGB, GL_FLOAT,
               texels.data());
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

TextureArray2D::~TextureArray2D() {
  if (id_) glDeleteTextures(1, &id_);
}

TextureArray2D::TextureArray2D(TextureArray2D&& other) noexcept
    : id_(std::exchange(other.id_, 0)) {}

void TextureArray2D::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
}

}  // namespace bounce::gl
