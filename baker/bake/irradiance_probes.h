// The probe stage of the bake: irradiance probes (bake_folder/irradiance_probes.h) for the static
// instances the atlas leaves without a lightmap region (atlas/atlas.h: too small or too thin for
// texels), so that the renderer lights them from baked data, not from a per-pixel VPL gather.
// GL-free.
//
// Placement (placeProbeGrids): one grid per such instance over its world bounding box grown by
// a margin m on every side: spacing target h = clamp(longest edge of the box / 2,
// kMinProbeSpacing, kMaxProbeSpacing), m = max(h/4, kMinProbeMargin), counts per axis
// round((extent + 2m)/h) + 1 clamped to [2, kMaxProbeGridCount], the probes spread evenly over
// the grown box (corners on its corners). A 30 cm box on a shelf gets 2×2×2 probes, a thin plate
// two layers, one on either side at distance m (the renderer reads the grid at p + m·n); an
// instance that is many small pieces spread over a room (the Conference Room's twelve chairs are
// one mesh) gets h = 25 cm over the whole room, and only the probes a surface of it can read are
// sampled (neededProbes: the corners of every cell its triangles' boxes, grown by m, touch); the
// others stay 0, never read (docs/probes.md says why this and not a scene-wide grid).
//
// Leaks: a probe whose kProbeTestRays fixed directions (a spherical Fibonacci set) meet back faces
// of single-sided triangles first for at least kProbeInsideFraction of them sits inside geometry
// or behind a wall (as the texels' leak guard judges a point, leak_guard.h) and is not sampled: it
// takes, ring by ring, the mean of its valid or already filled neighbours in the grid (26-
// neighbourhood, weighted 1/d²); one with none left at all keeps zeros.
//
// Estimate: sample s of probe i uses the sampler pattern (seed, kProbePatterns + i): dimension 0
// draws a uniform normal n on the sphere, dimensions 1 on one sample of the baked light E(n) at the
// probe (baked_light.h: the lightmap's own estimator, so the same light: indirect, plus the direct
// light of baked-only lights). Each sample adds 4π·Y_lm(n)·E(n) to the projection of E onto the L1
// basis (an unbiased estimate of E_lm = ∫ E Y_lm dn). Samples come in batches of 16 until, from
// kMinAdaptiveSpp on, the standard error of E(n) relative to the mean irradiance Y00·E00 is under
// the target for every n (bounded by (Y00·σ00 + Y1·|σ1|)/√N on luminance, σ the per-coefficient
// sample deviations), or maxSpp; an all-zero probe stops as a texel does (zeroSamplesToStop). Every
// probe is one task from its own pattern: the result does not depend on the thread count.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "bake_folder/irradiance_probes.h"
#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/stage_progress.h"
#include "trace/trace_settings.h"

namespace bounce {

inline constexpr float kMinProbeSpacing = 0.10f;  // m
inline constexpr float kMaxProbeSpacing = 0.25f;  // m
inline constexpr float kMinProbeMargin = 0.02f;   // m
inline constexpr int kProbeTestRays = 32;
inline constexpr float kProbeInsideFraction = 0.25f;
// Probe i samples the pattern of pixel kProbePatterns + i: apart from every texel's (< 2^31).
inline constexpr uint32_t kProbePatterns = 0x80000000u;

class IndirectCache;

// An instance to probe: its index in the scene file (stored) and in the scene the bake traces
// (staticScene: WorldGeometry::triangleInstance's numbering).
struct ProbedInstance {
  uint32_t fileIndex = 0;
  uint32_t tracedIndex = 0;
};

// The L1 projection of E over the sphere of normals (irradiance_probes.h's convention) from
// samples at normals drawn uniformly on the sphere (pdf 1/(4π)): each (n, E(n)) adds
// 4π·Y_lm(n)·E(n), whose mean is an unbiased estimate of E_lm = ∫ E Y_lm dn.
class ShProjection {
 public:
  void add(glm::vec3 normal, glm::vec3 irradiance);
  ProbeIrradiance mean() const;
  uint64_t samples() const { return samples_; }

 private:
  std::array<glm::dvec3, 4> sum_{};
  uint64_t samples_ = 0;
};

// One grid per instance with triangles (in `instances` order, which must ascend by fileIndex),
// the probes numbered grid after grid.
// `maxSpacing` (m): the h clamp's upper end, kMaxProbeSpacing unless a measurement asks
// (bench_probe_spacing).
std::vector<ProbeGrid> placeProbeGrids(const WorldGeometry& geometry,
                                       std::span<const ProbedInstance> instances,
                                       float maxSpacing = kMaxProbeSpacing);

// Per probe of `grids` (placeProbeGrids's, for the same instances): whether a surface of its
// instance can read it (a corner of a cell that a triangle's box, grown by the normal offset,
// touches).
std::vector<uint8_t> neededProbes(const WorldGeometry& geometry,
                                  std::span<const ProbedInstance> instances,
                                  std::span<const ProbeGrid> grids);

struct ProbeSettings {
  int maxSpp = 4096;         // samples per probe at most
  float targetError = 0.1f;  // relative standard error of E(n) to stop at; 0: always maxSpp
  int maxDepth = 64;
  uint32_t seed = 0;
  LightChoice lightChoice = LightChoice::ByPlace;
  int threads = 0;                      // 0: all cores
  float maxSpacing = kMaxProbeSpacing;  // m, placeProbeGrids's
  // Probes done are counted here (total: the probe count), and cancelling stops the stage.
  StageProgress* progress = nullptr;
  // Where a probe's paths end after their first reflection (trace/indirect_cache.h: the
  // delivered lightmap, pipeline/probe_stage.h); null: whole paths.
  const IndirectCache* cache = nullptr;
  // W/m² (luminance): a probe dimmer than it stops once its standard error is under targetError
  // times it, and its relativeError is against it (the texels' floor, texel_irradiance.h); 0:
  // every probe against its own mean.
  double errorFloor = 0.0;
};

struct ProbeBake {
  IrradianceProbes probes;
  std::vector<uint32_t> samples;     // per probe (0 for one not sampled)
  std::vector<float> relativeError;  // per probe, the stopping estimate (0 if not sampled)
  std::vector<uint8_t> needed;       // per probe: a surface can read it (else left 0)
  std::vector<uint8_t> invalid;      // per probe: needed, but inside geometry or behind a wall
  uint64_t totalSamples = 0, rays = 0, nonFiniteSamples = 0;
  uint64_t unfilled = 0;  // invalid probes no valid one could fill: left 0
  double seconds = 0.0;
};

// `scene` is the traced (static) scene, `geometry` = flatten(scene), `kernel` built over it.
// Throws BakeCancelled when the progress cancels.
ProbeBake bakeIrradianceProbes(const Scene& scene, const WorldGeometry& geometry,
                               const RayKernel& kernel, std::span<const ProbedInstance> instances,
                               const ProbeSettings& settings);

}  // namespace bounce
