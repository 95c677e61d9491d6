#include "render/reference_compare_pass.h"

#include <stdexcept>
#include <string>

#include "gl/draw_state.h"
#include "render/shader_constants.h"

namespace bounce {

ReferenceComparePass::ReferenceComparePass(const std::filesystem::path& shaderDir)
    : program_(shaderDir / "fullscreen.vert", shaderDir / "reference_compare.frag",
               shaderConstants()) {}

void ReferenceComparePass::setReference(const Image& reference) {
  if (reference.width <= 0 || reference.height <= 0)
    throw std::invalid_argument("the reference image is empty");
  if (reference.width > gl::Texture2D::maxSize() || reference.height > gl::Texture2D::maxSize())
    throw std::invalid_argument("the reference image is larger than the driver's textures (" +
                                std::to_string(gl::Texture2D::maxSize()) + " pixels a side)");
  reference_.reset();
  reference_.emplace(reference.width, reference.height, reference.pixels, gl::Filter::Nearest,
                     gl::Wrap::ClampToEdge);
}

void ReferenceComparePass::draw(const gl::Texture2D& frame, gl::RenderTarget& out,
                                ReferenceView view) {
  if (!reference_) throw std::logic_error("ReferenceComparePass::draw without a reference");
  out.bind();
  gl::setDepthTest(false);
  gl::setBackFaceCulling(false);
  frame.bind(0);
  reference_->bind(1);
  program_.set("uFrame", 0);
  program_.set("uReference", 1);
  program_.set("uView", view == ReferenceView::Difference ? 2 : 1);
  program_.set("uFrameSize",
               glm::vec2(static_cast<float>(frame.width()), static_cast<float>(frame.height())));
  program_.set("uReferenceSize", glm::vec2(static_cast<float>(reference_->width()),
                                           static_cast<float>(reference_->height())));
  gl::drawFullscreenTriangle();
  gl::checkErrors("reference comparison pass");
}

}  // namespace bounce
