// The forward renderer: a short sequence of passes per frame,
//   1. shadow maps   (shadow_pass.h: spot and point lights' depth maps),
//   2. lit pass      (forward_pass.h: outgoing radiance, W/(sr·m²), of the visible Lambertian
//                     surface into a linear float target,
//                       L_o = ρ/π · (Σ_punctual V_i·E_i + Σ_emitters E_j) + L_e,
//                     equations in shaders/lights.glsl, shaders/area_light.glsl, docs/renderer.md),
//   3. tone mapping  (tonemap_pass.h, by the viewer; files are tone-mapped by image_io),
// over a GpuScene (gpu_scene.h) uploaded once: instances keep their own model matrices. Later
// passes (lightmap, VPLs, debug views) slot in by RenderMode. Uses the GL layer's API only;
// needs a current context for its whole life.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "image/image.h"
#include "render/frame_profile.h"
#include "render/light_culling_settings.h"
#include "render/render_mode.h"
#include "render/shadow_settings.h"
#include "render/vpl_render_settings.h"
#include "scene/scene.h"

namespace bounce {

class VplPass;
struct ShadowChoice;
namespace gl {
class RenderTarget;
class GpuPassTimers;  // gl/gpu_pass_timers.h
}  // namespace gl

struct Bake;  // bake_folder/bake_folder.h

// What the VPL clamp removed over a frame (render mode vpl-clamp, every visible surface).
struct VplClampReport {
  double irradiance = 0.0;  // Σ over pixels of luminance(E_vpl) clamped, W/m²
  double removed = 0.0;     // Σ over pixels of luminance(E_unclamped − E_vpl), W/m²
  std::size_t vplCount = 0;
  float clampDistance = 0.0f;  // r, m
  // removed / (irradiance + removed): the share of the unclamped VPL irradiance the clamp took.
  double removedFraction() const {
    return irradiance + removed > 0.0 ? removed / (irradiance + removed) : 0.0;
  }
};

// VPLs of light paths traced with instance i at object → world transforms[i] (W per channel,
// bake_folder/vpl.h), e.g. baker/vpl/vpl_retrace.h's PlacedVplTracer, which the apps wire in (the
// renderer does not depend on the baker).
using VplTracer = std::function<std::vector<Vpl>(std::span<const glm::mat4> transforms)>;

struct RendererSettings {
  RenderMode mode = RenderMode::Direct;
  ShadowSettings shadows;
  VplRenderSettings vpls;
  // Per-cluster light lists (light_culling.h): which lights each fragment shades, and the
  // irradiance floor below which a light is left out.
  LightCullingSettings lightCulling;
  // Given, the VPLs are traced again with the dynamic instances where they are (on setBake and
  // whenever one moves): they shadow the room and reflect light into it. Empty: the bake's VPLs
  // (traced without them), their paths cut where the dynamic instances block them
  // (vpl_runtime/vpl_occlusion.h), which misses the light those instances reflect.
  VplTracer vplTracer;
  // false: the static instances without a lightmap region take the VPLs' light even when the
  // bake has irradiance probes for them, as before the probes (bounce-render --no-probes).
  bool probes = true;
  // true: with a bake that holds the static lights' visibility, their direct light on static
  // surfaces is computed once, per lightmap texel and per probe-lit corner
  // (static_direct_texels.h, static_direct_corners.h), and read there; false: evaluated per pixel
  // (bounce-render --live-static-lights).
  bool precomputedStaticDirect = true;
};

class ForwardRenderer {
 public:
  // Uploads the scene (per-mesh buffers, per-instance matrices, textures, the emitter table,
  // the punctual lights, shadow maps) and builds the shaders found in `shaderDir`. `scene` must
  // outlive the renderer.
  // With `bake` (read by readBake for this scene), as setBake; a mode that needs a bake
  // (renderModeNeedsBake) without one throws std::invalid_argument.
  ForwardRenderer(const Scene& scene, const std::filesystem::path& shaderDir,
                  const RendererSettings& settings = {}, const Bake* bake = nullptr);
  ~ForwardRenderer();
  ForwardRenderer(const ForwardRenderer&) = delete;
  ForwardRenderer& operator=(const ForwardRenderer&) = delete;

  // Draws radiance seen by `camera` into `target` (cleared to black first). Aspect = target's.
  void render(const Camera& camera, gl::RenderTarget& target);
  // Renders offscreen at width x height with `samples` per pixel (multisampling, resolved to
  // each pixel's mean radiance) and reads the radiance back, rows top to bottom.
  Image renderImage(const Camera& camera, int width, int height, int samples = 1);
  // Reads `target` back as renderImage does, timing the wait for the GPU (CPU, "gpu wait") and
  // the readback (GPU pass "readback" and CPU "readback") into the profile.
  Image readBack(const gl::RenderTarget& target);

  // Where the frames' time went since the last clearProfile(): each pass's GPU time ("shadow:
  // spot maps", "shadow: point cubes", "shadow: directional cascades", "shadow: area-light
  // cubes", "VPL shadow cubes", "lit forward pass" (MSAA resolve included), "readback", and what
  // the caller times with gpuTimers(), e.g. the viewer's "tone map"), the CPU time of render()
  // ("frame": building and submitting, no wait for the GPU; "light culling": the part of it that
  // builds the light lists) and of readBack. GPU times arrive a
  // frame or two late (gl/gpu_pass_timers.h); `waitForGpu` collects every frame in flight (after
  // a benchmark's last frame).
  const FrameProfile& profile(bool waitForGpu = false);
  // Forgets what was measured; `waitForGpu` also drops the frames in flight (else they land in
  // the next profile).
  void clearProfile(bool waitForGpu = true);
  // The renderer's pass timers, for passes drawn outside it into the same frame.
  gl::GpuPassTimers& gpuTimers();

  // Moves instance `index` (object → world) without re-uploading its mesh. After moving dynamic
  // instances, the next frame re-traces the VPLs once (RendererSettings::vplTracer), else
  // recomputes which VPLs their triangles cut off (vpl_runtime/vpl_occlusion.h): moving several
  // instances (bounce-view moves every instance of a name) costs one re-trace.
  void setInstanceTransform(std::size_t index, const glm::mat4& transform);
  // Punctual light `index` (Scene::lights) moved, turned or changed intensity or colour: drawn
  // so from the next frame, its shadow map following. Its type and bakeDirect must stay (throws
  // std::invalid_argument otherwise). Baked light is not changed: the bake is then stale.
  void setLight(std::size_t index, const Light& light);
  // Per-corner lightmap UVs of instance `index` (vertex attribute 3, gl/vertex_attributes.h);
  // empty removes them.
  void setLightmapUv(std::size_t index, std::span<const glm::vec2> cornerUv);

  // Fits the directional light's cascades to `camera` instead of the one drawn with (none: the
  // drawn one): the viewer's frozen-shadow view, and how tests compare the maps two cameras get.
  void setCascadeCamera(std::optional<Camera> camera) { cascadeCamera_ = std::move(camera); }

  // Adds the baked light of `bake` (read by readBake for this scene): uploads the lightmap and
  // gives its static instances their atlas UVs; with bake.vpls, groups and uploads the VPLs
  // (clamp distance: bake.json "vpls"."clampDistance", else sqrt(A/(π·N)) over the static
  // surfaces). Modes other than Direct need a bake; the vpl modes need its VPLs.
  void setBake(const Bake& bake);
  bool hasBake() const;
  bool hasVpls() const;
  bool hasErrorMap() const;  // the bake's error.exr (mode error)
  // Switches what the lit pass draws; throws std::invalid_argument for a mode that needs a bake
  // (or VPLs) when none is set.
  void setMode(RenderMode mode);

  // The VPLs as drawn: K groups with their representatives (groups().representatives(): one
  // Vpl per group; each group's shadow cube sits at its member nearest it), the per-cell cuts
  // and the clamp distance. Empty before a bake with VPLs.
  const VplPass& vpls() const;
  // Which of the bake's VPLs are drawn and how they are clamped (the viewer's panel): the VPLs of
  // its first `paths` light paths, each flux × totalPaths/paths (vpl_runtime/vpl_paths.h: the
  // same estimator over fewer paths), with the geometry term capped at 1/r², r = clampDistance
  // (m; 0 unclamped; bake_folder/vpl_clamp.h). paths is kept in [1, totalPaths]. Throws
  // std::invalid_argument without VPLs, for a negative or non-finite r, or when those paths left
  // no VPL. With a VplTracer and dynamic instances the re-traced set is drawn whole, at this r.
  void setVplSelection(uint64_t paths, float clampDistance);
  struct VplSelection {
    uint64_t paths = 0, totalPaths = 0;  // light paths drawn, of the bake's
    std::size_t vplCount = 0;            // the VPLs of those paths
    float clampDistance = 0.0f;          // r drawn, m
    float bakeClampDistance = 0.0f;      // the bake's r, m
  };
  VplSelection vplSelection() const;
  // VPL visibility (one shadow cube per group) on or off; off draws every VPL unoccluded.
  void setVplShadows(bool enabled);
  // Renders the vpl-clamp view of `camera` at width x height and sums it (needs VPLs; the mode
  // is restored).
  VplClampReport measureVplClamp(const Camera& camera, int width, int height);

  const RendererSettings& settings() const { return settings_; }
  // Light culling on or off, or another irradiance floor (the viewer's exposure changed).
  void setLightCulling(const LightCullingSettings& culling);
  // The light lists of the last frame.
  LightGridStats lightGridStats() const;
  // The last frame's view clusters (render/cluster_grid.h).
  const ClusterGrid& clusterGrid() const;
  // How many frames rebuilt the light lists (LightCulling::gridBuilds): a still camera's frames
  // do not.
  uint64_t lightGridBuilds() const;
  // How many frames gathered the VPLs at the dynamic instances' vertices (VplVertexLight): a
  // still scene's do not.
  uint64_t vplVertexGathers() const;
  // Shadow-map views and caster draws of the last frame (lights or faces that cannot reach
  // the view are skipped; casters are culled to each view's frustum).
  ShadowDrawCount shadowDrawCount() const;
  // The last frame's area-light shadow budget: which lights had a cube, how many that reach
  // where cubes are read had none and what they bring (area_shadow_budget.h); the most cubes
  // the driver's texture units allow at once.
  const ShadowChoice& areaShadowChoice() const;
  // Each punctual light's shadow-map slot among its kind's this frame, −1 for none
  // (render/punctual_shadow_budget.h).
  std::span<const int> punctualShadowSlots() const;
  int areaShadowSlots() const;
  // Set-ups that make no sense or that the renderer does not support, one sentence each.
  const std::vector<std::string>& warnings() const { return warnings_; }
  std::size_t emitterTriangleCount() const;
  std::size_t areaLightCount() const;

 private:
  struct Passes;
  // Recomputes the VPLs the dynamic instances block at their current transforms.
  void updateVplOcclusion();
  // Traces the VPLs again with every instance at its current transform (settings_.vplTracer).
  void retraceVpls();
  // Per frame: one re-trace or occlusion update when dynamic instances moved since the last.
  void followDynamicMoves();
  // Decides which static lights' direct light on static surfaces is computed once (every static
  // area light the bake's visibility names, and the punctual lights as the bake saw them), then
  // computes and uploads their texels and corners (static_direct_texels.h,
  // static_direct_corners.h); none with RendererSettings::precomputedStaticDirect off.
  void updateStaticDirect();
  // Whether the static lights' direct light is read from texels and corners: asked for, a bake
  // with visibility attached, and a driver that can read them.
  bool staticDirectWanted() const;

  RendererSettings settings_;
  // Draws vpls_ (or the re-traced set) at vplClampDistance_ into the VPL pass.
  void attachVpls();

  std::vector<Vpl> bakeVpls_;          // the bake's VPLs in file order (path order)
  uint64_t vplTotalPaths_ = 0;         // the light paths of bakeVpls_ (vpl_runtime/vpl_paths.h)
  uint64_t vplPathsDrawn_ = 0;         // the first this many of them are drawn
  std::vector<Vpl> vpls_;              // those paths' VPLs, as drawn, for updateVplOcclusion
  float vplClampDistance_ = 0.0f;      // r drawn, m
  float bakeVplClampDistance_ = 0.0f;  // the bake's r (its N over the static area), m
  Box vplBounds_;                      // where the VPL grid lies: the static surfaces
  bool dynamicMoved_ = false;          // a dynamic instance moved since the VPLs last followed
  const Scene& scene_;
  std::optional<Camera> cascadeCamera_;
  std::vector<std::string> warnings_;
  std::unique_ptr<Passes> passes_;
  FrameProfile profile_;
};

}  // namespace bounce
