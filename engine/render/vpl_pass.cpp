#include "render/vpl_pass.h"

#include <limits>

#include "render/texture_units.h"

namespace bounce {
namespace {

// Cells first, then the entries; entry offsets count from texel 0 (shaders/vpl.glsl).
std::vector<glm::uvec2> cutTexels(const VplLightCuts& cuts) {
  std::vector<glm::uvec2> texels;
  texels.reserve(cuts.cellEntries.size() + cuts.entries.size());
  const auto base = static_cast<uint32_t>(cuts.cellEntries.size());
  for (const glm::uvec2 cell : cuts.cellEntries) texels.emplace_back(base + cell.x, cell.y);
  texels.insert(texels.end(), cuts.entries.begin(), cuts.entries.end());
  return texels;
}

std::vector<glm::vec4> lightTexels(const VplGroups& groups) {
  std::vector<glm::vec4> texels;
  const std::span<const Vpl> lights = groups.lights();
  texels.reserve(3 * lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    texels.emplace_back(lights[i].position, static_cast<float>(groups.groupOf(i)));
    texels.emplace_back(lights[i].normal, 0.0f);
    texels.emplace_back(lights[i].flux, 0.0f);
  }
  return texels;
}

}  // namespace

VplPass::VplPass() {
  lights_.emplace(std::span<const glm::vec4>{});
  cutTable_.emplace(std::span<const glm::uvec2>{});  // cell 0: no entries
}

void VplPass::attach(std::span<const Vpl> vpls, float clampDistance, const Box& bounds,
                     const VplRenderSettings& settings) {
  groups_ = vpls.empty() ? VplGroups() : VplGroups(vpls, settings.groups);
  VplLightCutSettings cutSettings;
  cutSettings.kappa = settings.culling ? settings.kappa : std::numeric_limits<float>::infinity();
  cutSettings.maxCellsPerAxis = settings.culling ? settings.maxCellsPerAxis : 1;
  const glm::vec3 lo = bounds.empty() ? glm::vec3(0.0f) : bounds.lo;
  const glm::vec3 hi = bounds.empty() ? glm::vec3(0.0f) : bounds.hi;
  cuts_ = buildVplLightCuts(groups_, lo, hi, cutSettings);
  // The cut table must fit one texture buffer (GL 3.3 promises only 65536 texels): coarser grids
  // until it does (fewer cells, the same κ: fewer texels, more lights per cell).
  const std::size_t limit = gl::TextureBuffer::maxTexels();
  while (cuts_.cellEntries.size() + cuts_.entries.size() > limit &&
         cutSettings.maxCellsPerAxis > 1) {
    cutSettings.maxCellsPerAxis /= 2;
    cuts_ = buildVplLightCuts(groups_, lo, hi, cutSettings);
  }
  if (settings.culling && !vpls.empty()) {
    // A cut that keeps more than half the VPLs costs more than it saves (its per-cell lists
    // are read through the texture cache; docs/vpl.md, "Frame time"): one cell, every VPL.
    double evaluated = 0.0;
    for (std::size_t c = 0; c < cuts_.cellEntries.size(); ++c)
      evaluated += static_cast<double>(cuts_.lightsEvaluated(c));
    if (evaluated / static_cast<double>(cuts_.cellEntries.size()) >
        0.5 * static_cast<double>(vpls.size()))
      cuts_ = buildVplLightCuts(groups_, lo, hi, {std::numeric_limits<float>::infinity(), 1});
  }
  clampDistance_ = clampDistance;
  lights_.reset();
  lights_.emplace(std::span<const glm::vec4>(lightTexels(groups_)));
  cutTable_.reset();
  cutTable_.emplace(std::span<const glm::uvec2>(cutTexels(cuts_)));
  attached_ = true;
}

void VplPass::bind(gl::Program& program) const {
  program.set("uVplLights", TextureUnit::kVplLights);
  program.set("uVplCuts", TextureUnit::kVplCuts);
  program.set("uVplGridOrigin", cuts_.origin);
  program.set("uVplCellSize", cuts_.cellSize);
  program.set("uVplGridCells", cuts_.cells);
  program.set("uVplClampDistance", clampDistance_);
  lights_->bind(TextureUnit::kVplLights);
  cutTable_->bind(TextureUnit::kVplCuts);
}

void VplPass::setInstance(gl::Program& program, const GpuScene& scene, std::size_t index) const {
  const std::span<const GpuInstance> instances = scene.instances();
  const bool receiver =
      attached_ && index < instances.size() && instances[index].mobility == Mobility::Dynamic;
  program.set("uVplReceiver", receiver ? 1 : 0);
}

}  // namespace bounce
