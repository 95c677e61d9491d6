// The lit pass's one light table: a single RGBA32F texture buffer (gl/texture_buffer.h, GL 3.3
// core) on one texture unit, holding every light the fragment shader loops over, so that no
// light kind has a fixed cap and the light kinds together take one of the 16 units GL 3.3
// guarantees. Sections, in this order (shaders/light_table.glsl reads them):
//
//   punctual lights  4 texels each (render/punctual_lights.h): (position m, type),
//                    (unit direction of travel, shadow slot or −1), (power: W/sr or W/m², 0),
//                    (cos inner, cos outer, 0, 0)
//   VPL lights       3 texels each (render/vpl_pass.h): (position m, group), (unit normal, 0),
//                    (Φ W, 0)
//   VPL cuts         1 texel each: (first, count, 0, 0): per grid cell a range of entries, then
//                    the entries, each a range of VPL lights
//   cluster headers  1 texel per view cluster (render/light_grid.h): (first entry, punctual
//                    count, area count, 0); empty while light culling is off
//   cluster entries  4 light indices per texel
//
// The cluster sections change whenever the view moves; the table is then uploaded again whole.
//
// Indices and counts are stored as floats: exact below 2^24, so the whole table is held to
// 2^24 texels (and to GL_MAX_TEXTURE_BUFFER_SIZE); beyond either, update() throws naming both.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "gl/shader.h"
#include "gl/texture_buffer.h"

namespace bounce {

// Largest table: float holds every integer up to 2^24 exactly.
inline constexpr std::size_t kMaxLightTableTexels = std::size_t{1} << 24;

class LightTable {
 public:
  void setPunctual(std::vector<glm::vec4> texels);
  void setVpls(std::vector<glm::vec4> lightTexels, std::vector<glm::vec4> cutTexels);
  void setClusters(std::vector<glm::vec4> headers, std::vector<glm::vec4> entries);

  // Uploads what changed since the last call (one buffer for all sections).
  void update();
  // Binds the buffer on TextureUnit::kLightTable and sets uLightTable and the section uniforms
  // (uPunctualCount, uVplLightsFirst, uVplCutsFirst, uClustersFirst, uClusterEntriesFirst).
  // update() first.
  void bind(gl::Program& program) const;

  std::size_t punctualCount() const { return punctual_.size() / 4; }

 private:
  std::vector<glm::vec4> punctual_, vplLights_, vplCuts_, clusters_, clusterEntries_;
  std::optional<gl::TextureBuffer> buffer_;
  bool dirty_ = true;
};

}  // namespace bounce
