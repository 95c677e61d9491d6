// The bake, one plain function running its steps in order: texel coverage → leak guard →
// irradiance → static area lights' visibility → denoise (optional) → fill invalid texels and dilate
// into the padding → seam stitching. The irradiance and the visibility are computed tile by tile
// (tile_grid.h) by the tile scheduler (tile_scheduler.h): tiles a journal holds are restored
// instead, and a shard computes its share and stops there. GL-free; bounce-bake and the tests call
// it.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "bake/delivered_error.h"
#include "bake/leak_guard.h"
#include "bake/light_visibility_bake.h"
#include "bake/texel_irradiance.h"
#include "bake/tile_scheduler.h"
#include "image/image.h"

namespace bounce {

class IrradianceCache;
class RayKernel;
class StagePlan;
enum class Gather : uint8_t;  // bake_folder/gather.h
struct LightmapLayout;
struct Scene;
struct WorldGeometry;

// Its stages' names, for a StagePlan (trace/stage_progress.h).
inline constexpr char kStageCoverage[] = "texel coverage";
inline constexpr char kStageLeakGuard[] = "leak guard";
inline constexpr char kStageIrradiance[] = "irradiance";
inline constexpr char kStageVisibility[] = "light visibility";
inline constexpr char kStageFilters[] = "denoise, dilate, stitch";

struct LightmapBakeSettings {
  // Where the steps report (those of the plan's stages named above: each begun, counted and
  // finished there) and learn to stop (BakeCancelled); null: silent and never cancelled.
  // irradiance.progress and visibility.progress are set from it.
  const StagePlan* stages = nullptr;
  IrradianceSettings irradiance;
  LeakGuardSettings leak;
  VisibilityBakeSettings visibility;  // seed and threads: the irradiance's
  int pointsPerTexel = 8;             // candidate sample points per texel
  bool denoise = false;
  bool stitch = true;
  bool dilate = true;
  LightmapTiles tiles;
  // Gather::Cache: a cache pass of `cacheSpp` whole paths per texel first, in two half caches
  // of cacheSpp/2 (rounded up) each, dilated, not denoised; then the texels' paths end at the
  // map of their sample's half (irradiance_cache.h).
  Gather gather{};  // Gather::Paths
  int cacheSpp = 32;
  // Gather::Cache: a texel also stops once its standard error is below targetError ·
  // errorFloor · Ē, Ē the cache's mean irradiance over the readable texels (luminance, W/m²):
  // the light the frame shows at its exposure, not the texel's own dimness (texel_irradiance.h).
  // 0: each texel against its own mean only.
  float errorFloor = 0.0f;
};

struct BakePhaseSeconds {
  double coverage = 0, leakGuard = 0, irradiance = 0, visibility = 0, denoise = 0, dilate = 0,
         stitch = 0;
  double total() const {
    return coverage + leakGuard + irradiance + visibility + denoise + dilate + stitch;
  }
};

struct LightmapBake {
  Image irradiance;                  // W/m², layout.width × layout.height
  std::vector<uint32_t> samples;     // per texel
  std::vector<float> relativeError;  // per texel, estimated relative standard error
  std::vector<uint8_t> covered;      // per texel: some triangle overlaps it
  std::vector<uint8_t> invalid;      // per texel: covered, every point dropped, filled
  uint64_t coveredTexels = 0;
  // Texels the zero rule stopped at 0 that took their lit neighbours' mean (fillUnresolvedZeros).
  uint64_t zerosFilled = 0;
  std::vector<uint8_t> zeroFilled;  // per texel: one of those
  uint64_t invalidTexels = 0;
  uint64_t pointsInside = 0, pointsAcross = 0;
  uint64_t rays = 0;  // leak guard + irradiance
  uint64_t totalSamples = 0;
  uint64_t nonFiniteSamples = 0;  // counted as black (texel_irradiance.h)
  // The sampler's estimate over valid covered texels with E > 0, before any filter: mean and
  // 95th percentile of the per-texel relative standard error (what the adaptive stop uses).
  float meanRelativeError = 0.0f;
  float p95RelativeError = 0.0f;
  // The half-sample difference D (W/m², delivered_error.h); after the filters, one draw of the
  // delivered map's error (the halves' noise through the filters plus the denoiser's and the
  // stop's estimated bias), and from it the delivered map's estimated relative error (valid
  // covered texels whose delivered E > 0; perTexel −1 elsewhere).
  Image halfDifference;
  std::vector<float> prefixLuminance;  // W/m², texel_irradiance.h
  DeliveredError delivered;
  std::size_t seams = 0;
  float seamMismatch = 0.0f;  // after stitching, relative (stitchSeams)
  BakePhaseSeconds seconds;
  // The static area lights' visibility per texel (light_visibility_bake.h), when the scene has
  // static area lights and settings.visibility.enabled.
  std::optional<BakedVisibility> visibility;
  VisibilityBakeReport visibilityReport;
  // The tiles with work (covered texels), this bake's share of them (all but for a shard), how
  // many of the share were restored rather than computed, and whether this is one shard's part
  // only (then only the tile stages ran: the filters did not, and the texels of other shards'
  // tiles are zero).
  uint32_t tiles = 0, tilesShare = 0, tilesRestored = 0;
  bool partial = false;
  // The cache pass (Gather::Cache), when this process computed tiles: its samples, rays (not in
  // `rays`, which every way of baking reports alike) and seconds (part of the irradiance's).
  uint64_t cacheSamples = 0, cacheRays = 0;
  double cacheSeconds = 0.0;
  double cacheMeanIrradiance = 0.0;   // Ē, luminance, W/m² (0 without a cache pass)
  double errorFloorIrradiance = 0.0;  // errorFloor · Ē, W/m²: the stop's floor
};

// bounce-bake's defaults, chosen on the Cornell box (docs/baker.md): at most 4096 samples per
// texel, target relative standard error 10%, denoiser on; gathered with a 32-sample cache
// (measured on the Cornell box and the Conference Room: docs/baker.md "Gather with a cache"). The
// texel size has its own rule (atlas/texel_density.h).
LightmapBakeSettings defaultBakeSettings();

LightmapBake bakeLightmap(const Scene& scene, const WorldGeometry& geometry,
                          const RayKernel& kernel, const LightmapLayout& layout,
                          const LightmapBakeSettings& settings);

// Per texel: 1 where the texel is covered and the leak guard kept some of its points (the texels
// a cache may be read at: irradiance_cache.h).
std::vector<uint8_t> keptTexels(const LightmapBake& bake);
// The mean luminance (W/m²) of `image` (the layout's size) over the texels of `mask`; 0 if none.
double meanLuminance(const Image& image, const std::vector<uint8_t>& mask);

// The delivered map of a whole `bake` as a cache (irradiance_cache.h: both halves the map, read
// where the leak guard kept a texel's points): paths that end at it after one reflection, as
// the texels' final samples end at the cache pass's (the probes: pipeline/probe_stage.h), read
// the light of every sample, denoised. Null when the map holds baked-only lights' direct light,
// which the paths' next-event estimate would count a second time, or holds no texel. `scene`,
// `geometry` and `layout` are the bake's (geometry must outlive the cache).
std::unique_ptr<IrradianceCache> deliveredMapCache(const Scene& scene,
                                                   const WorldGeometry& geometry,
                                                   const LightmapLayout& layout,
                                                   const LightmapBake& bake);

}  // namespace bounce
