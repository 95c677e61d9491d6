#include "render/tonemap_pass.h"

#include "gl/draw_state.h"
#include "gl/shader.h"
#include "render/shader_constants.h"

namespace bounce {

struct TonemapPass::Gpu {
  gl::Program program;
};

TonemapPass::TonemapPass(const std::filesystem::path& shaderDir)
    : gpu_(std::make_unique<Gpu>(Gpu{gl::Program(
          shaderDir / "fullscreen.vert", shaderDir / "tonemap.frag", shaderConstants())})) {}

TonemapPass::~TonemapPass() = default;

void TonemapPass::draw(const gl::Texture2D& radiance, float exposureEV,
                       std::optional<CostDisplay> cost) {
  gl::setDepthTest(false);
  gl::setBackFaceCulling(false);
  radiance.bind(0);
  gpu_->program.set("uRadiance", 0);
  gpu_->program.set("uExposureEV", exposureEV);
  gpu_->program.set("uCostChannel", cost ? static_cast<int>(cost->count) : -1);
  gpu_->program.set("uCostMax", cost ? cost->scaleMax : 1.0f);
  gpu_->program.set("uCostLegendRows", costLegendRows(radiance.height()));
  gl::drawFullscreenTriangle();
  gl::checkErrors("tone-map pass");
}

}  // namespace bounce
