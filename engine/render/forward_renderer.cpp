#include "render/forward_renderer.h"

#include <stdexcept>
#include <string>

#include "render/forward_pass.h"
#include "render/frustum.h"
#include "render/gpu_scene.h"
#include "render/punctual_lights.h"
#include "render/shadow_pass.h"
#include "render/view.h"

namespace bounce {

struct ForwardRenderer::Passes {
  GpuScene scene;
  PunctualLights lights;
  ShadowPass shadows;
  LightmapPass lightmap;
  ForwardPass forward;

  Passes(const Scene& source, const std::filesystem::path& shaderDir,
         const RendererSettings& settings, std::vector<std::string>& warnings)
      : scene(source, warnings),
        lights(source, warnings),
        shadows(scene, lights, settings.shadows, shaderDir, warnings),
        forward(shaderDir) {}
};

ForwardRenderer::ForwardRenderer(const Scene& scene, const std::filesystem::path& shaderDir,
                                 const RendererSettings& settings, const Bake* bake)
    : settings_(settings) {
  if (renderModeNeedsBake(settings.mode) && !bake)
    throw std::invalid_argument("mode '" + std::string(renderModeName(settings.mode)) +
                                "' needs a bake (--bake DIR)");
  passes_ = std::make_unique<Passes>(scene, shaderDir, settings, warnings_);
  if (bake) setBake(*bake);
  if (scene.lights.empty() && passes_->scene.emitterCount() == 0)
    warnings_.push_back("the scene has no lights and no emissive surfaces: the image is black");
}

ForwardRenderer::~ForwardRenderer() = default;

std::size_t ForwardRenderer::emitterTriangleCount() const {
  return static_cast<std::size_t>(passes_->scene.emitterCount());
}

void ForwardRenderer::setInstanceTransform(std::size_t index, const glm::mat4& transform) {
  passes_->scene.setInstanceTransform(index, transform);
}

void ForwardRenderer::setLightmapUv(std::size_t index, std::span<const glm::vec2> cornerUv) {
  passes_->scene.setLightmapUv(index, cornerUv);
}

void ForwardRenderer::setBake(const Bake& bake) {
  passes_->lightmap.attach(bake, passes_->scene);
  passes_->lights.setBakedDirectInLightmap(true);
}

bool ForwardRenderer::hasBake() const {
  return passes_->lightmap.attached();
}

void ForwardRenderer::setMode(RenderMode mode) {
  if (renderModeNeedsBake(mode) && !hasBake())
    throw std::invalid_argument("mode '" + std::string(renderModeName(mode)) +
                                "' needs a bake (--bake DIR)");
  settings_.mode = mode;
}

void ForwardRenderer::render(const Camera& camera, gl::RenderTarget& target) {
  Passes& p = *passes_;
  const float aspect = static_cast<float>(target.width()) / static_cast<float>(target.height());
  const glm::mat4 cameraViewProjection = viewProjection(camera, aspect);
  // What the camera can see: its frustum within the scene's bounds.
  const Box visible = intersect(frustumBox(cameraViewProjection), p.scene.bounds());
  p.shadows.render(p.scene, visible);
  p.forward.draw(p.scene, p.lights, p.shadows, p.lightmap, settings_.mode, cameraViewProjection,
                 target);
}

Image ForwardRenderer::renderImage(const Camera& camera, int width, int height) {
  gl::RenderTarget target(width, height);
  render(camera, target);
  return target.read();
}

}  // namespace bounce
