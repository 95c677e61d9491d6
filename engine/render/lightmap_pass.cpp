#include "render/lightmap_pass.h"

#include "bake/lightmap_charts.h"
#include "render/texture_units.h"

namespace bounce {
namespace {

const glm::vec3 kBlack(0.0f);

// The LIGHTING_* constants of shaders/lightmap.glsl.
int lightingModeIndex(RenderMode mode) {
  switch (mode) {
    case RenderMode::Full:
      return 0;
    case RenderMode::Direct:
      return 1;
    case RenderMode::Indirect:
      return 2;
    case RenderMode::Lightmap:
      return 3;
    case RenderMode::Charts:
      return 4;
    case RenderMode::Vpl:
      return 5;
    case RenderMode::VplClamp:
      return 6;
  }
  return 1;
}

}  // namespace

LightmapPass::LightmapPass() {
  irradiance_.emplace(1, 1, std::span(&kBlack, 1), gl::Filter::Nearest, gl::Wrap::ClampToEdge);
  charts_.emplace(1, 1, std::span(&kBlack, 1), gl::Filter::Nearest, gl::Wrap::ClampToEdge);
}

void LightmapPass::attach(const Bake& bake, GpuScene& scene) {
  const LightmapLayout& layout = bake.layout;
  // Image rows are top first and texture row t = 0 is the first row uploaded, so atlas
  // v = 0 (the top row, lightmap_layout.h) samples row 0: no flip.
  irradiance_.reset();
  irradiance_.emplace(layout.width, layout.height, bake.irradiance.pixels, gl::Filter::Linear,
                      gl::Wrap::ClampToEdge);
  const Image charts = chartImage(layout, findCharts(layout));
  charts_.reset();
  charts_.emplace(layout.width, layout.height, charts.pixels, gl::Filter::Nearest,
                  gl::Wrap::ClampToEdge);
  size_ = {static_cast<float>(layout.width), static_cast<float>(layout.height)};
  const std::span<const GpuInstance> instances = scene.instances();
  lightmapped_.assign(instances.size(), 0);
  for (std::size_t i = 0; i < instances.size(); ++i) scene.setLightmapUv(i, {});
  for (const InstanceLightmapUv& region : layout.instances) {
    if (region.instance >= instances.size() ||
        instances[region.instance].mobility != Mobility::Static)
      continue;  // readBake refuses these; a hand-made bake is ignored rather than drawn wrong
    scene.setLightmapUv(region.instance, region.cornerUv);
    lightmapped_[region.instance] = 1;
  }
  attached_ = true;
}

void LightmapPass::bind(gl::Program& program, RenderMode mode) const {
  program.set("uLightingMode", lightingModeIndex(attached_ ? mode : RenderMode::Direct));
  program.set("uLightmap", TextureUnit::kLightmap);
  program.set("uLightmapCharts", TextureUnit::kLightmapCharts);
  program.set("uLightmapSize", size_);
  irradiance_->bind(TextureUnit::kLightmap);
  charts_->bind(TextureUnit::kLightmapCharts);
}

void LightmapPass::setInstance(gl::Program& program, std::size_t index) const {
  program.set("uHasLightmap", index < lightmapped_.size() && lightmapped_[index] ? 1 : 0);
}

}  // namespace bounce
