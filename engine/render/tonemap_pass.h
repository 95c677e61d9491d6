// The viewer's display pass: draws a radiance texture to the bound framebuffer through
// shaders/tonemap.glsl, the GLSL mirror of bounce::toneMap (engine/image/tonemap.h).
#pragma once

#include <filesystem>
#include <memory>

#include "gl/texture.h"

namespace bounce {

class TonemapPass {
 public:
  explicit TonemapPass(const std::filesystem::path& shaderDir);
  ~TonemapPass();
  TonemapPass(const TonemapPass&) = delete;
  TonemapPass& operator=(const TonemapPass&) = delete;

  // Fills the bound framebuffer's viewport with toneMap(radiance, exposureEV).
  void draw(const gl::Texture2D& radiance, float exposureEV);

 private:
  struct Gpu;
  std::unique_ptr<Gpu> gpu_;
};

}  // namespace bounce
