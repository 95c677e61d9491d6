#include "gl/render_target.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "gl/driver_quirks.h"
#include "gl/gl_functions.h"

namespace bounce::gl {

namespace {

// Checked before any member is built, so the message names the render target.
int checkedSize(int width, int height) {
  if (width <= 0 || height <= 0 || width > Texture2D::maxSize() || height > Texture2D::maxSize())
    throw std::invalid_argument("render target of " + std::to_string(width) + "x" +
                                std::to_string(height) + " pixels (the driver allows 1 to " +
                                std::to_string(Texture2D::maxSize()) + ")");
  return height;
}

}  // namespace

RenderTarget::RenderTarget(int width, int height) : depth_(width, checkedSize(width, height)) {
  color_.width_ = width;
  color_.height_ = height;
  glGenTextures(1, &color_.id_);
  glBindTexture(GL_TEXTURE_2D, color_.id_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.id_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id_, 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &framebuffer_);
    throw std::runtime_error("the driver cannot render to an RGBA32F + depth32F framebuffer");
  }
}

RenderTarget::~RenderTarget() {
  glDeleteFramebuffers(1, &framebuffer_);
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width(), height());
}

Image RenderTarget::read() const {
  const int w = width(), h = height();
  std::vector<float> rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glFinish();
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  static_assert(kDriverQuirks.readPixelsBottomUp);
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    const float* row =
        rgba.data() + static_cast<std::size_t>(h - 1 - y) * static_cast<std::size_t>(w) * 4;
    for (int x = 0; x < w; ++x) {
      const float* p = row + static_cast<std::size_t>(x) * 4;
      image.at(x, y) = glm::vec3(p[0], p[1], p[2]);
    }
  }
  return image;
}

void bindDefaultFramebuffer(int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
}

}  // namespace bounce::gl
