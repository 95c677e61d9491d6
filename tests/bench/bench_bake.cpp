// bench_bake: the default lightmap bake of the Cornell box (wall and CPU time per phase), the
// bake's ray rate against Embree's raw rate on the same scene measured in the same run (the
// incoherent surface rays of bench_ray_kernel), and the lightmap's accuracy against independent
// path-traced irradiance over sampled texels. With --sweep CSV: error against bake time for a
// sweep of target errors, with and without the denoiser, for two texel budgets (docs/charts).
//
//   bench_bake [--scene FILE] [--texels N] [--reference-spp N] [--sweep FILE.csv]
//              [--coarse-denoised-only 1]   (the sweep's 4096-texel denoised line only)
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "atlas/atlas.h"
#include "bake/leak_guard.h"
#include "bake/texel_coverage.h"
#include "pipeline/scene_bake.h"
#include "scene/load.h"
#include "test_geometry.h"
#include "trace/denormals_flushed.h"
#include "trace/path_tracer.h"
#include "trace/sampling.h"

namespace {

using namespace bounce;

double cpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Rate {
  double perWallSecond = 0, perCpuSecond = 0;
};

// Embree's raw rate on this scene: bench_ray_kernel's incoherent surface rays (closest hit),
// all cores, best of 3.
Rate embreeRate(const WorldGeometry& geometry, const RayKernel& kernel, bool occlusion) {
  const std::vector<Ray> rays =
      testing::surfaceRays(geometry, 1 << 18, occlusion ? 2 : 1, occlusion ? 0.5f : 0.0f);
  Rate best;
  for (int rep = 0; rep < 3; ++rep) {
    const double w0 = wallSeconds(), c0 = cpuSeconds();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        const DenormalsFlushed flushed;
                        volatile uint32_t sink = 0;
                        for (std::size_t i = r.begin(); i != r.end(); ++i)
                          sink = occlusion ? kernel.occluded(rays[i])
                                           : kernel.intersect(rays[i]).triangle;
                        (void)sink;
                      });
    const double n = static_cast<double>(rays.size());
    best.perWallSecond = std::max(best.perWallSecond, n / (wallSeconds() - w0));
    best.perCpuSecond = std::max(best.perCpuSecond, n / std::max(cpuSeconds() - c0, 1e-9));
  }
  return best;
}

// Independent reference: E (luminance, W/m²) averaged over each chosen texel's area, from 64
// points of its own pattern (leak-guarded like the bake) and `spp` indirect-only samples.
struct Reference {
  std::vector<std::size_t> texels;
  std::vector<double> value, standardError;
};

Reference reference(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                    const LightmapLayout& layout, int count, int spp) {
  TexelCoverage coverage = buildTexelCoverage(scene, geometry, layout, 64, 0xabcdefu);
  guardAgainstLeaks(scene, geometry, kernel, layout.texelSize, LeakGuardSettings{}, coverage);
  std::vector<std::size_t> valid;
  for (std::size_t t = 0; t < coverage.texelCount(); ++t)
    if (coverage.covered(t)) valid.push_back(t);
  Reference ref;
  const std::size_t stride =
      std::max<std::size_t>(1, valid.size() / static_cast<std::size_t>(count));
  for (std::size_t i = stride / 2; i < valid.size(); i += stride) ref.texels.push_back(valid[i]);
  ref.value.resize(ref.texels.size());
  ref.standardError.resize(ref.texels.size());
  TraceSettings trace;
  trace.paths = PathSet::IndirectOnly;
  const PathTracer tracer(scene, geometry, kernel, trace);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, ref.texels.size(), 1),
      [&](const tbb::blocked_range<std::size_t>& r) {
        const DenormalsFlushed flushed;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          const std::size_t t = ref.texels[i];
          const uint32_t first = coverage.first[t], n = coverage.pointCount(t);
          SobolSampler sampler(0x5eed5u, static_cast<uint32_t>(t));
          double sum = 0, sum2 = 0;
          for (int s = 0; s < spp; ++s) {
            sampler.startSample(static_cast<uint32_t>(s));
            const uint32_t k =
                std::min(n - 1, static_cast<uint32_t>(sampler.get1D() * static_cast<float>(n)));
            const TexelPoint& p = coverage.points[first + k];
            const double e = luminance(tracer.irradiance(p.position, p.shadingNormal, sampler));
            sum += e;
            sum2 += e * e;
          }
          const double mean = sum / spp;
          ref.value[i] = mean;
          ref.standardError[i] = std::sqrt(std::max(0.0, sum2 / spp - mean * mean) / (spp - 1.0));
        }
      });
  return ref;
}

struct Accuracy {
  double meanAbsRelative = 0, rmsRelative = 0, referenceRelative = 0;
  int texels = 0;
};

Accuracy accuracy(const Image& lightmap, const Reference& ref) {
  Accuracy a;
  for (std::size_t i = 0; i < ref.texels.size(); ++i) {
    if (!(ref.value[i] > 0)) continue;
    const double e = luminance(lightmap.pixels[ref.texels[i]]);
    const double rel = (e - ref.value[i]) / ref.value[i];
    a.meanAbsRelative += std::abs(rel);
    a.rmsRelative += rel * rel;
    a.referenceRelative += ref.standardError[i] / ref.value[i];
    ++a.texels;
  }
  if (a.texels > 0) {
    a.meanAbsRelative /= a.texels;
    a.rmsRelative = std::sqrt(a.rmsRelative / a.texels);
    a.referenceRelative /= a.texels;
  }
  return a;
}

// bakeScene's lightmap (bounce-bake's entry point, from the atlas to the filters; no VPLs), with
// its wall and CPU time.
struct Timed {
  Bake bake;
  double wall = 0, cpu = 0;
  const BakeManifest& manifest() const { return bake.manifest; }
  double meanSpp() const {
    const BakeManifest::Atlas& a = bake.manifest.atlas;
    return static_cast<double>(bake.manifest.samples.total) /
           static_cast<double>(a.coveredTexels - a.invalidTexels);
  }
};

Timed timedBake(const Scene& scene, SceneBakeSettings settings) {
  settings.vpls = 0;
  const double w0 = wallSeconds(), c0 = cpuSeconds();
  Timed t{bakeScene(scene, settings).folder, 0, 0};
  t.wall = wallSeconds() - w0;
  t.cpu = cpuSeconds() - c0;
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scenePath = BOUNCE_SOURCE_DIR "/content/cornell_box/cornell_box.gltf";
  std::string sweep;
  int texels = 400, referenceSpp = 8192;
  int coarseOnly = 0;  // --coarse-denoised-only 1: the sweep's 4096-texel denoised line only
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--scene")
      scenePath = argv[i + 1];
    else if (flag == "--sweep")
      sweep = argv[i + 1];
    else if (flag == "--texels")
      texels = std::stoi(argv[i + 1]);
    else if (flag == "--reference-spp")
      referenceSpp = std::stoi(argv[i + 1]);
    else if (flag == "--coarse-denoised-only")
      coarseOnly = std::stoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "bench_bake: unknown option %s\n", argv[i]);
      return 2;
    }
  }
  const Scene scene = loadScene(scenePath);
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const Rate closest = embreeRate(geometry, *kernel, false);
  const Rate occluded = embreeRate(geometry, *kernel, true);

  // The default bake, timed from the atlas on (as bounce-bake runs it, minus loading, writing and
  // the VPLs).
  const SceneBakeSettings defaults;
  const Timed bake = timedBake(scene, defaults);
  const BakeManifest& m = bake.manifest();
  const LightmapLayout& layout = bake.bake.layout;
  const double tracing = m.measured.seconds.leakGuard + m.measured.seconds.irradiance;
  const double traceCpu = bake.cpu * tracing / bake.wall;
  std::printf("scene %s: atlas %dx%d, texel %.4f m (%s), %llu texels\n", scenePath.c_str(),
              layout.width, layout.height, static_cast<double>(layout.texelSize),
              m.atlas.texelRule.c_str(), static_cast<unsigned long long>(m.atlas.coveredTexels));
  std::printf(
      "default bake: %.2f s wall, %.2f s CPU (irradiance %.2f s wall), %.0f spp mean, "
      "estimated error mean %.2f%% p95 %.2f%%\n",
      bake.wall, bake.cpu, m.measured.seconds.irradiance, bake.meanSpp(),
      100.0 * m.estimatedError.mean, 100.0 * m.estimatedError.p95);
  const double bakeRays = static_cast<double>(m.rays.traced);
  std::printf(
      "rays: bake %.2f Mrays/s wall, %.2f Mrays per CPU-second; Embree raw incoherent "
      "closest %.2f / %.2f, occlusion %.2f / %.2f (wall / CPU-second); bake/Embree "
      "closest per CPU-second %.2f\n",
      1e-6 * bakeRays / tracing, 1e-6 * bakeRays / traceCpu, 1e-6 * closest.perWallSecond,
      1e-6 * closest.perCpuSecond, 1e-6 * occluded.perWallSecond, 1e-6 * occluded.perCpuSecond,
      bakeRays / traceCpu / closest.perCpuSecond);
  const Reference ref = reference(scene, geometry, *kernel, layout, texels, referenceSpp);
  const Accuracy acc = accuracy(bake.bake.irradiance, ref);
  std::printf(
      "accuracy over %d texels against %d-spp path-traced irradiance: mean |rel| %.2f%%, "
      "rms %.2f%% (reference's own standard error %.2f%%)\n",
      acc.texels, referenceSpp, 100.0 * acc.meanAbsRelative, 100.0 * acc.rmsRelative,
      100.0 * acc.referenceRelative);

  if (!sweep.empty()) {
    FILE* csv = std::fopen(sweep.c_str(), "w");
    if (csv == nullptr) {
      std::fprintf(stderr, "bench_bake: cannot write %s: %s\n", sweep.c_str(),
                   std::strerror(errno));
      return 1;
    }
    std::fprintf(csv,
                 "texel_budget,texel_size_m,denoise,target_error,wall_s,cpu_s,spp_mean,"
                 "estimated_error,mean_abs_rel_error,rms_rel_error,reference_error\n");
    for (const int budget : {kSmallSceneTexels, kSmallSceneTexels / 4}) {
      if (coarseOnly && budget == kSmallSceneTexels) continue;
      // The atlas is a function of the scene and the budget: the reference's is the bakes'.
      AtlasSettings s;
      s.texelBudget = budget;
      const Atlas a = buildAtlas(scene, s);
      const Reference r = reference(scene, geometry, *kernel, a.layout, texels, referenceSpp);
      for (const bool denoise : {false, true}) {
        if (coarseOnly && !denoise) continue;
        for (const float target : {0.4f, 0.2f, 0.1f, 0.05f, 0.03f}) {
          SceneBakeSettings settings = defaults;
          settings.texelBudget = budget;
          settings.denoise = denoise;
          settings.targetError = target;
          const Timed t = timedBake(scene, settings);
          if (t.bake.layout.width != a.layout.width || t.bake.layout.height != a.layout.height) {
            std::fprintf(stderr, "bench_bake: the bake's atlas is not the reference's\n");
            return 1;
          }
          const Accuracy e = accuracy(t.bake.irradiance, r);
          std::fprintf(csv, "%d,%.5f,%d,%.3f,%.3f,%.3f,%.1f,%.4f,%.4f,%.4f,%.4f\n", budget,
                       static_cast<double>(a.layout.texelSize), denoise ? 1 : 0,
                       static_cast<double>(target), t.wall, t.cpu, t.meanSpp(),
                       t.manifest().estimatedError.mean, e.meanAbsRelative, e.rmsRelative,
                       e.referenceRelative);
          std::fflush(csv);
          std::printf(
              "budget %d denoise %d target %.3f: %.2f s wall %.2f s CPU, mean |rel| %.2f%%\n",
              budget, denoise ? 1 : 0, static_cast<double>(target), t.wall, t.cpu,
              100.0 * e.meanAbsRelative);
          std::fflush(stdout);
        }
      }
    }
    std::fclose(csv);
  }
  return 0;
}
