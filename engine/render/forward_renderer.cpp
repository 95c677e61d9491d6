#include "render/forward_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "bake_folder/bake_folder.h"
#include "bake_folder/vpl_clamp.h"
#include "gl/draw_state.h"
#include "gl/gpu_pass_timers.h"
#include "gl/render_target.h"
#include "render/area_shadow_budget.h"
#include "render/forward_pass.h"
#include "render/frustum.h"
#include "render/gpu_scene.h"
#include "render/light_culling.h"
#include "render/light_table.h"
#include "render/lightmap_pass.h"
#include "render/probe_pass.h"
#include "render/punctual_lights.h"
#include "render/shadow_pass.h"
#include "render/static_direct_corners.h"
#include "render/static_direct_texels.h"
#include "render/view.h"
#include "render/vpl_pass.h"
#include "render/vpl_vertex_light.h"
#include "vpl_runtime/vpl_occlusion.h"
#include "vpl_runtime/vpl_paths.h"

namespace bounce {

struct ForwardRenderer::Passes {
  GpuScene scene;
  PunctualLights lights;
  ShadowPass shadows;
  LightTable lightTable;
  LightCulling culling;
  LightmapPass lightmap;
  ProbePass probes;
  VplPass vpls;
  VplVertexLight vplVertexLight;
  ForwardPass forward;
  gl::GpuPassTimers timers;
  // What the static lights' texels and corners are computed from (kept for setLight: a light
  // edited away from its baked state leaves them, which are then computed again).
  struct StaticDirectSource {
    LightmapLayout layout;
    BakedVisibility visibility;
    IrradianceProbes probes;
  };
  std::optional<StaticDirectSource> staticDirectSource;

  Passes(const Scene& source, const std::filesystem::path& shaderDir,
         const RendererSettings& settings, std::vector<std::string>& warnings)
      : scene(source, warnings),
        lights(source),
        shadows(scene, lights, settings.shadows, shaderDir, warnings),
        culling(settings.lightCulling),
        vpls(shaderDir, settings.vpls.shadows, warnings),
        vplVertexLight(source, shaderDir),
        forward(shaderDir) {
    lightTable.setPunctual(lights.texels(shadows.lightSlots()));
  }
};

namespace {

void requireLight(RenderMode mode, bool hasBake, bool hasVpls, bool hasErrorMap) {
  if (renderModeNeedsBake(mode) && !hasBake)
    throw std::invalid_argument("mode '" + std::string(renderModeName(mode)) +
                                "' needs a bake (--bake DIR)");
  if (renderModeNeedsVpls(mode) && !hasVpls)
    throw std::invalid_argument("mode '" + std::string(renderModeName(mode)) +
                                "' draws virtual point lights, but the bake has none (no 'vpls' "
                                "file: bake with bounce-bake --vpls N, N > 0)");
  if (renderModeNeedsErrorMap(mode) && !hasErrorMap)
    throw std::invalid_argument("mode '" + std::string(renderModeName(mode)) +
                                "' shows the bake's per-texel error, but the bake has no "
                                "error.exr (bake it again with this version of bounce-bake)");
}

bool hasDynamicInstance(const GpuScene& scene) {
  for (const GpuInstance& instance : scene.instances())
    if (instance.mobility == Mobility::Dynamic) return true;
  return false;
}

}  // namespace

ForwardRenderer::ForwardRenderer(const Scene& scene, const std::filesystem::path& shaderDir,
                                 const RendererSettings& settings, const Bake* bake)
    : settings_(settings), scene_(scene) {
  requireLight(settings.mode, bake != nullptr, bake && bake->vpls && !bake->vpls->empty(),
               bake && bake->relativeError);
  passes_ = std::make_unique<Passes>(scene, shaderDir, settings, warnings_);
  if (bake) setBake(*bake);
  if (scene.lights.empty() && passes_->scene.emitterCount() == 0)
    warnings_.push_back("the scene has no lights and no emissive surfaces: the image is black");
}

ForwardRenderer::~ForwardRenderer() = default;

std::size_t ForwardRenderer::areaLightCount() const {
  return passes_->scene.areaLights().lights.size();
}

std::size_t ForwardRenderer::emitterTriangleCount() const {
  return static_cast<std::size_t>(passes_->scene.emitterCount());
}

void ForwardRenderer::setLightCulling(const LightCullingSettings& culling) {
  settings_.lightCulling = culling;
  passes_->culling.setSettings(culling);
}

LightGridStats ForwardRenderer::lightGridStats() const {
  return passes_->culling.lastFrame();
}

const ClusterGrid& ForwardRenderer::clusterGrid() const {
  return passes_->culling.grid();
}

uint64_t ForwardRenderer::lightGridBuilds() const {
  return passes_->culling.gridBuilds();
}

uint64_t ForwardRenderer::vplVertexGathers() const {
  return passes_->vplVertexLight.gathers();
}

ShadowDrawCount ForwardRenderer::shadowDrawCount() const {
  return passes_->shadows.lastFrame();
}

std::span<const int> ForwardRenderer::punctualShadowSlots() const {
  return passes_->shadows.lightSlots();
}

const ShadowChoice& ForwardRenderer::areaShadowChoice() const {
  return passes_->shadows.areaShadowChoice();
}

int ForwardRenderer::areaShadowSlots() const {
  return passes_->shadows.areaShadowSlots();
}

void ForwardRenderer::setInstanceTransform(std::size_t index, const glm::mat4& transform) {
  passes_->scene.setInstanceTransform(index, transform);
  const std::span<const GpuInstance> instances = passes_->scene.instances();
  if (index < instances.size() && instances[index].mobility == Mobility::Dynamic)
    dynamicMoved_ = true;  // the VPLs follow in the next frame, once for all of its moves
}

void ForwardRenderer::followDynamicMoves() {
  if (!dynamicMoved_) return;
  dynamicMoved_ = false;
  if (settings_.vplTracer)
    retraceVpls();
  else
    updateVplOcclusion();
}

void ForwardRenderer::updateVplOcclusion() {
  Passes& p = *passes_;
  if (!p.vpls.attached() || vpls_.empty()) return;
  // The dynamic instances at their current places block the bake's light paths
  // (vpl_runtime/vpl_occlusion.h): the VPLs past a blocked segment go dark.
  std::vector<VplOccluder> occluders;
  const std::span<const GpuInstance> instances = p.scene.instances();
  for (std::size_t i = 0; i < instances.size() && i < scene_.instances.size(); ++i)
    if (instances[i].mobility == Mobility::Dynamic &&
        scene_.instances[i].mesh < scene_.meshes.size())
      occluders.push_back(
          makeVplOccluder(scene_.meshes[scene_.instances[i].mesh], instances[i].model));
  p.vpls.setAlive(vplAliveMask(vpls_, occluders));
  p.lightTable.setVpls(p.vpls.lightTexels(), p.vpls.cutTexels());
}

void ForwardRenderer::retraceVpls() {
  Passes& p = *passes_;
  if (vpls_.empty()) return;  // no bake with VPLs yet
  std::vector<glm::mat4> transforms;
  for (const GpuInstance& instance : p.scene.instances()) transforms.push_back(instance.model);
  // The bake's clamp distance and grid: the re-traced set has the bake's count rule, so about
  // its N, over the same static surfaces.
  p.vpls.attach(settings_.vplTracer(transforms), vplClampDistance_, vplBounds_, settings_.vpls);
  p.lightTable.setVpls(p.vpls.lightTexels(), p.vpls.cutTexels());
}

void ForwardRenderer::setLightmapUv(std::size_t index, std::span<const glm::vec2> cornerUv) {
  passes_->scene.setLightmapUv(index, cornerUv);
}

void ForwardRenderer::setBake(const Bake& bake) {
  Passes& p = *passes_;
  p.lightmap.attach(bake, p.scene);
  p.probes.attach(bake.probes && settings_.probes ? *bake.probes : IrradianceProbes{},
                  p.scene.instances().size(), p.lightmap.hasBakedVisibility());
  std::vector<uint8_t> cornerVisibility(p.scene.instances().size(), 0);
  for (std::size_t i = 0; i < cornerVisibility.size(); ++i)
    cornerVisibility[i] = p.probes.cornerVisibility(i) ? 1 : 0;
  p.lightmap.setCornerVisibility(std::move(cornerVisibility));
  if (!p.lightmap.visibilityRefusal().empty())
    warnings_.push_back("the bake's area-light visibility is not used (" +
                        p.lightmap.visibilityRefusal() + "): area lights use their shadow maps");
  // With every surface reading baked visibility and nothing dynamic, the area cubes are unused.
  p.shadows.setAreaCubesNeeded(
      !(p.lightmap.visibilityCoversEveryInstance(p.scene) && !hasDynamicInstance(p.scene)));
  // Which lights static surfaces still read cubes for: the area-shadow budget ranks the rest by
  // the dynamic instances only.
  p.shadows.setAreaBake(p.lightmap.bakedVisibilityLights(p.scene), true);
  // Likewise the static spot and point lights the bake names: a map only for what moves.
  p.shadows.setStaticVisibilityBaked(settings_.shadows.bakedPunctualMapsOnlyForDynamic &&
                                     p.lightmap.visibilityOnEveryStaticInstance(p.scene));
  // Baked visibility holds the static occluders; the dynamic ones still shadow static surfaces
  // through cubes of their own.
  if (p.lightmap.hasBakedVisibility() && hasDynamicInstance(p.scene) &&
      !p.shadows.setDynamicCasterCubes(true))
    warnings_.push_back(
        "dynamic instances cast no area-light shadows on baked static surfaces: the driver has "
        "too few fragment texture units");
  p.lights.setBakedDirectInLightmap(true);
  p.lights.setBakedVisibility(p.lightmap.bakedLightCount(), p.lightmap.bakedPunctualCount());
  p.staticDirectSource.reset();
  if (bake.visibility)
    p.staticDirectSource = Passes::StaticDirectSource{
        bake.layout, *bake.visibility,
        bake.probes && settings_.probes ? *bake.probes : IrradianceProbes{}};
  updateStaticDirect();
  std::size_t bakedWithoutMap = 0;
  for (std::size_t i = 0; i < p.lights.size(); ++i)
    if (p.lights.bakedIndex(i) >= 0 &&
        (i >= p.shadows.lightSlots().size() || p.shadows.lightSlots()[i] < 0))
      ++bakedWithoutMap;
  if (bakedWithoutMap > 0)
    warnings_.push_back(std::to_string(bakedWithoutMap) +
                        " punctual lights have no shadow map in a frame (more lights than maps; "
                        "which do is chosen per frame): static surfaces take their shadows from "
                        "the bake's visibility, dynamic objects neither cast nor receive them");
  p.lightTable.setPunctual(p.lights.texels(p.shadows.lightSlots()));
  if (bake.vpls && !bake.vpls->empty()) {
    const std::optional<float> fromManifest = manifestVplClampDistance(bake.manifest);
    const float r = fromManifest ? *fromManifest
                                 : vplClampDistance(staticSurfaceArea(scene_), bake.vpls->size());
    // The grid covers the static surfaces (where the VPLs and most receivers are).
    Box statics;
    for (const GpuInstance& instance : p.scene.instances())
      if (instance.mobility == Mobility::Static && !instance.worldBox.empty()) {
        statics.grow(instance.worldBox.lower);
        statics.grow(instance.worldBox.upper);
      }
    vplClampDistance_ = bakeVplClampDistance_ = r;
    vplBounds_ = statics.empty() ? p.scene.bounds() : statics;
    bakeVpls_ = *bake.vpls;
    vplTotalPaths_ = vplPathCount(bakeVpls_, bake.manifest.vpls ? bake.manifest.vpls->paths : 0);
    vplPathsDrawn_ = vplTotalPaths_;
    vpls_ = bakeVpls_;
    attachVpls();
  }
}

void ForwardRenderer::attachVpls() {
  Passes& p = *passes_;
  // Both hand the VPL sections to the light table.
  if (settings_.vplTracer && hasDynamicInstance(p.scene)) {
    retraceVpls();
  } else {
    p.vpls.attach(vpls_, vplClampDistance_, vplBounds_, settings_.vpls);
    updateVplOcclusion();
  }
}

void ForwardRenderer::setVplSelection(uint64_t paths, float clampDistance) {
  if (bakeVpls_.empty()) throw std::invalid_argument("no VPLs to select: the bake has none");
  if (!std::isfinite(clampDistance) || clampDistance < 0.0f)
    throw std::invalid_argument("VPL clamp distance " + std::to_string(clampDistance) +
                                " m is not a finite number >= 0");
  paths = std::clamp<uint64_t>(paths, 1, vplTotalPaths_);
  std::vector<Vpl> selected = firstPathsVpls(bakeVpls_, paths, vplTotalPaths_);
  if (selected.empty())
    throw std::invalid_argument("the first " + std::to_string(paths) + " of the bake's " +
                                std::to_string(vplTotalPaths_) + " light paths left no VPL");
  vpls_ = std::move(selected);
  vplPathsDrawn_ = paths;
  vplClampDistance_ = clampDistance;
  attachVpls();
}

ForwardRenderer::VplSelection ForwardRenderer::vplSelection() const {
  return {vplPathsDrawn_, vplTotalPaths_, vpls_.size(), vplClampDistance_, bakeVplClampDistance_};
}

bool ForwardRenderer::hasBake() const {
  return passes_->lightmap.attached();
}

void ForwardRenderer::setLight(std::size_t index, const Light& light) {
  Passes& p = *passes_;
  if (index >= p.lights.size()) throw std::invalid_argument("no light " + std::to_string(index));
  const Light& old = p.lights.light(index);
  if (light.type != old.type || light.bakeDirect != old.bakeDirect)
    throw std::invalid_argument("light '" + old.name + "': its type and bake mode cannot change");
  p.lights.setLight(index, light);
  p.shadows.setLight(index, light);
  // Edited away from (or back to) its baked state: the texels and corners leave (take) it.
  if (p.lights.precomputed(index) != (staticDirectWanted() && p.lights.asBaked(index)))
    updateStaticDirect();
  p.lightTable.setPunctual(p.lights.texels(p.shadows.lightSlots()));
}

bool ForwardRenderer::staticDirectWanted() const {
  const Passes& p = *passes_;
  return settings_.precomputedStaticDirect && p.staticDirectSource &&
         p.lightmap.canReadStaticDirect();
}

void ForwardRenderer::updateStaticDirect() {
  Passes& p = *passes_;
  const bool on = staticDirectWanted();
  std::vector<uint8_t> precomputed(p.lights.size(), 0);
  for (std::size_t i = 0; i < precomputed.size(); ++i)
    precomputed[i] = on && p.lights.asBaked(i) ? 1 : 0;
  p.lights.setPrecomputed(precomputed);
  if (!on) {
    p.lightmap.setStaticDirect({});
    p.probes.attachStaticDirect({});
    return;
  }
  const Passes::StaticDirectSource& source = *p.staticDirectSource;
  const PrecomputedLights lights{&p.scene.areaLights(),
                                 static_cast<std::size_t>(p.lightmap.bakedLightCount()),
                                 p.lights.all(), precomputed};
  p.lightmap.setStaticDirect(
      staticDirectTexels(p.scene.source(), source.layout, source.visibility, lights));
  p.probes.attachStaticDirect(staticDirectCorners(p.scene.source(), source.probes, lights));
}

bool ForwardRenderer::hasVpls() const {
  return passes_->vpls.attached();
}

bool ForwardRenderer::hasErrorMap() const {
  return passes_->lightmap.hasErrorMap();
}

const VplPass& ForwardRenderer::vpls() const {
  return passes_->vpls;
}

void ForwardRenderer::setVplShadows(bool enabled) {
  settings_.vpls.shadows.enabled = enabled;
  passes_->vpls.setShadowsEnabled(enabled);
}

VplClampReport ForwardRenderer::measureVplClamp(const Camera& camera, int width, int height) {
  const RenderMode mode = settings_.mode;
  setMode(RenderMode::VplClamp);
  const Image image = renderImage(camera, width, height);
  settings_.mode = mode;
  VplClampReport report;
  // The view holds (lum E_vpl, lum E_removed, 0)/π (shaders/lightmap.glsl).
  for (const glm::vec3& pixel : image.pixels) {
    report.irradiance += std::numbers::pi * static_cast<double>(pixel.r);
    report.removed += std::numbers::pi * static_cast<double>(pixel.g);
  }
  report.vplCount = passes_->vpls.groups().vplCount();
  report.clampDistance = passes_->vpls.clampDistance();
  return report;
}

void ForwardRenderer::setMode(RenderMode mode) {
  requireLight(mode, hasBake(), hasVpls(), hasErrorMap());
  settings_.mode = mode;
}

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

void ForwardRenderer::render(const Camera& camera, gl::RenderTarget& target) {
  Passes& p = *passes_;
  const Clock::time_point cpuStart = Clock::now();
  p.timers.beginFrame();
  using Timed = gl::GpuPassTimers::Scope;
  const float aspect = static_cast<float>(target.width()) / static_cast<float>(target.height());
  const glm::mat4 cameraViewProjection = viewProjection(camera, aspect);
  // Without culling every light is shaded everywhere: any light that brings light competes.
  const float floor =
      settings_.lightCulling.enabled ? settings_.lightCulling.irradianceFloor : 0.0f;
  ViewVolume view(cameraViewProjection, p.scene.bounds());
  view.eye = camera.position();
  if (p.shadows.render(p.scene, p.lights, view, cascadeCamera_ ? *cascadeCamera_ : camera, aspect,
                       floor, &p.timers))
    p.lightTable.setPunctual(p.lights.texels(p.shadows.lightSlots()));
  followDynamicMoves();
  // The VPL shadow cubes only where some surface of this mode takes the VPLs' light: with every
  // static surface baked (lightmap or probes) and nothing dynamic, none is drawn. The cost view
  // counts what the full frame does.
  std::vector<uint8_t> baked(p.scene.instances().size(), 0);
  for (std::size_t i = 0; i < baked.size(); ++i)
    baked[i] = p.lightmap.lightmapped(i) || p.probes.probeLit(i) ? 1 : 0;
  const bool everySurface =
      settings_.mode == RenderMode::Vpl || settings_.mode == RenderMode::VplClamp;
  const bool vplsShaded = everySurface || settings_.mode == RenderMode::Full ||
                          settings_.mode == RenderMode::Indirect ||
                          settings_.mode == RenderMode::Cost;
  if (vplsShaded && p.vpls.anyReceiver(p.scene, baked, everySurface)) {
    const Timed timed(&p.timers, "VPL shadow cubes");
    p.vpls.renderShadows(p.scene);
  }
  const Clock::time_point cullingStart = Clock::now();
  p.culling.update(camera, target.width(), target.height(), p.scene.bounds(), p.lights,
                   p.scene.areaLights(), p.scene.emitterVersion(), p.lightTable,
                   p.lights.listOrder(p.shadows.lightSlots()));
  profile_.addCpu("light culling", millisecondsSince(cullingStart));
  p.lightTable.update();
  // The dynamic instances' VPL light, gathered at their vertices (not in the vpl modes, which
  // show every pixel's own gather).
  if (settings_.vpls.perVertex && vplsShaded && !everySurface && p.vpls.attached()) {
    const Timed timed(&p.timers, "VPL vertex light");
    p.vplVertexLight.render(p.scene, p.lightTable, p.vpls);
  } else {
    p.vplVertexLight.clear();
  }
  {
    const Timed timed(&p.timers, "lit forward pass");
    p.forward.draw(p.scene, p.lightTable, p.culling, p.shadows, p.lightmap, p.probes, p.vpls,
                   p.vplVertexLight, settings_.mode, cameraViewProjection, target);
  }
  profile_.addCpu("frame", millisecondsSince(cpuStart));
}

Image ForwardRenderer::renderImage(const Camera& camera, int width, int height, int samples) {
  gl::RenderTarget target(width, height, samples);
  render(camera, target);
  return readBack(target);
}

Image ForwardRenderer::readBack(const gl::RenderTarget& target) {
  Passes& p = *passes_;
  const Clock::time_point waitStart = Clock::now();
  gl::finish();
  profile_.addCpu("gpu wait", millisecondsSince(waitStart));
  const Clock::time_point readStart = Clock::now();
  Image image;
  {
    const gl::GpuPassTimers::Scope timed(&p.timers, "readback");
    image = target.read();
  }
  profile_.addCpu("readback", millisecondsSince(readStart));
  return image;
}

const FrameProfile& ForwardRenderer::profile(bool waitForGpu) {
  Passes& p = *passes_;
  if (waitForGpu) p.timers.finish();
  for (const gl::GpuFrameTimes& frame : p.timers.takeFinished()) {
    std::vector<std::pair<std::string, double>> passes;
    for (const gl::GpuFrameTimes::Pass& pass : frame.passes)
      passes.emplace_back(pass.name, pass.milliseconds);
    profile_.addGpuFrame(passes);
  }
  return profile_;
}

void ForwardRenderer::clearProfile(bool waitForGpu) {
  if (waitForGpu) passes_->timers.finish();
  (void)passes_->timers.takeFinished();
  profile_.clear();
}

gl::GpuPassTimers& ForwardRenderer::gpuTimers() {
  return passes_->timers;
}

}  // namespace bounce
