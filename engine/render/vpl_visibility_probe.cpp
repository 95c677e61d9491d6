#include "render/vpl_visibility_probe.h"

#include "render/shader_constants.h"

#include <algorithm>
#include <stdexcept>

#include "gl/draw_state.h"
#include "gl/render_target.h"
#include "gl/texture.h"

namespace bounce {

VplVisibilityProbe::VplVisibilityProbe(const std::filesystem::path& shaderDir)
    : program_(shaderDir / "fullscreen.vert", shaderDir / "vpl_visibility_probe.frag",
               shaderConstants()) {}

std::vector<float> VplVisibilityProbe::read(const VplShadowMaps& maps, int group,
                                            std::span<const glm::vec3> positions,
                                            std::span<const glm::vec3> normals) {
  if (positions.size() != normals.size())
    throw std::invalid_argument("VPL visibility probe: positions and normals differ in count");
  std::vector<float> out;
  out.reserve(positions.size());
  constexpr std::size_t kBatch = 1024;  // receivers per draw: one row of the target
  for (std::size_t first = 0; first < positions.size(); first += kBatch) {
    const std::size_t n = std::min(kBatch, positions.size() - first);
    std::vector<glm::vec4> table(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      table[i] = glm::vec4(positions[first + i], 1.0f);
      table[n + i] = glm::vec4(normals[first + i], 0.0f);
    }
    const gl::Texture2D data(static_cast<int>(n), 2, table);
    gl::RenderTarget target(static_cast<int>(n), 1);
    target.bind();
    gl::setDepthTest(false);
    maps.bind(program_, 0);
    data.bind(1);
    program_.set("uReceivers", 1);
    program_.set("uProbeGroup", group);
    gl::drawFullscreenTriangle();
    const Image image = target.read();
    for (std::size_t i = 0; i < n; ++i) out.push_back(image.at(static_cast<int>(i), 0).x);
  }
  gl::checkErrors("VPL visibility probe");
  return out;
}

}  // namespace bounce
