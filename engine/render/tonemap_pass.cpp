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

void TonemapPass::draw(const gl::Texture2D& radiance, float exposureEV) {
  gl::setDepthTest(false);
  gl::setBackFaceCulling(false);
  radiance.bind(0);
  gpu_->program.set("uRadiance", 0);
  gpu_->program.set("uExposureEV", exposureEV);
  gl::drawFullscreenTriangle();
  gl::checkErrors("tone-map pass");
}

}  // namespace bounce
