#include "render/lightmap_pass.h"

#include "bake_folder/bake_folder.h"
#include "bake_folder/lightmap_charts.h"
#include "bake_folder/texel_error.h"
#include "render/shader_constants.h"
#include "render/texture_units.h"

namespace bounce {
namespace {

const glm::vec3 kBlack(0.0f);

// The lighting the lit pass draws for each render mode (shader_constants.h).
ShaderLighting shaderLighting(RenderMode mode) {
  switch (mode) {
    case RenderMode::Full:
      return ShaderLighting::Full;
    case RenderMode::Direct:
      return ShaderLighting::Direct;
    case RenderMode::Indirect:
      return ShaderLighting::Indirect;
    case RenderMode::Lightmap:
      return ShaderLighting::Lightmap;
    case RenderMode::Charts:
      return ShaderLighting::Charts;
    case RenderMode::Vpl:
      return ShaderLighting::Vpl;
    case RenderMode::VplClamp:
      return ShaderLighting::VplClamp;
    case RenderMode::Error:
    case RenderMode::Validity:
      return ShaderLighting::Error;  // both read their colours from the chart unit
    case RenderMode::TexelDensity:
      return ShaderLighting::TexelDensity;
    case RenderMode::Cascades:
      return ShaderLighting::Cascades;
    case RenderMode::Cost:
      return ShaderLighting::Cost;
  }
  return ShaderLighting::Direct;
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
  errorColours_.reset();
  validityColours_.reset();
  if (bake.relativeError) {
    errorColours_.emplace(
        layout.width, layout.height,
        errorFalseColourImage(*bake.relativeError, bakeErrorTarget(bake.manifest)).pixels,
        gl::Filter::Nearest, gl::Wrap::ClampToEdge);
    validityColours_.emplace(layout.width, layout.height,
                             texelValidityImage(*bake.relativeError, charts).pixels,
                             gl::Filter::Nearest, gl::Wrap::ClampToEdge);
  }
  size_ = {static_cast<float>(layout.width), static_cast<float>(layout.height)};
  targetTexelsPerMetre_ = layout.texelSize > 0.0f ? 1.0f / layout.texelSize : 1.0f;
  attachVisibility(bake);
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
  staticDirect_.reset();
  attached_ = true;
}

bool LightmapPass::canReadStaticDirect() const {
  return visibility_.has_value() && gl::Texture2D::maxFragmentUnits() > TextureUnit::kStaticDirect;
}

void LightmapPass::setStaticDirect(std::span<const glm::vec3> texels) {
  staticDirect_.reset();
  if (texels.empty() || !canReadStaticDirect()) return;
  staticDirect_.emplace(static_cast<int>(size_.x), static_cast<int>(size_.y), 3, texels);
}

void LightmapPass::attachVisibility(const Bake& bake) {
  visibility_.reset();
  bakedLights_ = 0;
  bakedPunctual_ = 0;
  visibilityRefusal_.clear();
  if (!bake.visibility) return;
  const BakedVisibility& v = *bake.visibility;
  if (gl::Texture2D::maxFragmentUnits() <= TextureUnit::kBakedVisibility) {
    visibilityRefusal_ = "the driver has " + std::to_string(gl::Texture2D::maxFragmentUnits()) +
                         " fragment texture units, baked visibility needs unit " +
                         std::to_string(TextureUnit::kBakedVisibility);
    return;
  }
  if (2 * v.width > gl::Texture2D::maxSize() || v.height > gl::Texture2D::maxSize()) {
    visibilityRefusal_ = "the visibility table " + std::to_string(2 * v.width) + "x" +
                         std::to_string(v.height) + " exceeds the driver's texture size " +
                         std::to_string(gl::Texture2D::maxSize());
    return;
  }
  // Texel (2x, y): the slots' light indices (−1 empty, −2 every other light); (2x+1, y): V.
  std::vector<glm::vec4> table(static_cast<std::size_t>(2 * v.width) *
                               static_cast<std::size_t>(v.height));
  for (std::size_t t = 0; t < v.texels.size(); ++t) {
    const TexelVisibility& texel = v.texels[t];
    glm::vec4 lights, visible;
    for (int s = 0; s < kVisibilitySlots; ++s) {
      const uint16_t l = texel.light[s];
      lights[s] = l == kNoLight       ? -1.0f
                  : l == kOtherLights ? kVisibilityOtherLightsCode
                                      : static_cast<float>(l);
      visible[s] = texel.visible[s];
    }
    table[2 * t] = lights;
    table[2 * t + 1] = visible;
  }
  visibility_.emplace(2 * v.width, v.height, table);
  bakedLights_ = static_cast<int>(v.lightCount);
  bakedPunctual_ = v.punctualCount;
}

bool LightmapPass::readsVisibility(std::size_t index) const {
  return (index < lightmapped_.size() && lightmapped_[index]) ||
         (index < cornerVisibility_.size() && cornerVisibility_[index]);
}

bool LightmapPass::visibilityCoversEveryInstance(const GpuScene& scene) const {
  if (!visibility_) return false;
  for (std::size_t i = 0; i < scene.instances().size(); ++i)
    if (!readsVisibility(i)) return false;
  return true;
}

bool LightmapPass::visibilityOnEveryStaticInstance(const GpuScene& scene) const {
  if (!visibility_) return false;
  for (std::size_t i = 0; i < scene.instances().size(); ++i)
    if (scene.instances()[i].mobility == Mobility::Static && !readsVisibility(i)) return false;
  return true;
}

std::size_t LightmapPass::bakedVisibilityLights(const GpuScene& scene) const {
  return visibilityOnEveryStaticInstance(scene) ? static_cast<std::size_t>(bakedLights_) : 0;
}

void LightmapPass::bind(gl::Program& program, RenderMode mode) const {
  // Without a bake only the modes that need none are drawn as asked.
  program.set("uLightingMode",
              static_cast<int>(shaderLighting(
                  attached_ || !renderModeNeedsBake(mode) ? mode : RenderMode::Direct)));
  program.set("uTargetTexelsPerMetre", targetTexelsPerMetre_);
  program.set("uLightmap", TextureUnit::kLightmap);
  program.set("uLightmapCharts", TextureUnit::kLightmapCharts);
  program.set("uLightmapSize", size_);
  irradiance_->bind(TextureUnit::kLightmap);
  // The error view reads its false colours where the chart view reads chart colours.
  (mode == RenderMode::Error && errorColours_         ? *errorColours_
   : mode == RenderMode::Validity && validityColours_ ? *validityColours_
                                                      : *charts_)
      .bind(TextureUnit::kLightmapCharts);
  program.set("uBakedLightCount", bakedLights_);
  program.set("uHasBake", attached_ ? 1 : 0);
  if (visibility_) {
    program.set("uBakedVisibility", TextureUnit::kBakedVisibility);
    visibility_->bind(TextureUnit::kBakedVisibility);
  } else {
    program.set("uBakedVisibility", TextureUnit::kLightmap);  // never read; a sampler2D unit
  }
  if (staticDirect_) {
    program.set("uStaticDirect", TextureUnit::kStaticDirect);
    staticDirect_->bind(TextureUnit::kStaticDirect);
  } else {
    // Never read: a unit of its type (the area lights' cubes are sampler2DArray too).
    program.set("uStaticDirect", TextureUnit::kAreaShadow0);
  }
}

void LightmapPass::setInstance(gl::Program& program, std::size_t index) const {
  const bool lightmapped = index < lightmapped_.size() && lightmapped_[index];
  program.set("uHasLightmap", lightmapped ? 1 : 0);
  program.set("uHasBakedVisibility", lightmapped && visibility_ ? 1 : 0);
  program.set("uStaticDirectFromTexels", lightmapped && staticDirect_ ? 1 : 0);
}

}  // namespace bounce
