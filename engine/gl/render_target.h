// An offscreen linear HDR target: an RGBA32F colour texture (radiance, W/(sr·m²), unclamped)
// and a 32-bit float depth texture (window depth, readable by later passes, e.g. debug views).
// Readback gives a bounce::Image with rows top to bottom.
#pragma once

#include <cstdint>

#include "gl/depth_texture.h"
#include "gl/texture.h"
#include "image/image.h"

namespace bounce::gl {

class RenderTarget {
 public:
  RenderTarget(int width, int height);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // Binds it for drawing and sets the viewport to cover it.
  void bind() const;
  // Waits for the GPU and returns the colour's RGB, top row first.
  Image read() const;
  const Texture2D& color() const { return color_; }
  const DepthTexture2D& depth() const { return depth_; }
  int width() const { return color_.width(); }
  int height() const { return color_.height(); }

 private:
  Texture2D color_;
  DepthTexture2D depth_;
  uint32_t framebuffer_ = 0;
};

// Binds the window's own framebuffer (GLFW) with a viewport of width x height pixels.
void bindDefaultFramebuffer(int width, int height);

}  // namespace bounce::gl
