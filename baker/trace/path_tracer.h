// The unidirectional path tracer: Lambertian surfaces (BRDF ρ/π), cosine-weighted BRDF
// sampling, next-event estimation to ONE light per vertex, picked by what each brings to the
// vertex among the area emitters' clusters and the point, spot and directional lights (by power
// when there are (for checks) virtual point lights: trace/light_sampler.h), MIS with the power
// heuristic (the pick pmf is part of the light strategy's density), Russian roulette on path
// throughput. GL-free; used by the reference renderer and by the lightmap baker.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/emitters.h"
#include "trace/indirect_cache.h"
#include "trace/light_sampler.h"
#include "trace/sobol_sampler.h"
#include "trace/surface_point.h"
#include "trace/trace_settings.h"

namespace bounce {

class PathTracer {
 public:
  // scene, geometry and kernel must outlive the tracer; geometry = flatten(scene) and kernel
  // is built over it. `vpls` (kept by the tracer) are sampled as extra cosine emitters, for
  // checks of the VPL convention (bake_folder/vpl.h); the renderer, not the tracer, draws them.
  PathTracer(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
             const TraceSettings& settings, std::vector<Vpl> vpls = {});
  // lights_ refers to emitters_ and vpls_: not copyable.
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  // One-sample estimate of the radiance arriving at ray.origin from −ray.direction,
  // W/(sr·m²) per channel (i.e. the radiance leaving the first surface hit towards the
  // origin; black where the ray escapes). Uses the sampler's dimensions from its current
  // one on. Always finite: a non-finite estimate (possible only from non-finite scene data
  // that slipped past the checks) is returned as black, which biases the pixel low; when
  // `nonFinite` is given, *nonFinite is set to whether that happened, so the caller can count
  // such samples (traceCamera does: CameraRender::nonFiniteSamples).
  glm::vec3 Li(const Ray& ray, SobolSampler& sampler, bool* nonFinite = nullptr) const;

  // One-sample estimate of the irradiance E (W/m²) at `position` on a surface with unit
  // normal `normal` (facing the hemisphere integrated over): E = π × the radiance a white
  // Lambertian surface there would reflect, estimated with the same NEE + MIS. Always finite,
  // as Li: a non-finite estimate is returned as black and, when `nonFinite` is given,
  // *nonFinite says so, so the baker can count such samples. `reachedSurface`, when given, says
  // whether the sample's first ray from the point met a surface (else the sample is an exact 0
  // wherever the scene has no light at infinity).
  glm::vec3 irradiance(glm::vec3 position, glm::vec3 normal, SobolSampler& sampler,
                       bool* nonFinite = nullptr, bool* reachedSurface = nullptr) const;

  // Ends paths at `cache` (indirect_cache.h) from the first vertex after a reflection on where its
  // guards let it answer, and where that vertex's own next-event light is counted (so never for
  // DirectOnly, and for IndirectOnly from the second vertex of a camera path, the first of an
  // irradiance estimate). The cache must hold the light of this tracer's scene that reflected at
  // least once (PathSet::IndirectOnly irradiance) and outlive the tracer; null: no cache.
  void setCache(const IndirectCache* cache) { cache_ = cache; }

  bool hasLights() const { return !emitters_.empty() || !scene_.lights.empty() || !vpls_.empty(); }
  const EmitterTable& emitters() const { return emitters_; }
  const LightSampler& lightSampler() const { return lights_; }
  const TraceSettings& settings() const { return settings_; }

 private:
  // Radiance reflected at `point` towards its ray's origin, from the first reflection on;
  // `throughput` is the path weight so far, `depth` the reflections before this vertex.
  // `reachedSurface`, when given, is set to whether the first reflected ray met a surface.
  glm::vec3 reflected(SurfacePoint point, glm::vec3 throughput, int depth, uint32_t baseDim,
                      SobolSampler& sampler, bool* reachedSurface = nullptr) const;
  // Next-event estimate of light after one reflection at `point` from one light picked
  // (LightSampler::pickAt), divided by its pick pmf (area emitters with MIS weight), not yet
  // multiplied by the path throughput.
  glm::vec3 sampleLight(const SurfacePoint& point, SobolSampler& sampler) const;
  // Reflected radiance from the area emitters picked (the set, or a cluster when the sampler
  // chooses by place), `coin` tossing the emitter alias table's coin.
  glm::vec3 sampleAreaLight(const SurfacePoint& point, const LightPick& pick, float coin,
                            SobolSampler& sampler) const;
  // Area density (per m² of `triangle`, an emitter) with which next-event estimation at `point`
  // samples a point on it: the pick's pmf times the triangle's within the set or cluster.
  float lightPdfArea(const SurfacePoint& point, uint32_t triangle) const;
  // Reflected radiance from one delta light (exact: no sampling).
  glm::vec3 deltaLight(const SurfacePoint& point, const Light& light) const;
  glm::vec3 virtualLight(const SurfacePoint& point, const Vpl& vpl) const;
  // The firefly clamp (off when settings_.clampRadiance ≤ 0): scales a sample's reflected
  // radiance so its largest channel is at most the clamp. Biased low; see docs/path_tracer.md.
  glm::vec3 clamped(glm::vec3 radiance) const;
  bool visible(glm::vec3 from, glm::vec3 fromNormal, glm::vec3 to, glm::vec3 toNormal) const;

  const Scene& scene_;
  const WorldGeometry& geometry_;
  const RayKernel& kernel_;
  TraceSettings settings_;
  EmitterTable emitters_;
  std::vector<Vpl> vpls_;
  LightSampler lights_;  // over emitters_, scene_.lights and vpls_
  bool byPlace_;         // settings ask for it and lights_ can (LightSampler::choosesByPlace)
  int minReflections_;
  int maxReflections_;
  const IndirectCache* cache_ = nullptr;
};

}  // namespace bounce
