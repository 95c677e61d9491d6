// An offscreen linear HDR target: an RGBA32F colour texture (radiance, W/(sr·m²), unclamped)
// and a 32-bit float depth texture (window depth, readable by later passes, e.g. debug views).
// Readback gives a bounce::Image with rows top to bottom.
//
// With samples > 1 (multisample anti-aliasing) drawing goes to multisampled RGBA32F and
// depth32F renderbuffers, and resolve() averages each pixel's samples into the textures: the
// radiance is box-filtered over the pixel in linear units, before any tone mapping, as the
// path tracer filters its pixels. Shading runs once per pixel and primitive; only coverage and
// depth are per sample.
#pragma once

#include <cstdint>

#include "gl/depth_texture.h"
#include "gl/texture.h"
#include "image/image.h"

namespace bounce::gl {

class RenderTarget {
 public:
  // samples: 1 (no multisampling) to maxSamples(); throws std::invalid_argument beyond.
  RenderTarget(int width, int height, int samples = 1);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // Binds it for drawing (the multisampled buffers when samples > 1) and sets the viewport.
  void bind() const;
  // Averages the samples of what was drawn into color() and depth() (the depth of one sample:
  // depth does not average); nothing to do with one sample. Call after drawing, before
  // color(), depth() or read() are used.
  void resolve() const;
  // Waits for the GPU and returns the colour's RGB, top row first (resolved).
  Image read() const;
  const Texture2D& color() const { return color_; }
  const DepthTexture2D& depth() const { return depth_; }
  int width() const { return color_.width(); }
  int height() const { return color_.height(); }
  int samples() const { return samples_; }
  // The most samples the driver gives a float colour target (GL_MAX_SAMPLES; at least 4 by the
  // GL 3.3 specification).
  static int maxSamples();

 private:
  void release();  // the framebuffers and renderbuffers (the textures free themselves)

  Texture2D color_;
  DepthTexture2D depth_;
  uint32_t framebuffer_ = 0;
  int samples_ = 1;
  uint32_t multisampleFramebuffer_ = 0;  // with its two renderbuffers, only when samples_ > 1
  uint32_t multisampleColor_ = 0;
  uint32_t multisampleDepth_ = 0;
};

// Binds the window's own framebuffer (GLFW) with a viewport of width x height pixels.
void bindDefaultFramebuffer(int width, int height);
// The window's back buffer as drawn so far (display values in [0, 1], sRGB-encoded: what the
// screen shows, panel included), top row first.
Image readWindowPixels(int width, int height);

}  // namespace bounce::gl
