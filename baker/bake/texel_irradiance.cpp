#include "bake/texel_irradiance.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include "bake/baked_light.h"
#include "bake/delivered_error.h"
#include "bake/texel_coverage.h"
#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/path_tracer.h"
#include "trace/sampling.h"
#include "trace/sobol_sampler.h"
#include "trace/stage_progress.h"
#include "trace/trace_settings.h"

namespace bounce {

namespace {

constexpr uint32_t kDimPoint = 0;  // then baked_light.h's dimensions

// Forwards every query to `inner` and counts it on the calling thread.
class CountingRayKernel final : public RayKernel {
 public:
  explicit CountingRayKernel(const RayKernel& inner) : inner_(inner) {}
  using RayKernel::intersect;  // the batched forms (one count per ray via the single forms)
  using RayKernel::occluded;
  Hit intersect(const Ray& ray) const override {
    ++count_.local();
    return inner_.intersect(ray);
  }
  bool occluded(const Ray& ray) const override {
    ++count_.local();
    return inner_.occluded(ray);
  }
  const char* name() const override { return inner_.name(); }
  // Rays this thread has traced so far: a texel's rays are the difference across it, as each
  // texel runs on one thread from start to end.
  uint64_t countOnThisThread() const { return count_.local(); }

 private:
  const RayKernel& inner_;
  mutable tbb::enumerable_thread_specific<uint64_t> count_{0};
};

}  // namespace

TexelIrradiance gatherIrradiance(const Scene& scene, const WorldGeometry& geometry,
                                 const RayKernel& kernel, const TexelCoverage& coverage,
                                 const IrradianceSettings& settings) {
  const CountingRayKernel counting(kernel);
  TraceSettings trace;
  trace.maxDepth = settings.maxDepth;
  trace.seed = settings.seed;
  trace.lightChoice = settings.lightChoice;
  const BakedLight light(scene, geometry, counting, trace, settings.cache, settings.bakedDirect,
                         settings.totalLight ? PathSet::All : PathSet::IndirectOnly);

  const std::size_t texels = coverage.texelCount();
  TexelIrradiance out;
  out.irradiance = Image(coverage.width, coverage.height);
  out.halfDifference = Image(coverage.width, coverage.height);
  out.samples.assign(texels, 0);
  out.relativeError.assign(texels, 0.0f);
  out.prefixLuminance.assign(texels, 0.0f);
  out.nonFinite.assign(texels, 0);
  out.rays.assign(texels, 0);
  std::vector<uint32_t>& nonFinite = out.nonFinite;
  const int maxSpp = std::max(settings.maxSpp, 1);
  const auto start = std::chrono::steady_clock::now();
  StageProgress* progress = settings.progress;

  const uint32_t zerosToStop =
      settings.targetError > 0.0f ? zeroSamplesToStop(settings.targetError, maxSpp) : maxSpp;
  const auto zerosToGiveUp = static_cast<uint32_t>(std::max(maxSpp / 4, 1));
  auto bakeTexel = [&](std::size_t texel) {
    const uint32_t begin = coverage.first[texel];
    const uint32_t points = coverage.first[texel + 1] - begin;
    if (points == 0) return;
    const uint64_t raysBefore = counting.countOnThisThread();
    SobolSampler sampler(settings.seed, static_cast<uint32_t>(texel));
    glm::dvec3 sum(0.0);
    HalfSplit halves;
    double mean = 0.0, m2 = 0.0;  // Welford on luminance
    uint32_t n = 0;
    uint32_t reachedSurface = 0;  // samples whose first ray met a surface
    while (n < static_cast<uint32_t>(maxSpp)) {
      const uint32_t batchEnd = std::min<uint32_t>(n + kIrradianceBatch, maxSpp);
      for (; n < batchEnd; ++n) {
        sampler.startSample(n);
        sampler.setDimension(kDimPoint);
        const uint32_t pick = std::min(
            points - 1, static_cast<uint32_t>(sampler.get1D() * static_cast<float>(points)));
        const TexelPoint& point = coverage.points[begin + pick];
        // The sample's half picks the cache it reads.
        const float half = splitSign(settings.seed, static_cast<uint32_t>(texel), n);
        const BakedLight::Sample sample =
            light.sample(point.position, point.shadingNormal, sampler, half > 0.0f ? 0 : 1);
        const glm::vec3 e = sample.irradiance;
        nonFinite[texel] += sample.nonFinite;
        reachedSurface += sample.reachedSurface ? 1 : 0;
        sum += glm::dvec3(e);
        halves.add(e, half);
        const double y = luminance(e);
        const double delta = y - mean;
        mean += delta / static_cast<double>(n + 1);
        m2 += delta * (y - mean);
      }
      const double variance = n > 1 ? m2 / static_cast<double>(n - 1) : 0.0;
      const double standardError = std::sqrt(variance / static_cast<double>(n));
      const float relative = mean > 0.0 ? static_cast<float>(standardError / mean) : 0.0f;
      out.relativeError[texel] = relative;
      if (n <= kMinAdaptiveSpp) out.prefixLuminance[texel] = static_cast<float>(mean);
      // With mean 0 the relative error is undefined (stored as 0).
      // A texel dimmer than the floor stops at the floor's absolute error.
      const bool belowFloor = mean < settings.errorFloor;
      if (settings.targetError > 0.0f && n >= kMinAdaptiveSpp && mean > 0.0 &&
          (belowFloor ? standardError < settings.targetError * settings.errorFloor
                      : relative < settings.targetError))
        break;
      // Samples all 0 so far, with enough of them on surfaces that stayed dark: not even the cap
      // could bring the texel to the target (zeroSamplesToStop).
      if (settings.targetError > 0.0f && mean == 0.0 && n >= kMinAdaptiveSpp &&
          (reachedSurface >= zerosToStop || n >= zerosToGiveUp))
        break;
    }
    out.samples[texel] = n;
    out.irradiance.pixels[texel] = glm::vec3(sum / static_cast<double>(n));
    out.halfDifference.pixels[texel] = halves.difference(sum / static_cast<double>(n), n);
    out.rays[texel] = static_cast<uint32_t>(counting.countOnThisThread() - raysBefore);
  };

  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    forEachTileRow(
        settings.work, coverage.width, coverage.height,
        [&](int y, int x0, int x1) {
          uint64_t rowSamples = 0;
          for (int x = x0; x < x1; ++x) {
            const std::size_t texel = static_cast<std::size_t>(y) * coverage.width + x;
            bakeTexel(texel);
            rowSamples += out.samples[texel];
          }
          if (progress) progress->advance(1, rowSamples);
        },
        [&](uint32_t tile) {
          if (settings.tileDone) settings.tileDone(tile, out);
        },
        [&] { return progress && progress->cancelled(); });
  });
  if (progress) progress->throwIfCancelled();
  out.summarise();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

uint32_t zeroSamplesToStop(float targetError, int maxSpp) {
  const double n = std::ceil(3.0 * static_cast<double>(targetError) * targetError * maxSpp);
  return static_cast<uint32_t>(std::clamp(n, static_cast<double>(kMinAdaptiveSpp),
                                          static_cast<double>(std::max(maxSpp, 1))));
}

void TexelIrradiance::summarise() {
  totalRays = totalSamples = nonFiniteSamples = 0;
  for (const uint32_t r : rays) totalRays += r;
  for (const uint32_t n : samples) totalSamples += n;
  for (const uint32_t n : nonFinite) nonFiniteSamples += n;
}

}  // namespace bounce
