#include "bake/lightmap_bake.h"

#include <algorithm>
#include <array>
#include <chrono>

#include "bake/baked_light.h"
#include "bake/error_summary.h"
#include "bake/irradiance_cache.h"
#include "bake/lightmap_filters.h"
#include "bake/texel_coverage.h"
#include "bake/tile_grid.h"
#include "bake/tile_payload.h"
#include "bake/tile_scheduler.h"
#include "bake_folder/gather.h"
#include "bake_folder/lightmap_layout.h"
#include "image/luminance.h"
#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/sampling.h"
#include "trace/stopwatch.h"

namespace bounce {

namespace {

// Candidate points use a pattern of their own, apart from the irradiance samples'.
constexpr uint32_t kPointSeedSalt = 0x9e3779b9u;
// So does each half of the cache pass: their errors are independent of each other and of the
// final gather's samples.
constexpr uint32_t kCacheSeedSalt[2] = {0x85ebca6bu, 0xc2b2ae35u};

// A stage of the plan, begun (and checked for a cancel) when the plan has it.
std::unique_ptr<StageProgress> beginStage(const StagePlan* plan, const char* name, uint64_t total) {
  std::unique_ptr<StageProgress> s = plan && plan->has(name) ? plan->begin(name, total) : nullptr;
  if (s) s->throwIfCancelled();
  return s;
}

// Texel coverage: each texel's sample points, by clipped area; bake.covered from it.
TexelCoverage coverTexels(const Scene& scene, const WorldGeometry& geometry,
                          const LightmapLayout& layout, const LightmapBakeSettings& settings,
                          LightmapBake& bake) {
  const std::unique_ptr<StageProgress> step = beginStage(settings.stages, kStageCoverage, 1);
  TexelCoverage coverage = buildTexelCoverage(scene, geometry, layout, settings.pointsPerTexel,
                                              settings.irradiance.seed ^ kPointSeedSalt);
  bake.covered.assign(coverage.texelCount(), 0);
  for (std::size_t t = 0; t < bake.covered.size(); ++t)
    bake.covered[t] = coverage.covered(t) ? 1 : 0;
  return coverage;
}

// The leak guard: drops the points inside geometry or across walls; bake.invalid from it.
uint64_t guardLeaks(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                    const LightmapLayout& layout, const LightmapBakeSettings& settings,
                    TexelCoverage& coverage, LightmapBake& bake) {
  const std::unique_ptr<StageProgress> step = beginStage(settings.stages, kStageLeakGuard, 1);
  LeakGuardSettings leak = settings.leak;
  if (leak.threads == 0) leak.threads = settings.irradiance.threads;
  const LeakGuardResult guard =
      guardAgainstLeaks(scene, geometry, kernel, layout.texelSize, leak, coverage);
  bake.invalid = guard.invalid;
  bake.pointsInside = guard.pointsInside;
  bake.pointsAcross = guard.pointsAcross;
  return guard.rays;
}

std::unique_ptr<IrradianceCache> cacheIrradiance(const Scene& scene, const WorldGeometry& geometry,
                                                 const RayKernel& kernel,
                                                 const LightmapLayout& layout,
                                                 const TexelCoverage& coverage,
                                                 const LightmapBakeSettings& settings,
                                                 LightmapBake& bake);

// The irradiance, tile by tile (the scheduler restores, shares and receives the tiles).
void bakeIrradiance(TileScheduler& tiles, const Scene& scene, const WorldGeometry& geometry,
                    const RayKernel& kernel, const LightmapLayout& layout,
                    const TexelCoverage& coverage, const LightmapBakeSettings& settings,
                    LightmapBake& bake) {
  std::unique_ptr<IrradianceCache> cache;
  TiledStage<TexelIrradiance> stage;
  stage.stage = TileStage::Irradiance;
  stage.compute = [&](const TileWork& work, StageProgress* progress, auto done) {
    IrradianceSettings irradiance = settings.irradiance;
    // Only a process with tiles to compute needs the cache (not a merge, nor a finished resume).
    if (settings.gather == Gather::Cache && (!work.tiles.empty() || work.next)) {
      cache = cacheIrradiance(scene, geometry, kernel, layout, coverage, settings, bake);
      irradiance.cache = {&cache->half(0), &cache->half(1)};
      // The cache pass is the same bytes in every process: so is the floor.
      bake.errorFloorIrradiance = settings.errorFloor * bake.cacheMeanIrradiance;
      irradiance.errorFloor = bake.errorFloorIrradiance;
    }
    irradiance.work = work;
    irradiance.tileDone = std::move(done);
    irradiance.progress = progress;
    return gatherIrradiance(scene, geometry, kernel, coverage, irradiance);
  };
  stage.encode = [&](const TexelIrradiance& texels, TileRect tile) {
    return encodeIrradianceTile(texels, coverage, tile);
  };
  stage.decode = [&](const TileRecord& record, TileRect tile, TexelIrradiance& into) {
    decodeIrradianceTile(record.source, record.bytes, coverage, tile, into);
  };
  TexelIrradiance gathered = tiles.run(
      stage, [&](uint64_t rows) { return beginStage(settings.stages, kStageIrradiance, rows); });
  gathered.summarise();
  bake.tilesRestored = tiles.restored(TileStage::Irradiance);
  bake.irradiance = std::move(gathered.irradiance);
  bake.samples = std::move(gathered.samples);
  bake.relativeError = std::move(gathered.relativeError);
  bake.halfDifference = std::move(gathered.halfDifference);
  bake.prefixLuminance = std::move(gathered.prefixLuminance);
  bake.rays += gathered.totalRays;
  bake.totalSamples = gathered.totalSamples;
  bake.nonFiniteSamples = gathered.nonFiniteSamples;
}

// The static area lights' visible fraction per texel, tile by tile like the irradiance; filled
// into the uncovered texels of their charts unless only part of the bake is computed here.
void bakeVisibility(TileScheduler& tiles, const AreaLightSet& lights, const Scene& scene,
                    const RayKernel& kernel, const TexelCoverage& coverage,
                    const std::vector<uint32_t>& labels, const LightmapBakeSettings& settings,
                    LightmapBake& bake) {
  TiledStage<VisibilityTexels> stage;
  stage.stage = TileStage::Visibility;
  stage.compute = [&](const TileWork& work, StageProgress* progress, auto done) {
    VisibilityBakeSettings visibility = settings.visibility;
    visibility.seed = settings.irradiance.seed;
    visibility.threads = settings.irradiance.threads;
    visibility.work = work;
    visibility.tileDone = std::move(done);
    visibility.progress = progress;
    return bakeVisibilityTexels(lights, scene.lights, kernel, coverage, visibility);
  };
  stage.encode = [&](const VisibilityTexels& texels, TileRect tile) {
    return encodeVisibilityTile(texels, coverage, tile);
  };
  stage.decode = [&](const TileRecord& record, TileRect tile, VisibilityTexels& into) {
    decodeVisibilityTile(record.source, record.bytes, coverage, tile, into);
  };
  VisibilityTexels computed = tiles.run(
      stage, [&](uint64_t rows) { return beginStage(settings.stages, kStageVisibility, rows); });
  bake.visibilityReport = summariseVisibility(computed);
  bake.visibility = std::move(computed.map);
  bake.rays += bake.visibilityReport.rays;
  if (!bake.partial) {
    std::vector<uint8_t> filled(coverage.texelCount(), 0);
    for (std::size_t t = 0; t < filled.size(); ++t) filled[t] = coverage.covered(t) ? 1 : 0;
    fillVisibility(*bake.visibility, filled, &labels);
  }
}

// Texels the zero rule stopped before the cap are unknown, not black (fillUnresolvedZeros);
// then the texel counts and the error summary, filled texels left out. Returns the valid texels.
std::vector<uint8_t> fillZerosAndSummarise(const TexelCoverage& coverage,
                                           const std::vector<uint32_t>& labels,
                                           const LightmapBakeSettings& settings,
                                           LightmapBake& bake) {
  const std::size_t texels = coverage.texelCount();
  std::vector<uint8_t> unresolved(texels, 0);
  for (std::size_t t = 0; t < texels; ++t)
    unresolved[t] = coverage.covered(t) && bake.irradiance.pixels[t] == glm::vec3(0.0f) &&
                            bake.samples[t] < static_cast<uint32_t>(settings.irradiance.maxSpp)
                        ? 1
                        : 0;
  bake.zerosFilled =
      fillUnresolvedZeros(bake.irradiance, unresolved, bake.invalid, labels, bake.relativeError);
  std::vector<float> unused = bake.relativeError;  // the same fill of the half difference
  fillUnresolvedZeros(bake.halfDifference, unresolved, bake.invalid, labels, unused);
  bake.zeroFilled.assign(texels, 0);
  for (std::size_t t = 0; t < texels; ++t)
    bake.zeroFilled[t] = unresolved[t] && bake.irradiance.pixels[t] != glm::vec3(0.0f) ? 1 : 0;
  std::vector<uint8_t> valid(texels, 0);
  std::vector<float> errors;
  for (std::size_t t = 0; t < texels; ++t) {
    bake.coveredTexels += bake.covered[t];
    bake.invalidTexels += bake.invalid[t];
    valid[t] = coverage.covered(t) ? 1 : 0;
    // A filled texel's error is unknown (1 is a stand-in for the denoiser): not in the summary.
    if (valid[t] && !unresolved[t] && luminance(bake.irradiance.pixels[t]) > 0.0f)
      errors.push_back(bake.relativeError[t]);
  }
  const ErrorSummary summary = summariseErrors(std::move(errors));
  bake.meanRelativeError = summary.mean;
  bake.p95RelativeError = summary.p95;
  return valid;
}

// The denoiser, guided by each texel's mean sample point, normal, chart and error.
void denoiseMap(const TexelCoverage& coverage, const std::vector<uint32_t>& labels,
                const LightmapLayout& layout, LightmapBake& bake) {
  const std::size_t texels = coverage.texelCount();
  DenoiseGuide guide;
  guide.position.assign(texels, glm::vec3(0.0f));
  guide.normal.assign(texels, glm::vec3(0.0f));
  guide.label.assign(texels, 0);
  guide.relativeError = bake.relativeError;
  guide.texelSize = layout.texelSize;
  for (std::size_t t = 0; t < texels; ++t) {
    const uint32_t n = coverage.pointCount(t);
    if (n == 0) continue;
    glm::vec3 p(0.0f), nrm(0.0f);
    for (uint32_t k = coverage.first[t]; k < coverage.first[t + 1]; ++k) {
      p += coverage.points[k].position;
      nrm += coverage.points[k].shadingNormal;
    }
    guide.position[t] = p / static_cast<float>(n);
    guide.normal[t] = glm::length(nrm) > 0.0f ? glm::normalize(nrm) : nrm;
    guide.label[t] = labels[t];
  }
  denoiseWithErrorDraw(bake.irradiance, bake.halfDifference, guide);
}

// Invalid texels take their chart's valid neighbours' values, then everything grows into the
// padding. The masks depend on the texels' flags only: the same filter for any image.
void dilateMap(const std::vector<uint8_t>& valid, const std::vector<uint32_t>& labels,
               const LightmapLayout& layout, const LightmapBake& bake, Image& image) {
  std::vector<uint8_t> filled = valid;
  for (std::size_t t = 0; t < filled.size(); ++t)
    filled[t] |= static_cast<uint8_t>(!bake.covered[t]);
  while (dilateOnce(image, filled, &labels) > 0) {
  }
  filled = valid;
  for (std::size_t t = 0; t < filled.size(); ++t) filled[t] |= bake.invalid[t];
  for (int ring = 0; ring < std::max(layout.padding, 2); ++ring) dilateOnce(image, filled);
}

// The cache pass (irradiance_cache.h): two half caches, each every covered texel's total
// irradiance E_total (every light's direct light and the light that reflected at least once)
// from half of settings.cacheSpp whole paths (rounded up) of a seed of its own, then the final
// map's dilation. A final sample ends at the first hit that reads it, with no next-event
// estimate and no further ray there: one ray a sample where the guards allow (Conference Room,
// default bake: irradiance 24.0 → 13.3 s, Šibenik 107.7 → 76.3 s, their indirect frames 2.19 →
// 2.09 % and 2.00 → 2.00 % off the path tracer; docs/baker.md "Gather with a cache"). Not denoised:
// the denoiser's weights follow the luminance, so a texel whose few skewed samples met a sunlit
// patch is pulled down to its neighbours while one that missed it keeps its low value
// (docs/baker.md: the sunlit room's indirect frame −1.78% with it); the raw cache's noise instead
// reaches the final map's half difference, as each final half reads its own cache. With a fixed
// count and no target no texel is an unresolved zero: the fill has nothing to do. A whole-map stage
// every process that computes tiles runs before them, deterministic like they are, so it is never
// journalled; readable: covered texels the leak guard kept.
std::unique_ptr<IrradianceCache> cacheIrradiance(const Scene& scene, const WorldGeometry& geometry,
                                                 const RayKernel& kernel,
                                                 const LightmapLayout& layout,
                                                 const TexelCoverage& coverage,
                                                 const LightmapBakeSettings& settings,
                                                 LightmapBake& bake) {
  Stopwatch clock;
  IrradianceSettings pass = settings.irradiance;
  pass.maxSpp = std::max((settings.cacheSpp + 1) / 2, 1);
  pass.targetError = 0.0f;
  pass.bakedDirect = false;
  pass.totalLight = true;
  pass.cache = {};
  pass.work = TileWork{};
  pass.tileDone = nullptr;
  pass.progress = nullptr;
  const std::vector<uint32_t> labels = labelCharts(layout.width, layout.height, bake.covered);
  std::vector<uint8_t> valid(bake.covered.size(), 0);
  for (std::size_t t = 0; t < valid.size(); ++t) valid[t] = coverage.covered(t) ? 1 : 0;
  std::array<Image, 2> halves;
  bake.cacheSamples = bake.cacheRays = 0;
  for (int h = 0; h < 2; ++h) {
    pass.seed = settings.irradiance.seed ^ kCacheSeedSalt[h];
    TexelIrradiance gathered = gatherIrradiance(scene, geometry, kernel, coverage, pass);
    halves[h] = std::move(gathered.irradiance);
    dilateMap(valid, labels, layout, bake, halves[h]);
    // Its rays are not in bake.rays: a merge computes no cache, yet must report what one
    // process does (bake.json's rays.traced: the leak guard's and the tiles' rays).
    bake.cacheSamples += gathered.totalSamples;
    bake.cacheRays += gathered.totalRays;
  }
  std::vector<uint8_t> readable = keptTexels(bake);
  Image both(layout.width, layout.height);
  for (std::size_t t = 0; t < both.pixels.size(); ++t)
    both.pixels[t] = 0.5f * (halves[0].pixels[t] + halves[1].pixels[t]);
  bake.cacheMeanIrradiance = meanLuminance(both, readable);
  bake.cacheSeconds = clock.lap();
  return std::make_unique<IrradianceCache>(scene, geometry, layout, std::move(halves),
                                           std::move(readable), /*holdsDirect=*/true);
}

}  // namespace

LightmapBakeSettings defaultBakeSettings() {
  LightmapBakeSettings settings;
  settings.irradiance.maxSpp = 4096;
  settings.irradiance.targetError = 0.1f;
  settings.denoise = true;
  settings.gather = Gather::Cache;
  settings.cacheSpp = 32;
  // Texels dimmer than a tenth of the scene's mean light stop at an error the frame cannot show
  // beside it. Conference Room: 382 → 307 samples a texel, irradiance 29.1 → 24.0 s, the
  // indirect frame 2.19 % off the path tracer either way (docs/baker.md "A floor for dim texels").
  settings.errorFloor = 0.1f;
  return settings;
}

LightmapBake bakeLightmap(const Scene& scene, const WorldGeometry& geometry,
                          const RayKernel& kernel, const LightmapLayout& layout,
                          const LightmapBakeSettings& settings) {
  LightmapBake bake;
  Stopwatch clock;
  TexelCoverage coverage = coverTexels(scene, geometry, layout, settings, bake);
  bake.seconds.coverage = clock.lap();
  bake.rays = guardLeaks(scene, geometry, kernel, layout, settings, coverage, bake);
  bake.seconds.leakGuard = clock.lap();

  // The tiles with work, this bake's share of them, and those earlier runs finished.
  const TileGrid grid(layout.width, layout.height, settings.tiles.size);
  TileScheduler tiles(grid, tilesByCost(grid, coverage), settings.tiles);
  bake.tiles = tiles.tiles();
  bake.tilesShare = tiles.share();
  bake.partial = tiles.partial();
  bakeIrradiance(tiles, scene, geometry, kernel, layout, coverage, settings, bake);
  bake.seconds.irradiance = clock.lap();
  const std::vector<uint32_t> labels = labelCharts(layout.width, layout.height, bake.covered);
  const AreaLightSet lights = sceneAreaLights(scene);
  if (settings.visibility.enabled && hasBakeableVisibility(lights, scene.lights))
    bakeVisibility(tiles, lights, scene, kernel, coverage, labels, settings, bake);
  bake.seconds.visibility = bake.visibilityReport.seconds = clock.lap();
  // A shard's part holds its tiles only: the filters need the whole map (the merge runs them).
  if (bake.partial) return bake;

  const std::unique_ptr<StageProgress> step = beginStage(settings.stages, kStageFilters, 1);
  const std::vector<uint8_t> valid = fillZerosAndSummarise(coverage, labels, settings, bake);
  std::vector<uint8_t> own = valid, sampled = valid;  // texels with samples of their own;
  for (std::size_t t = 0; t < own.size(); ++t) {      // and of those, the ones holding them
    own[t] &= static_cast<uint8_t>(!bake.invalid[t] && bake.samples[t] > 0);
    sampled[t] = own[t] & static_cast<uint8_t>(!bake.zeroFilled[t]);
  }
  const std::vector<float> stopBias =
      stoppingBias(bake.irradiance, bake.prefixLuminance, sampled, labels);
  if (settings.denoise) denoiseMap(coverage, labels, layout, bake);
  addStoppingBias(bake.halfDifference, bake.irradiance, stopBias);
  bake.seconds.denoise = clock.lap();
  if (settings.dilate) {
    dilateMap(valid, labels, layout, bake, bake.irradiance);
    dilateMap(valid, labels, layout, bake, bake.halfDifference);
  }
  bake.seconds.dilate = clock.lap();
  if (settings.stitch) {
    const std::vector<Seam> seams = findSeams(scene, geometry, layout);
    bake.seams = seams.size();
    bake.seamMismatch = stitchSeams(bake.irradiance, seams);
    stitchSeams(bake.halfDifference, seams, 64, false);
  }
  bake.seconds.stitch = clock.lap();
  bake.delivered = deliveredError(bake.irradiance, bake.halfDifference, own, bake.zeroFilled);
  if (step) step->advance(1);
  return bake;
}

std::unique_ptr<IrradianceCache> deliveredMapCache(const Scene& scene,
                                                   const WorldGeometry& geometry,
                                                   const LightmapLayout& layout,
                                                   const LightmapBake& bake) {
  if (bake.partial || bake.irradiance.pixels.empty()) return nullptr;
  if (holdsBakedDirect(scene)) return nullptr;
  return std::make_unique<IrradianceCache>(scene, geometry, layout,
                                           std::array<Image, 2>{bake.irradiance, bake.irradiance},
                                           keptTexels(bake));
}

std::vector<uint8_t> keptTexels(const LightmapBake& bake) {
  std::vector<uint8_t> kept(bake.covered.size(), 0);
  for (std::size_t t = 0; t < kept.size(); ++t)
    kept[t] = bake.covered[t] && !bake.invalid[t] ? 1 : 0;
  return kept;
}

double meanLuminance(const Image& image, const std::vector<uint8_t>& mask) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t t = 0; t < mask.size(); ++t) {
    if (!mask[t]) continue;
    sum += luminance(image.pixels[t]);
    ++count;
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace bounce
