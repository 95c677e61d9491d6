#include "trace/camera_render.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include "trace/denormals_flushed.h"
#include "trace/path_tracer.h"
#include "trace/progress_line.h"
#include "trace/sobol_sampler.h"

namespace bounce {

namespace {

constexpr int kTileSize = 16;  // pixels; each tile runs with denormals flushed

}  // namespace

Ray cameraRay(const Camera& camera, int width, int height, float x, float y) {
  const float tanHalf = std::tan(0.5f * camera.yfov);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const float sx = (2.0f * x / static_cast<float>(width) - 1.0f) * tanHalf * aspect;
  const float sy = (1.0f - 2.0f * y / static_cast<float>(height)) * tanHalf;
  Ray ray;
  ray.origin = camera.position();
  ray.direction = glm::normalize(glm::mat3(camera.cameraToWorld) * glm::vec3(sx, sy, -1.0f));
  return ray;
}

CameraRender traceCamera(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                         const Camera& camera, int width, int height,
                         const TraceSettings& settings) {
  if (width < 1 || height < 1) throw std::invalid_argument("image size must be at least 1x1");
  if (settings.spp < 1) throw std::invalid_argument("spp must be at least 1");
  const PathTracer tracer(scene, geometry, kernel, settings);
  CameraRender out;
  out.radiance = Image(width, height);
  out.sampleVariance = Image(width, height);
  const int tilesX = (width + kTileSize - 1) / kTileSize;
  const int tilesY = (height + kTileSize - 1) / kTileSize;
  const auto spp = static_cast<uint32_t>(settings.spp);
  ProgressLine progress("bounce-trace",
                        static_cast<uint64_t>(tilesX) * static_cast<uint64_t>(tilesY),
                        settings.progress);

  std::vector<uint64_t> tileNonFinite(static_cast<std::size_t>(tilesX) *
                                      static_cast<std::size_t>(tilesY));

  auto renderTile = [&](int tile) {
    uint64_t nonFinite = 0;
    const DenormalsFlushed flushed;
    const int x0 = (tile % tilesX) * kTileSize;
    const int y0 = (tile / tilesX) * kTileSize;
    const int x1 = std::min(x0 + kTileSize, width);
    const int y1 = std::min(y0 + kTileSize, height);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        SobolSampler sampler(settings.seed, static_cast<uint32_t>(out.radiance.index(x, y)));
        // Welford's running mean and sum of squared deviations, in double.
        glm::dvec3 mean(0.0), m2(0.0);
        for (uint32_t s = 0; s < spp; ++s) {
          sampler.startSample(s);
          const glm::vec2 jitter = sampler.get2D();
          const Ray ray = cameraRay(camera, width, height, static_cast<float>(x) + jitter.x,
                                    static_cast<float>(y) + jitter.y);
          bool wasNonFinite = false;
          const glm::dvec3 value(tracer.Li(ray, sampler, &wasNonFinite));
          if (wasNonFinite) ++nonFinite;
          const glm::dvec3 delta = value - mean;
          mean += delta / static_cast<double>(s + 1);
          m2 += delta * (value - mean);
        }
        out.radiance.at(x, y) = glm::vec3(mean);
        out.sampleVariance.at(x, y) =
            spp > 1 ? glm::vec3(m2 / static_cast<double>(spp - 1)) : glm::vec3(0.0f);
      }
    }
    tileNonFinite[static_cast<std::size_t>(tile)] = nonFinite;
    progress.advance(1, static_cast<uint64_t>(x1 - x0) * static_cast<uint64_t>(y1 - y0) * spp);
  };

  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tilesX * tilesY, 1),
        [&](const tbb::blocked_range<int>& range) {
          for (int tile = range.begin(); tile != range.end(); ++tile) renderTile(tile);
        },
        tbb::simple_partitioner());
  });
  for (const uint64_t n : tileNonFinite) out.nonFiniteSamples += n;
  out.samples = static_cast<uint64_t>(width) * static_cast<uint64_t>(height) * spp;
  out.seconds = progress.elapsedSeconds();
  out.threads = arena.max_concurrency();
  return out;
}

}  // namespace bounce
