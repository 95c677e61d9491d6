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

int checkedSamples(int samples) {
  if (samples < 1 || samples > RenderTarget::maxSamples())
    throw std::invalid_argument("multisampling with " + std::to_string(samples) +
                                " samples per pixel (the driver allows 1 to " +
                                std::to_string(RenderTarget::maxSamples()) + ")");
  return samples;
}

}  // namespace

int RenderTarget::maxSamples() {
  GLint samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &samples);
  return samples;
}

RenderTarget::RenderTarget(int width, int height, int samples)
    : depth_(width, checkedSize(width, height)), samples_(checkedSamples(samples)) {
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
  if (samples_ == 1) return;
  glGenRenderbuffers(1, &multisampleColor_);
  glBindRenderbuffer(GL_RENDERBUFFER, multisampleColor_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA32F, width, height);
  glGenRenderbuffers(1, &multisampleDepth_);
  glBindRenderbuffer(GL_RENDERBUFFER, multisampleDepth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT32F, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &multisampleFramebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, multisampleFramebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            multisampleColor_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            multisampleDepth_);
  const GLenum multisampleStatus = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (multisampleStatus != GL_FRAMEBUFFER_COMPLETE) {
    release();
    throw std::runtime_error(
        "the driver cannot render to an RGBA32F + depth32F framebuffer "
        "with " +
        std::to_string(samples_) + " samples per pixel");
  }
}

RenderTarget::~RenderTarget() {
  release();
}

void RenderTarget::release() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteFramebuffers(1, &multisampleFramebuffer_);
  glDeleteRenderbuffers(1, &multisampleColor_);
  glDeleteRenderbuffers(1, &multisampleDepth_);
  framebuffer_ = multisampleFramebuffer_ = multisampleColor_ = multisampleDepth_ = 0;
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? multisampleFramebuffer_ : framebuffer_);
  glViewport(0, 0, width(), height());
}

void RenderTarget::resolve() const {
  if (samples_ == 1) return;
  // A blit from a multisampled to a single-sampled buffer of the same size converts each
  // pixel's samples to one value: the mean for colour; depth takes one sample (NEAREST).
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampleFramebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
  glBlitFramebuffer(0, 0, width(), height(), 0, 0, width(), height(),
                    GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
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

Image readWindowPixels(int width, int height) {
  std::vector<float> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glFinish();
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* p = rgba.data() +
                       (static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) +
                        static_cast<std::size_t>(x)) *
                           4;
      image.at(x, y) = glm::vec3(p[0], p[1], p[2]);
    }
  return image;
}

void bindDefaultFramebuffer(int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
}

}  // namespace bounce::gl
