// The viewer's frame beside a reference image (render/reference_view.h: split screen or a
// false-colour relative difference), drawn in radiance into a target of its own that the tone
// mapper and the captures then read (shaders/reference_compare.frag). GL calls only through
// engine/gl.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "gl/render_target.h"
#include "gl/shader.h"
#include "gl/texture.h"
#include "image/image.h"
#include "render/reference_view.h"

namespace bounce {

class ReferenceComparePass {
 public:
  explicit ReferenceComparePass(const std::filesystem::path& shaderDir);

  // Uploads `reference` (radiance, rows top first); throws std::invalid_argument for an empty
  // image or one larger than the driver's textures.
  void setReference(const Image& reference);
  bool hasReference() const { return reference_.has_value(); }
  int referenceWidth() const { return reference_ ? reference_->width() : 0; }
  int referenceHeight() const { return reference_ ? reference_->height() : 0; }

  // Composes `frame` (resolved radiance) with the reference as `view` (Split or Difference)
  // into `out` (one sample per pixel, the frame's size).
  void draw(const gl::Texture2D& frame, gl::RenderTarget& out, ReferenceView view);

 private:
  gl::Program program_;
  std::optional<gl::Texture2D> reference_;
};

}  // namespace bounce
