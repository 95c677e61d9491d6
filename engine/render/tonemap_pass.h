// The viewer's display pass: draws a radiance texture to the bound framebuffer through
// shaders/tonemap.glsl, the GLSL mirror of bounce::toneMap (engine/image/tonemap.h).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "gl/texture.h"
#include "render/cost_view.h"

namespace bounce {

class TonemapPass {
 public:
  explicit TonemapPass(const std::filesystem::path& shaderDir);
  ~TonemapPass();
  TonemapPass(const TonemapPass&) = delete;
  TonemapPass& operator=(const TonemapPass&) = delete;

  // Fills the bound framebuffer's viewport with toneMap(radiance, exposureEV); with `cost`, the
  // texture holds the cost view's counts and one of them is drawn in false colour with its
  // legend bar (render/cost_view.h, shaders/cost_colour.glsl).
  struct CostDisplay {
    CostCount count = CostCount::Vpls;
    float scaleMax = 1.0f;
  };
  void draw(const gl::Texture2D& radiance, float exposureEV,
            std::optional<CostDisplay> cost = std::nullopt);

 private:
  struct Gpu;
  std::unique_ptr<Gpu> gpu_;
};

}  // namespace bounce
