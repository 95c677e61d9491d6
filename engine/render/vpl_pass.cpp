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
