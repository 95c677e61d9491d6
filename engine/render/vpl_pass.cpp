#include "render/vpl_pass.h"

#include <algorithm>
#include <limits>
#include <string>

#include "gl/depth_texture.h"
#include "gl/texture.h"

#include "render/gpu_scene.h"
#include "render/texture_units.h"

namespace bounce {
namespace {

// Cells first, then the entries; entry offsets count from the section's first texel
// (shaders/vpl.glsl). Ranges as floats, exact below 2^24 (render/light_table.h).
std::vector<glm::vec4> cutSection(const VplLightCuts& cuts) {
  std::vector<glm::vec4> texels;
  texels.reserve(cuts.cellEntries.size() + cuts.entries.size());
  const auto base = static_cast<uint32_t>(cuts.cellEntries.size());
  const auto range = [](uint32_t first, uint32_t count) {
    return glm::vec4(static_cast<float>(first), static_cast<float>(count), 0.0f, 0.0f);
  };
  for (const glm::uvec2 cell : cuts.cellEntries) texels.push_back(range(base + cell.x, cell.y));
  for (const glm::uvec2 entry : cuts.entries) texels.push_back(range(entry.x, entry.y));
  return texels;
}

// `flux`: per light-table entry, W per channel (VplGroups::lightFluxes); `cubeOf`: per entry,
// the shadow cube whose visibility it takes (VplShadowCubes).
std::vector<glm::vec4> lightSection(const VplGroups& groups, std::span<const glm::vec3> flux,
                                    std::span<const uint32_t> cubeOf) {
  std::vector<glm::vec4> texels;
  const std::span<const Vpl> lights = groups.lights();
  texels.reserve(3 * lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    texels.emplace_back(lights[i].position, static_cast<float>(cubeOf[i]));
    texels.emplace_back(lights[i].normal, 0.0f);
    texels.emplace_back(flux[i], 0.0f);
  }
  return texels;
}

}  // namespace

VplPass::VplPass(const std::filesystem::path& shaderDir, const VplShadowSettings& shadows,
                 std::vector<std::string>& warnings) {
  // 6 array layers per cube: fewer cubes per group, then fewer groups, on a driver with fewer
  // layers than 6·64·4 (GL 3.3 promises 256; llvmpipe and desktop GPUs give 2048).
  const int layers = gl::DepthTextureArray::maxLayers();
  const VplShadowBudget budget =
      vplShadowBudget(layers, kMaxVplShadowGroups, std::max(shadows.cubesPerGroup, 1));
  VplShadowSettings fitted = shadows;
  if (budget.cubesPerGroup < shadows.cubesPerGroup) {
    fitted.cubesPerGroup = budget.cubesPerGroup;
    warnings.push_back("the driver's array textures hold " + std::to_string(layers) +
                       " layers: " + std::to_string(budget.cubesPerGroup) +
                       " VPL shadow cube(s) per group instead of " +
                       std::to_string(shadows.cubesPerGroup));
  }
  if (budget.groups < kMaxVplShadowGroups && budget.groups > 0) {
    maxShadowGroups_ = static_cast<std::size_t>(budget.groups);
    warnings.push_back("the driver's array textures hold " + std::to_string(layers) +
                       " layers: at most " + std::to_string(budget.groups) +
                       " VPL groups with shadow cubes");
  }
  if (budget.groups == 0)
    warnings.push_back("the driver's array textures hold " + std::to_string(layers) +
                       " layers: VPLs cast no shadows (a cube needs 6)");
  else if (TextureUnit::kVplShadow < gl::Texture2D::maxFragmentUnits())
    shadows_.emplace(fitted, shaderDir);
  else
    warnings.push_back("the driver gives fragment shaders " +
                       std::to_string(gl::Texture2D::maxFragmentUnits()) +
                       " texture units: VPLs cast no shadows (they need unit " +
                       std::to_string(TextureUnit::kVplShadow) + ")");
}

void VplPass::attach(std::span<const Vpl> vpls, float clampDistance, const Box& bounds,
                     const VplRenderSettings& settings) {
  const std::size_t groups =
      shadows_ ? std::min(settings.groups, maxShadowGroups_) : settings.groups;
  groups_ = vpls.empty() ? VplGroups() : VplGroups(vpls, groups);
  VplLightCutSettings cutSettings;
  cutSettings.kappa = settings.culling ? settings.kappa : std::numeric_limits<float>::infinity();
  cutSettings.maxCellsPerAxis = settings.culling ? settings.maxCellsPerAxis : 1;
  cutSettings.maxLights = settings.culling ? settings.maxLights : 0;
  const glm::vec3 lo = bounds.empty() ? glm::vec3(0.0f) : bounds.lower;
  const glm::vec3 hi = bounds.empty() ? glm::vec3(0.0f) : bounds.upper;
  cuts_ = buildVplLightCuts(groups_, lo, hi, cutSettings);
  // The cut table must fit one texture buffer (GL 3.3 promises only 65536 texels): coarser grids
  // until it does (fewer cells, the same κ: fewer texels, more lights per cell).
  const std::size_t limit =
      std::min(kMaxLightTableTexels, gl::TextureBuffer::maxTexels()) - 3 * groups_.lights().size();
  while (cuts_.cellEntries.size() + cuts_.entries.size() > limit &&
         cutSettings.maxCellsPerAxis > 1) {
    cutSettings.maxCellsPerAxis /= 2;
    cuts_ = buildVplLightCuts(groups_, lo, hi, cutSettings);
  }
  if (settings.culling && !vpls.empty() &&
      (settings.maxLights == 0 || vpls.size() <= settings.maxLights)) {
    // A cut that keeps more than half the VPLs costs more than it saves (its per-cell lists
    // are read through the texture cache; docs/vpl_measurements.md, "Frame time"): one cell, every
    // VPL, when that is within the light bound.
    double evaluated = 0.0;
    for (std::size_t c = 0; c < cuts_.cellEntries.size(); ++c)
      evaluated += static_cast<double>(cuts_.lightsEvaluated(c));
    if (evaluated / static_cast<double>(cuts_.cellEntries.size()) >
        0.5 * static_cast<double>(vpls.size()))
      cuts_ = buildVplLightCuts(groups_, lo, hi, {std::numeric_limits<float>::infinity(), 1, 0});
  }
  clampDistance_ = clampDistance;
  cubes_ = vplShadowCubes(groups_, shadows_ ? shadows_->cubesPerGroup() : 1);
  setAlive(std::vector<uint8_t>(groups_.vplCount(), 1));
  cutTexels_ = cutSection(cuts_);
  // Each group's cubes sit at members of its parts: a centroid can lie inside an object
  // (docs/vpl.md "Visibility").
  if (shadows_) shadows_->setRepresentatives(cubes_.origins);
  attached_ = true;
  ++version_;
}

void VplPass::setAlive(std::span<const uint8_t> alive) {
  ++version_;
  lightTexels_ = lightSection(groups_, groups_.lightFluxes(alive), cubes_.cubeOf);
}

ShadowDrawCount VplPass::renderShadows(const GpuScene& scene) {
  if (!attached_ || !shadows_) return {};
  return shadows_->render(scene);
}

void VplPass::setShadowsEnabled(bool enabled) {
  ++version_;
  if (shadows_) shadows_->setEnabled(enabled);
}

void VplPass::bind(gl::Program& program) const {
  program.set("uVplGridOrigin", cuts_.origin);
  program.set("uVplCellSize", cuts_.cellSize);
  program.set("uVplGridCells", cuts_.cells);
  program.set("uVplClampDistance", clampDistance_);
  if (shadows_) shadows_->bind(program, TextureUnit::kVplShadow);
}

void VplPass::setInstance(gl::Program& program, const GpuScene& scene, std::size_t index,
                          bool baked) const {
  const std::span<const GpuInstance> instances = scene.instances();
  // Every surface without baked light takes the VPLs' light: dynamic instances, and static ones
  // with neither a lightmap region nor probes (a bake made before the probes).
  const bool receiver = attached_ && index < instances.size() &&
                        (instances[index].mobility == Mobility::Dynamic || !baked);
  program.set("uVplReceiver", receiver ? 1 : 0);
}

bool VplPass::anyReceiver(const GpuScene& scene, std::span<const uint8_t> baked,
                          bool everySurface) const {
  if (!attached_) return false;
  if (everySurface) return true;
  const std::span<const GpuInstance> instances = scene.instances();
  for (std::size_t i = 0; i < instances.size(); ++i)
    if (instances[i].mobility == Mobility::Dynamic || i >= baked.size() || !baked[i]) return true;
  return false;
}

}  // namespace bounce
