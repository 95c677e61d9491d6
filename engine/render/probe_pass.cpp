#include "render/probe_pass.h"

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

ProbePass::ProbePass() : buffer_(std::in_place, std::span<const glm::vec4>{}) {}

void ProbePass::attach(const IrradianceProbes& probes, std::size_t instances) {
  const std::vector<glm::vec4> texels = probeTexels(probes);
  buffer_.reset();
  buffer_.emplace(std::span<const glm::vec4>(texels));
  grids_ = probes.grids;
  gridOf_.assign(instances, -1);
  for (std::size_t g = 0; g < grids_.size(); ++g)
    if (grids_[g].instance < instances) gridOf_[grids_[g].instance] = static_cast<int>(g);
  probeCount_ = probes.probes.size();
}

void ProbePass::bind(gl::Program& program) const {
  program.set("uProbes", TextureUnit::kProbes);
  buffer_->bind(TextureUnit::kProbes);
}

void ProbePass::setInstance(gl::Program& program, std::size_t index) const {
  if (!probeLit(index)) {
    program.set("uHasProbes", 0);
    return;
  }
  const ProbeGrid& g = grids_[static_cast<std::size_t>(gridOf_[index])];
  program.set("uHasProbes", 1);
  program.set("uProbeFirst", static_cast<int>(g.first));
  program.set("uProbeCounts", glm::ivec3(g.counts));
  program.set("uProbeOrigin", g.origin);
  program.set("uProbeSpacing", g.spacing);
  program.set("uProbeNormalOffset", g.normalOffset);
}

}  // namespace bounce
