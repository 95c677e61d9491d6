#include "render/probe_pass.h"

#include "bake_folder/irradiance_probes.h"
#include "gl/texture.h"
#include "render/shader_constants.h"
#include "render/texture_units.h"

namespace bounce {

std::vector<glm::vec4> probeTexels(const IrradianceProbes& probes) {
  std::vector<glm::vec4> texels;
  texels.reserve(3 * probes.probes.size());
  for (const ProbeIrradiance& p : probes.probes)
    for (int c = 0; c < 3; ++c)
      texels.emplace_back(kShY00 * p.sh[0][c], kShY1 * p.sh[3][c], kShY1 * p.sh[1][c],
                          kShY1 * p.sh[2][c]);
  return texels;
}

std::vector<glm::vec4> cornerVisibilityTexels(const ProbeVisibility& visibility) {
  std::vector<glm::vec4> texels;
  texels.reserve(2 * visibility.corners.size());
  for (const TexelVisibility& corner : visibility.corners) {
    glm::vec4 lights, visible;
    for (int s = 0; s < kVisibilitySlots; ++s) {
      const uint16_t l = corner.light[s];
      lights[s] = l == kNoLight       ? -1.0f
                  : l == kOtherLights ? kVisibilityOtherLightsCode
                                      : static_cast<float>(l);
      visible[s] = corner.visible[s];
    }
    texels.push_back(lights);
    texels.push_back(visible);
  }
  return texels;
}

ProbePass::ProbePass()
    : buffer_(std::in_place, std::span<const glm::vec4>{}),
      corners_(std::in_place, std::span<const glm::vec4>{}) {}

void ProbePass::attach(const IrradianceProbes& probes, std::size_t instances, bool visibility) {
  const std::vector<glm::vec4> texels = probeTexels(probes);
  buffer_.reset();
  buffer_.emplace(std::span<const glm::vec4>(texels));
  const std::vector<glm::vec4> corners = cornerVisibilityTexels(probes.visibility);
  visibility_ = visibility && !corners.empty() && corners.size() <= gl::TextureBuffer::maxTexels();
  corners_.reset();
  corners_.emplace(visibility_ ? std::span<const glm::vec4>(corners)
                               : std::span<const glm::vec4>{});
  grids_.clear();
  gridOf_.assign(instances, -1);
  for (const ProbeGrid& g : probes.grids) {
    if (g.instance < instances) gridOf_[g.instance] = static_cast<int>(grids_.size());
    grids_.push_back({static_cast<int>(g.first), glm::ivec3(g.counts), g.origin, g.spacing,
                      g.normalOffset, static_cast<int>(g.firstCorner),
                      static_cast<int>(g.cornerCount)});
  }
  probeCount_ = probes.probes.size();
  staticDirect_.reset();
}

void ProbePass::attachStaticDirect(std::span<const glm::vec4> corners) {
  staticDirect_.reset();
  if (!visibility_ || corners.empty() || corners.size() > gl::TextureBuffer::maxTexels() ||
      gl::Texture2D::maxFragmentUnits() <= TextureUnit::kCornerStaticDirect)
    return;
  staticDirect_.emplace(corners);
}

void ProbePass::bind(gl::Program& program) const {
  program.set("uProbes", TextureUnit::kProbes);
  buffer_->bind(TextureUnit::kProbes);
  program.set("uCornerVisibility", TextureUnit::kCornerVisibility);
  corners_->bind(TextureUnit::kCornerVisibility);
  if (staticDirect_) {
    program.set("uCornerStaticDirect", TextureUnit::kCornerStaticDirect);
    staticDirect_->bind(TextureUnit::kCornerStaticDirect);
  } else {
    program.set("uCornerStaticDirect", TextureUnit::kProbes);  // never read; a samplerBuffer unit
  }
}

void ProbePass::setInstance(gl::Program& program, std::size_t index) const {
  program.set("uHasCornerVisibility", 0);
  program.set("uHasCornerStaticDirect", cornerVisibility(index) && staticDirect_ ? 1 : 0);
  if (!probeLit(index)) {
    program.set("uHasProbes", 0);
    return;
  }
  const Grid& g = grids_[static_cast<std::size_t>(gridOf_[index])];
  if (cornerVisibility(index)) {
    // In place of the lightmap's table (LightmapPass::setInstance set it false: no region).
    program.set("uHasBakedVisibility", 1);
    program.set("uHasCornerVisibility", 1);
    program.set("uCornerVisibilityFirst", g.firstCorner);
  }
  program.set("uHasProbes", 1);
  program.set("uProbeFirst", g.first);
  program.set("uProbeCounts", g.counts);
  program.set("uProbeOrigin", g.origin);
  program.set("uProbeSpacing", g.spacing);
  program.set("uProbeNormalOffset", g.normalOffset);
}

}  // namespace bounce
