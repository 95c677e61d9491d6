// Monte Carlo irradiance E (W/m², per linear-RGB channel) at every covered texel, with an
// error estimate per texel.
//
// What is gathered: the light of baked_light.h (light that reflected at least once, plus the
// direct light of the lights and emitters marked baked-only).
//
// Sample s of texel i uses the sampler pattern (seed, i): dimension 0 picks one of the texel's
// points uniformly, the baked light uses dimensions 1 on (baked_light.h).
// The texel value is the mean over its samples, so it estimates the mean of E over the texel's
// covered area. Samples are taken in batches of 16 until, from 128 samples on, the relative
// standard error of the luminance mean, sqrt(s²/n)/mean, is below `targetError` (for a texel
// dimmer than `errorFloor`, its standard error below targetError · errorFloor) or `maxSpp` is
// reached; a texel whose samples are all zero stops once zeroSamplesToStop() of them met a
// surface (that stayed dark). Every texel
// is computed by one task from its own pattern: the result does not depend on the thread count, nor
// on the tiles the work is cut into (tile_work.h).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "bake/tile_work.h"
#include "bake_folder/light_choice.h"
#include "image/image.h"

namespace bounce {

class IndirectCache;
class RayKernel;
class StageProgress;
struct Scene;
struct TexelCoverage;
struct WorldGeometry;

struct TexelIrradiance;

struct IrradianceSettings {
  int maxSpp = 1024;         // samples per texel at most
  float targetError = 0.0f;  // relative standard error to stop at; 0: always maxSpp
  // W/m² (luminance): a texel stops once its standard error is below targetError · max(mean,
  // errorFloor), so a texel dimmer than the floor stops at an absolute error; 0: relative only.
  double errorFloor = 0.0;
  int maxDepth = 64;  // most diffuse reflections along a path
  uint32_t seed = 0;
  LightChoice lightChoice = LightChoice::ByPlace;  // next-event estimation's (trace_settings.h)
  int threads = 0;                                 // 0: all cores
  // Where the rows of texels done are counted (total: the coverage's rows), and whether to stop
  // (then BakeCancelled is thrown after the rows in flight); null: neither.
  StageProgress* progress = nullptr;
  // The tiles to compute (all texels by default); the others are left zero.
  TileWork work;
  // Ends the indirect paths of the samples of half h (delivered_error.h's split) at cache[h]
  // (trace/indirect_cache.h, irradiance_cache.h); null: whole paths. Must outlive the call.
  std::array<const IndirectCache*, 2> cache{};
  // false: without the separate estimate of the baked-only lights' direct light (the cache pass,
  // whose totalLight paths hold every light's).
  bool bakedDirect = true;
  // true: the light arriving at the texel by every path, its direct light too (E_total, the
  // cache pass of a cache that holds it: IndirectCache::holdsDirect).
  bool totalLight = false;
  // Called with each tile of `work` once its texels are in `out`, from the worker that finished
  // it (several at once: it must lock what it shares); may be empty.
  std::function<void(uint32_t tile, const TexelIrradiance& out)> tileDone;
};

inline constexpr int kIrradianceBatch = 16;
// The error estimate is trusted from eight batches on. Stopping on an estimate biases the texel
// low: a skewed sample that has not yet met its rare large values has a low mean and a low s²
// together. From 32 samples the default bake's furnace came out −1.7% (every pixel), from 64
// −0.4%, from 128 +0.2% (docs/baker.md, issue 15).
inline constexpr uint32_t kMinAdaptiveSpp = 128;

// When adaptive, a texel whose samples are all 0 stops (black) once h of them met a surface: a
// sample whose first ray leaves the scene is an exact 0 (no light at infinity), so the doubt is
// only whether the surfaces it meets are ever lit. h zero samples on surfaces put that chance p
// under 3/h (95%, the rule of three), and a texel with that p needs about h/(3·target²) more
// samples on surfaces to reach the target: beyond maxSpp once h ≥ 3·target²·maxSpp, so more
// samples could not bring it to the target anyway. At least kMinAdaptiveSpp, at most maxSpp;
// the default (10%, 4096) gives 128. Whatever its samples met, an all-zero texel stops at
// maxSpp/4 samples (a quad facing empty space meets nothing): a light path of probability
// 3/(maxSpp/4) would have shown at 95%, and such a texel too could not reach the target within
// the cap. A floor whose only light is a small lit board above it (1.1% of its samples meet the
// board) is not stopped: a sample meeting the board is lit, and 1024 samples all miss it with
// probability 1e-5; the surfaces no light reaches are (Šibenik's outside at night: 35% of its
// texels, which took 90% of its samples before; docs/baker.md).
uint32_t zeroSamplesToStop(float targetError, int maxSpp);

struct TexelIrradiance {
  Image irradiance;                  // W/m², coverage.width × coverage.height; 0 where uncovered
  std::vector<uint32_t> samples;     // per texel
  std::vector<float> relativeError;  // per texel, estimated relative standard error (0 uncovered)
  // Per texel, a draw of its mean's error from two random halves of its samples (W/m²,
  // delivered_error.h); 0 uncovered.
  Image halfDifference;
  // Per texel, the luminance of the mean of its first min(kMinAdaptiveSpp, n) samples (W/m²):
  // a fixed count, so unbiased where the adaptive stop is not (delivered_error.h); 0 uncovered.
  std::vector<float> prefixLuminance;
  // Per texel: samples whose estimate was non-finite (bad scene data) and counted as black (each
  // biases its texel low, PathTracer::irradiance); closest-hit and occlusion rays traced.
  std::vector<uint32_t> nonFinite, rays;
  // Sums over every texel (summarise()).
  uint64_t totalRays = 0, totalSamples = 0, nonFiniteSamples = 0;
  double seconds = 0.0;

  // The sums from the per-texel counts, whichever tiles computed them.
  void summarise();
};

TexelIrradiance gatherIrradiance(const Scene& scene, const WorldGeometry& geometry,
                                 const RayKernel& kernel, const TexelCoverage& coverage,
                                 const IrradianceSettings& settings);

}  // namespace bounce
