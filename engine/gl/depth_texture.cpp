#include "gl/depth_texture.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "gl/gl_functions.h"
#include "gl/texture.h"

namespace bounce::gl {
namespace {

void requireSize(int width, int height) {
  if (width <= 0 || height <= 0 || width > Texture2D::maxSize() || height > Texture2D::maxSize())
    throw std::invalid_argument("depth texture of " + std::to_string(width) + "x" +
                                std::to_string(height) + " texels (the driver allows 1 to " +
                                std::to_string(Texture2D::maxSize()) + ")");
}

// Comparison sampling: result = Σ w·(ref ≤ depth) over the bilinear footprint.
void setComparison(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

}  // namespace

DepthTexture2D::DepthTexture2D(int width, int height) : width_(width), height_(height) {
  requireSize(width, height);
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, width, height, 0, GL_DEPTH_COMPONENT,
               GL_FLOAT, nullptr);
  setComparison(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float far[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, far);
  glBindTexture(GL_TEXTURE_2D, 0);
}

DepthTexture2D::~DepthTexture2D() {
  if (id_) glDeleteTextures(1, &id_);
}

DepthTexture2D::DepthTexture2D(DepthTexture2D&& other) noexcept
    : id_(std::exchange(other.id_, 0)), width_(other.width_), height_(other.height_) {}

DepthTexture2D& DepthTexture2D::operator=(DepthTexture2D&& other) noexcept {
  std::swap(id_, other.id_);
  width_ = other.width_;
  height_ = other.height_;
  return *this;
}

void DepthTexture2D::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D, id_);
}

DepthCubeMap::DepthCubeMap(int size) : size_(size) {
  requireSize(size, size);
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_CUBE_MAP, id_);
  for (int face = 0; face < 6; ++face)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face), 0,
                 GL_DEPTH_COMPONENT32F, size, size, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  setComparison(GL_TEXTURE_CUBE_MAP);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

DepthCubeMap::~DepthCubeMap() {
  if (id_) glDeleteTextures(1, &id_);
}

DepthCubeMap::DepthCubeMap(DepthCubeMap&& other) noexcept
    : id_(std::exchange(other.id_, 0)), size_(other.size_) {}

DepthCubeMap& DepthCubeMap::operator=(DepthCubeMap&& other) noexcept {
  std::swap(id_, other.id_);
  size_ = other.size_;
  return *this;
}

void DepthCubeMap::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_CUBE_MAP, id_);
}

int DepthTextureArray::maxLayers() {
  GLint layers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
  return layers;
}

DepthTextureArray::DepthTextureArray(int size, int layers) : size_(size), layers_(layers) {
  requireSize(size, size);
  const int limit = maxLayers();
  if (layers <= 0 || layers > limit)
    throw std::invalid_argument("depth texture array of " + std::to_string(layers) +
                                " layers (the driver allows 1 to " + std::to_string(limit) + ")");
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, size, size, layers, 0,
               GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  setComparison(GL_TEXTURE_2D_ARRAY);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

DepthTextureArray::~DepthTextureArray() {
  if (id_) glDeleteTextures(1, &id_);
}

DepthTextureArray::DepthTextureArray(DepthTextureArray&& other) noexcept
    : id_(std::exchange(other.id_, 0)), size_(other.size_), layers_(other.layers_) {}

void DepthTextureArray::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
}

DepthTarget::DepthTarget() {
  glGenFramebuffers(1, &framebuffer_);
}

DepthTarget::~DepthTarget() {
  glDeleteFramebuffers(1, &framebuffer_);
}

void DepthTarget::bind(const DepthTexture2D& texture) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture.id_, 0);
  check();
  glViewport(0, 0, texture.width_, texture.height_);
}

void DepthTarget::bind(const DepthCubeMap& cube, int face) {
  if (face < 0 || face > 5)
    throw std::invalid_argument("cube face " + std::to_string(face) + " (faces are 0..5)");
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                         GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face), cube.id_, 0);
  check();
  glViewport(0, 0, cube.size_, cube.size_);
}

void DepthTarget::bind(const DepthTextureArray& array, int layer) {
  if (layer < 0 || layer >= array.layers_)
    throw std::invalid_argument("layer " + std::to_string(layer) + " of a depth array of " +
                                std::to_string(array.layers_));
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, array.id_, 0, layer);
  check();
  glViewport(0, 0, array.size_, array.size_);
}

void DepthTarget::check() {
  // Depth only: no colour buffer is drawn or read.
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    throw std::runtime_error("the driver cannot render to a depth32F-only framebuffer (status " +
                             std::to_string(status) + ")");
  }
}

}  // namespace bounce::gl
