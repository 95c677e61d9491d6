#include "bake/lightmap_bake.h"

#include <algorithm>
#include <chrono>

#include "bake/lightmap_filters.h"
#include "bake/texel_coverage.h"
#include "bake/tile_grid.h"
#include "scene/load_error.h"
#include "trace/sampling.h"
#include "trace/stopwatch.h"

namespace bounce {

namespace {

// Candidate points use a pattern of their own, apart from the irradiance samples'.
constexpr uint32_t kPointSeedSalt = 0x9e3779b9u;

}  // namespace

LightmapBakeSettings defaultBakeSettings() {
  LightmapBakeSettings settings;
  settings.irradiance.maxSpp = 4096;
  settings.irradiance.targetError = 0.1f;
  settings.denoise = true;
  return settings;
}

LightmapBake bakeLightmap(const Scene& scene, const WorldGeometry& geometry,
                          const RayKernel& kernel, const LightmapLayout& layout,
                          const LightmapBakeSettings& settings) {
  LightmapBake bake;
  Stopwatch clock;
  // A stage of the plan, begun (and checked for a cancel) when the plan has it.
  const auto stage = [&](const char* name, uint64_t total) {
    std::unique_ptr<StageProgress> s = settings.stages && settings.stages->has(name)
                                           ? settings.stages->begin(name, total)
                                           : nullptr;
    if (s) s->throwIfCancelled();
    return s;
  };
  std::unique_ptr<StageProgress> step = stage(kStageCoverage, 1);
  TexelCoverage coverage = buildTexelCoverage(scene, geometry, layout, settings.pointsPerTexel,
                                              settings.irradiance.seed ^ kPointSeedSalt);
  const std::size_t texels = coverage.texelCount();
  bake.covered.assign(texels, 0);
  for (std::size_t t = 0; t < texels; ++t) bake.covered[t] = coverage.covered(t) ? 1 : 0;
  bake.seconds.coverage = clock.lap();
  step.reset();

  step = stage(kStageLeakGuard, 1);
  LeakGuardSettings leak = settings.leak;
  if (leak.threads == 0) leak.threads = settings.irradiance.threads;
  const LeakGuardResult guard =
      guardAgainstLeaks(scene, geometry, kernel, layout.texelSize, leak, coverage);
  bake.invalid = guard.invalid;
  bake.pointsInside = guard.pointsInside;
  bake.pointsAcross = guard.pointsAcross;
  bake.seconds.leakGuard = clock.lap();
  step.reset();

  // The tiles with work, this bake's share of them, and those earlier runs finished.
  const LightmapTiles& tiling = settings.tiles;
  const TileGrid grid(layout.width, layout.height, tiling.size);
  const std::vector<uint32_t> byCost = tilesByCost(grid, coverage);
  const std::vector<uint32_t> mine =
      tiling.shards > 1 ? shardTiles(byCost, tiling.shard, tiling.shards) : byCost;
  bake.tiles = static_cast<uint32_t>(byCost.size());
  bake.tilesShare = static_cast<uint32_t>(mine.size());
  TileExchange* exchange = tiling.exchange;
  bake.partial = tiling.shards > 1 || (exchange && !exchange->keeper());
  std::vector<uint8_t> hasWork(grid.count(), 0);
  for (const uint32_t t : byCost) hasWork[t] = 1;
  std::vector<const TileRecord*> restored[2];  // by stage, then tile
  for (std::vector<const TileRecord*>& r : restored) r.assign(grid.count(), nullptr);
  for (const TileRecord& record : tiling.restored) {
    if (record.tile >= grid.count() || !hasWork[record.tile])
      throw LoadError(record.source, "holds tile " + std::to_string(record.tile) +
                                         ", which is not one of this bake's " +
                                         std::to_string(byCost.size()) + " tiles with work");
    const TileRecord*& slot = restored[static_cast<int>(record.stage) - 1][record.tile];
    if (slot && slot->bytes != record.bytes)
      throw LoadError(record.source, "holds tile " + std::to_string(record.tile) + " twice, " +
                                         "with different texels (also in " + slot->source.string() +
                                         ")");
    slot = &record;
  }
  // This bake's tiles of `stage` that no earlier run finished, in cost order.
  const auto todo = [&](TileStage of) {
    std::vector<uint32_t> left;
    for (const uint32_t t : mine)
      if (!restored[static_cast<int>(of) - 1][t]) left.push_back(t);
    if (!left.empty() && !tiling.computeMissing)
      throw MissingTiles(std::to_string(left.size()) + " of the " + std::to_string(mine.size()) +
                         " tiles of the " +
                         (of == TileStage::Irradiance ? "irradiance" : "visibility") +
                         " are in no part (tile " + std::to_string(left.front()) + " first)");
    return left;
  };
  const auto journal = [&](TileStage of, uint32_t tile, std::vector<unsigned char> bytes) {
    const TileRecord record{of, tile, std::move(bytes), {}};
    if (exchange) exchange->finished(record);
    if (tiling.finished) tiling.finished(record);
  };
  // With an exchange the stage's tiles are pulled from it, one at a time.
  const auto share = [&](TileStage of, TileWork& work) {
    if (!exchange) return;
    exchange->open(of, work.tiles);
    work.next = [exchange, of] { return exchange->next(of); };
  };
  // The tiles other processes computed (the keeper's), checked like restored ones and journalled.
  const auto received = [&](TileStage of) {
    std::vector<TileRecord> records;
    if (exchange) records = exchange->gather(of);
    for (const TileRecord& record : records) {
      if (record.tile >= grid.count() || !hasWork[record.tile])
        throw std::runtime_error("a process sent tile " + std::to_string(record.tile) +
                                 ", which is not one of this bake's tiles");
      if (tiling.finished) tiling.finished(record);
    }
    return records;
  };

  IrradianceSettings irradiance = settings.irradiance;
  irradiance.work = {&grid, todo(TileStage::Irradiance), {}};
  bake.tilesRestored = static_cast<uint32_t>(mine.size() - irradiance.work.tiles.size());
  irradiance.tileDone = [&](uint32_t tile, const TexelIrradiance& out) {
    journal(TileStage::Irradiance, tile, encodeIrradianceTile(out, coverage, grid.rect(tile)));
  };
  step = stage(kStageIrradiance, tileRows(irradiance.work, coverage.height));
  irradiance.progress = step.get();
  share(TileStage::Irradiance, irradiance.work);
  TexelIrradiance gathered = gatherIrradiance(scene, geometry, kernel, coverage, irradiance);
  for (const TileRecord* record : restored[0])
    if (record)
      decodeIrradianceTile(record->source, record->bytes, coverage, grid.rect(record->tile),
                           gathered);
  for (const TileRecord& record : received(TileStage::Irradiance)) {
    decodeIrradianceTile(record.source, record.bytes, coverage, grid.rect(record.tile), gathered);
    if (irradiance.progress) irradiance.progress->advance(grid.rect(record.tile).height());
  }
  gathered.summarise();
  bake.irradiance = std::move(gathered.irradiance);
  bake.samples = std::move(gathered.samples);
  bake.relativeError = std::move(gathered.relativeError);
  bake.rays = guard.rays + gathered.totalRays;
  bake.totalSamples = gathered.totalSamples;
  bake.nonFiniteSamples = gathered.nonFiniteSamples;
  bake.seconds.irradiance = clock.lap();
  step.reset();

  const std::vector<uint32_t> labels = labelCharts(layout.width, layout.height, bake.covered);
  const AreaLightSet lights = sceneAreaLights(scene);
  if (settings.visibility.enabled && hasBakeableVisibility(lights, scene.lights)) {
    VisibilityBakeSettings visibility = settings.visibility;
    visibility.seed = settings.irradiance.seed;
    visibility.threads = settings.irradiance.threads;
    visibility.work = {&grid, todo(TileStage::Visibility), {}};
    visibility.tileDone = [&](uint32_t tile, const VisibilityTexels& out) {
      journal(TileStage::Visibility, tile, encodeVisibilityTile(out, coverage, grid.rect(tile)));
    };
    step = stage(kStageVisibility, tileRows(visibility.work, coverage.height));
    visibility.progress = step.get();
    share(TileStage::Visibility, visibility.work);
    VisibilityTexels computed =
        bakeVisibilityTexels(lights, scene.lights, kernel, coverage, visibility);
    for (const TileRecord* record : restored[1])
      if (record)
        decodeVisibilityTile(record->source, record->bytes, coverage, grid.rect(record->tile),
                             computed);
    for (const TileRecord& record : received(TileStage::Visibility)) {
      decodeVisibilityTile(record.source, record.bytes, coverage, grid.rect(record.tile), computed);
      if (visibility.progress) visibility.progress->advance(grid.rect(record.tile).height());
    }
    bake.visibilityReport = summariseVisibility(computed);
    bake.visibility = std::move(computed.map);
    bake.rays += bake.visibilityReport.rays;
    if (!bake.partial) {
      std::vector<uint8_t> filled(texels, 0);
      for (std::size_t t = 0; t < texels; ++t) filled[t] = coverage.covered(t) ? 1 : 0;
      fillVisibility(*bake.visibility, filled, &labels);
    }
  }
  bake.seconds.visibility = bake.visibilityReport.seconds = clock.lap();
  step.reset();
  // A shard's part holds its tiles only: the filters need the whole map (the merge runs them).
  if (bake.partial) return bake;
  step = stage(kStageFilters, 1);

  // Texels the zero rule stopped before the cap are unknown, not black (fillUnresolvedZeros).
  std::vector<uint8_t> unresolved(texels, 0);
  for (std::size_t t = 0; t < texels; ++t)
    unresolved[t] = coverage.covered(t) && bake.irradiance.pixels[t] == glm::vec3(0.0f) &&
                            bake.samples[t] < static_cast<uint32_t>(settings.irradiance.maxSpp)
                        ? 1
                        : 0;
  bake.zerosFilled =
      fillUnresolvedZeros(bake.irradiance, unresolved, bake.invalid, labels, bake.relativeError);
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
  if (!errors.empty()) {
    double sum = 0;
    for (const float e : errors) sum += e;
    bake.meanRelativeError = static_cast<float>(sum / static_cast<double>(errors.size()));
    const std::size_t k = std::min(errors.size() - 1, errors.size() * 95 / 100);
    std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(k), errors.end());
    bake.p95RelativeError = errors[k];
  }

  if (settings.denoise) {
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
    denoise(bake.irradiance, guide);
  }
  bake.seconds.denoise = clock.lap();

  if (settings.dilate) {
    // Invalid texels take their chart's valid neighbours' values, then everything grows into
    // the padding.
    std::vector<uint8_t> filled = valid;
    for (std::size_t t = 0; t < texels; ++t) filled[t] |= static_cast<uint8_t>(!bake.covered[t]);
    while (dilateOnce(bake.irradiance, filled, &labels) > 0) {
    }
    filled = valid;
    for (std::size_t t = 0; t < texels; ++t) filled[t] |= bake.invalid[t];
    for (int ring = 0; ring < std::max(layout.padding, 2); ++ring)
      dilateOnce(bake.irradiance, filled);
  }
  bake.seconds.dilate = clock.lap();

  if (settings.stitch) {
    const std::vector<Seam> seams = findSeams(scene, geometry, layout);
    bake.seams = seams.size();
    bake.seamMismatch = stitchSeams(bake.irradiance, seams);
  }
  bake.seconds.stitch = clock.lap();
  if (step) step->advance(1);
  return bake;
}

}  // namespace bounce
