// Virtual point light generation (instant radiosity): light paths are started from lights
// picked in proportion to their power (trace/light_sampler.h: area emitters by area × Le with
// cosine-weighted directions, point and spot lights by their intensity, directional lights
// through the scene's bounding disc), stratified by one Owen-scrambled Sobol pattern (path i
// is sample i), continued by cosine-weighted (Lambertian) reflection with Russian roulette on
// the albedo. One VPL is left at every diffuse vertex, from the first hit (bounce 1) on, and
// none at the lights: the set carries indirect light only (the renderer draws direct light).
// Each VPL records its path index (the sample index; a path's VPLs are consecutive, in bounce
// order) and where its incoming segment started (the sampled light point, else the previous
// VPL), so that a path can be cut later where a dynamic object blocks it.
//
// Flux (bake_folder/vpl.h convention, derived in docs/vpl.md): a path leaves its light carrying
// β₀ = Le·cosθ / p(x, ω) (W, per channel), p the density of the sampled origin and direction
// including the light's pick pmf; at its k-th hit y_k it arrives with β_k and leaves a VPL
// of flux Φ = β_k · ρ(y_k) / N (N the number of paths traced); it continues with
// β_{k+1} = β_k · ρ(y_k) / q, q = min(1, max ρ) the survival probability of the roulette
// (bounce ≥ rouletteBounce). E[Σ VPL flux of bounce k] = the flux leaving the surfaces after
// exactly k reflections.
//
// Count (the rule): paths are traced in fixed batches of kVplBatch; after each batch the
// relative standard error of the total VPL flux (luminance, from the per-path totals) is
// checked, and generation stops at the first batch end where it is ≤ relativeError with at
// least minPaths paths, or where the next path would exceed maxVpls VPLs (the cap: paths are
// then kept in order up to the last one that fits), or after 64 × maxVpls paths (a scene whose
// light mostly escapes). The result depends only on (scene, settings without threads): the
// same at any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/vpl.h"
#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/stage_progress.h"

namespace bounce {

inline constexpr int kVplBatch = 1024;

struct VplSettings {
  int maxVpls = 4096;           // the cap (bounce-bake --vpls N)
  float relativeError = 0.01f;  // target relative standard error of the total VPL flux
  int minPaths = 1024;
  int maxBounces = 16;     // deepest VPL (its bounce index); truncation loses ρ^(maxBounces+1)
  int rouletteBounce = 2;  // Russian roulette from this bounce on
  uint32_t seed = 0;
  int threads = 0;  // 0: all cores (TBB's default)
  // VPLs made so far, counted against maxVpls, and whether to stop (checked between batches:
  // then BakeCancelled); null: neither.
  StageProgress* progress = nullptr;
};

struct VplSet {
  std::vector<Vpl> vpls;
  std::vector<uint8_t> bounce;  // per VPL: reflections of the light it re-emits (1 = first hit)
  uint64_t paths = 0;           // N
  // Σ VPL flux per bounce k = 1..maxBounces (index k−1), W per channel, and the standard error
  // of each sum estimated from the per-path contributions.
  std::vector<glm::dvec3> fluxPerBounce;
  std::vector<glm::dvec3> fluxPerBounceError;
  double relativeError = 0.0;  // achieved relative standard error of the total (luminance)

  glm::dvec3 totalFlux() const;
};

// kernel is built over geometry = flatten(scene). No lights: an empty set.
VplSet generateVpls(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                    const VplSettings& settings);

// The bake runs generateVpls in staticScene(scene) (scene/static_scene.h): the VPLs carry the
// static scene's indirect light, which dynamic objects receive wherever they are moved; each VPL
// records its path and the start of its incoming segment, and the renderer cuts the paths the
// placed objects block (vpl_runtime/vpl_occlusion.h). The light the dynamic objects reflect is
// left out.

}  // namespace bounce
