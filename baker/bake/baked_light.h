// The light a bake holds at a point, one Monte Carlo sample at a time: what the lightmap's
// texels (texel_irradiance.h) and the irradiance probes (irradiance_probes.h) both gather, so
// that the two hold the same light. GL-free.
//
// A sample of the irradiance E (W/m², per linear-RGB channel) on a surface of unit normal n at a
// point: light that reflected at least once before arriving (PathSet::IndirectOnly: the renderer
// adds direct light live), plus the direct light of the lights the scene marks as baked
// (Light::bakeDirect, and emitters of a Material::bakeDirect), which the renderer does not draw.
// The baked direct light uses sampler dimensions kDimBakedDirect..kDimBakedDirect + 3, the
// indirect path kDimIndirect on; dimension 0 is the caller's (which point, which normal).
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/indirect_cache.h"
#include "trace/path_tracer.h"
#include "trace/sobol_sampler.h"
#include "trace/trace_settings.h"

namespace bounce {

inline constexpr uint32_t kDimBakedDirect = 1;
inline constexpr uint32_t kDimIndirect = 5;

// The scene seen by the baked direct light: only the lights and emissive materials marked
// bakeDirect.
Scene bakedDirectScene(const Scene& scene);
// True when some light or emissive material is marked baked-only: the lightmap holds its direct
// light.
bool holdsBakedDirect(const Scene& scene);

class BakedLight {
 public:
  // `trace` gives the depth, seed and light choice (its paths are set here). scene, geometry and
  // kernel must outlive it. `cache`, when given (and outliving it), ends the indirect paths of
  // the samples of half h (delivered_error.h's split) at the cached irradiance of cache[h]
  // (trace/indirect_cache.h), so that the two half-sample maps carry independent cache errors
  // (irradiance_cache.h); `bakedDirect` false leaves out the separate estimate of the baked-only
  // lights' direct light; `gathered` is what the other paths gather: the light that reflected at
  // least once (IndirectOnly), or every light's with the direct light too (All: the cache pass
  // of a cache that holds the total light, where the baked-only lights are among all).
  BakedLight(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
             TraceSettings trace, std::array<const IndirectCache*, 2> cache = {},
             bool bakedDirect = true, PathSet gathered = PathSet::IndirectOnly);
  BakedLight(const BakedLight&) = delete;
  BakedLight& operator=(const BakedLight&) = delete;

  struct Sample {
    glm::vec3 irradiance{0.0f};   // W/m²
    uint32_t nonFinite = 0;       // estimates that were not finite, counted as black (0, 1 or 2)
    bool reachedSurface = false;  // the indirect path's first ray met a surface
  };
  // `half` (0: A, 1: B) picks the cache the sample reads.
  Sample sample(glm::vec3 position, glm::vec3 normal, SobolSampler& sampler, int half = 0) const;

 private:
  Scene directScene_;
  bool anyBakedDirect_;
  PathTracer indirect_, bakedDirect_;
  // Half B's indirect tracer where its cache is not half A's (a tracer reads one cache).
  std::unique_ptr<PathTracer> indirectB_;
};

}  // namespace bounce
