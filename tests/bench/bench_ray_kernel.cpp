// Ray-kernel throughput: rays per second of both backends on the Cornell box and on a
// ≥ 1M-triangle scene built here, for closest hit and occlusion, coherent (camera) and
// incoherent (cosine rays from random surface points) rays, on 1 and 2 threads. After the
// runs it prints our BVH's throughput as a ratio of Embree's, and the build times of both
// backends for the large scene.
//
//   bench_ray_kernel [--benchmark_filter=REGEX] [--benchmark_min_time=SECONDS]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ray/ray_kernel.h"
#include "scene/load.h"
#include "test_geometry.h"

namespace bounce {
namespace {

constexpr std::size_t kIncoherentRays = 1 << 18;
constexpr int kImageWidth = 384, kImageHeight = 256;

struct BenchScene {
  WorldGeometry geometry;
  std::vector<Ray> coherent, incoherent, shadow;  // shadow: incoherent with finite tmax
  std::unique_ptr<RayKernel> kernels[2];          // indexed by RayBackend
  double buildSeconds[2] = {0, 0};
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void prepare(BenchScene& s, glm::vec3 eye, glm::vec3 target, float shadowDistance) {
  s.coherent = testing::cameraRays(eye, target, kImageWidth, kImageHeight);
  s.incoherent = testing::surfaceRays(s.geometry, kIncoherentRays, 1);
  s.shadow = testing::surfaceRays(s.geometry, kIncoherentRays, 2, shadowDistance);
  for (const RayBackend backend : {RayBackend::Embree, RayBackend::Bvh}) {
    const auto start = std::chrono::steady_clock::now();
    s.kernels[static_cast<int>(backend)] = makeRayKernel(s.geometry, backend);
    s.buildSeconds[static_cast<int>(backend)] = secondsSince(start);
  }
}

// The Cornell box from content/, seen by its own camera.
const BenchScene& cornellBox() {
  static const std::unique_ptr<BenchScene> scene = [] {
    auto s = std::make_unique<BenchScene>();
    const Scene loaded = loadScene(BOUNCE_SOURCE_DIR "/content/cornell_box/cornell_box.gltf");
    s->geometry = flatten(loaded);
    const Camera camera = loaded.cameras.empty() ? Camera{} : loaded.cameras[0];
    prepare(*s, camera.position(), camera.position() + camera.forward(), 1.0f);
    return s;
  }();
  return *scene;
}

// A field of 4×4 bumpy spheres of 65k triangles each on a ground plane, in a room-sized
// bounds of 50 m: 16 × 65,280 + 2 = 1,044,482 triangles.
const BenchScene& millionTriangles() {
  static const std::unique_ptr<BenchScene> scene = [] {
    auto s = std::make_unique<BenchScene>();
    for (int i = 0; i < 16; ++i) {
      const glm::vec3 centre(-15.0f + 10.0f * static_cast<float>(i % 4), 4.0f,
                             -15.0f + 10.0f * static_cast<float>(i / 4));
      testing::addDisplacedSphere(s->geometry, 256, 128, centre, 4.0f, 0.15f,
                                  static_cast<uint32_t>(i));
    }
    const auto base = static_cast<uint32_t>(s->geometry.positions.size());
    for (const glm::vec3 p : {glm::vec3(-25, 0, -25), glm::vec3(25, 0, -25), glm::vec3(25, 0, 25),
                              glm::vec3(-25, 0, 25)})
      s->geometry.positions.push_back(p);
    s->geometry.triangles.push_back({base, base + 2, base + 1});
    s->geometry.triangles.push_back({base, base + 3, base + 2});
    testing::finish(s->geometry);
    prepare(*s, {0, 18, 32}, {0, 2, 0}, 10.0f);
    return s;
  }();
  return *scene;
}

enum class Query { ClosestHit, Occlusion };
enum class Rays { Coherent, Incoherent };

// Each thread traces its own contiguous share of the ray set, round after round.
void traceRays(benchmark::State& state, const BenchScene& (*sceneOf)(), RayBackend backend,
               Query query, Rays kind) {
  const BenchScene& scene = sceneOf();
  const RayKernel& kernel = *scene.kernels[static_cast<int>(backend)];
  const std::vector<Ray>& all = kind == Rays::Coherent      ? scene.coherent
                                : query == Query::Occlusion ? scene.shadow
                                                            : scene.incoherent;
  const std::size_t share = all.size() / static_cast<std::size_t>(state.threads());
  const std::span<const Ray> rays(
      all.data() + share * static_cast<std::size_t>(state.thread_index()), share);
  std::size_t hits = 0;
  for (auto _ : state) {
    for (const Ray& ray : rays)
      hits += query == Query::ClosestHit ? kernel.intersect(ray).valid() : kernel.occluded(ray);
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * rays.size()));
  state.counters["hit_fraction"] =
      static_cast<double>(hits) / static_cast<double>(state.iterations() * rays.size());
}

// Embree's batched form (8-wide packets), single thread, for comparison with single rays.
void traceBatches(benchmark::State& state, const BenchScene& (*sceneOf)(), Query query, Rays kind) {
  const BenchScene& scene = sceneOf();
  const RayKernel& kernel = *scene.kernels[static_cast<int>(RayBackend::Embree)];
  const std::vector<Ray>& rays = kind == Rays::Coherent      ? scene.coherent
                                 : query == Query::Occlusion ? scene.shadow
                                                             : scene.incoherent;
  std::vector<Hit> hits(rays.size());
  std::vector<uint8_t> occluded(rays.size());
  for (auto _ : state) {
    if (query == Query::ClosestHit)
      kernel.intersect(rays, hits);
    else
      kernel.occluded(rays, occluded);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * rays.size()));
}

// Records the rays per second of each benchmark, by process CPU time (what the kernel costs,
// robust on a shared machine) and by wall time, so the BVH/Embree ratios can be printed at
// the end. With --benchmark_repetitions the best run is kept: on a shared machine, the best of
// several is the least disturbed.
struct Rate {
  double perCpuSecond = 0.0, perWallSecond = 0.0;
};

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      const auto it = run.counters.find("items_per_second");
      if (run.run_type != Run::RT_Iteration || it == run.counters.end()) continue;
      // items_per_second is items / process CPU time (MeasureProcessCPUTime).
      const double rays = it->second.value * run.cpu_accumulated_time;
      Rate& best = rates[run.benchmark_name()];
      best.perCpuSecond = std::max(best.perCpuSecond, it->second.value);
      best.perWallSecond = std::max(best.perWallSecond, rays / run.real_accumulated_time);
    }
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, Rate> rates;
};

void registerAll() {
  using SceneFn = const BenchScene& (*)();
  const std::pair<const char*, SceneFn> scenes[] = {{"cornell", cornellBox},
                                                    {"million", millionTriangles}};
  for (const auto& [sceneName, sceneFn] : scenes)
    for (const Query query : {Query::ClosestHit, Query::Occlusion})
      for (const Rays kind : {Rays::Coherent, Rays::Incoherent}) {
        const std::string stem = std::string(query == Query::ClosestHit ? "closest" : "occluded") +
                                 "/" + sceneName + "/" +
                                 (kind == Rays::Coherent ? "coherent" : "incoherent");
        for (const RayBackend backend : {RayBackend::Embree, RayBackend::Bvh})
          benchmark::RegisterBenchmark(
              (stem + "/" + (backend == RayBackend::Embree ? "embree" : "bvh")).c_str(), traceRays,
              sceneFn, backend, query, kind)
              ->Threads(1)
              ->Threads(2)
              ->MeasureProcessCPUTime()
              ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark((stem + "/embree_packets").c_str(), traceBatches, sceneFn,
                                     query, kind)
            ->MeasureProcessCPUTime()
            ->Unit(benchmark::kMillisecond);
      }
}

void printSummary(const RatioReporter& reporter) {
  std::printf("\nMrays/s per CPU-second of the process (per wall-second in brackets)\n");
  std::printf("%-28s %7s %20s %20s %10s\n", "query/scene/rays", "threads", "embree", "bvh",
              "bvh/embree");
  for (const auto& [name, embree] : reporter.rates) {
    const auto at = name.find("/embree/");
    if (at == std::string::npos) continue;
    const std::string bvhName = name.substr(0, at) + "/bvh/" + name.substr(at + 8);
    const auto found = reporter.rates.find(bvhName);
    if (found == reporter.rates.end()) continue;
    const Rate& bvh = found->second;
    const std::string threads = name.substr(name.rfind(':') + 1);
    std::printf("%-28s %7s %9.2f (%8.2f) %9.2f (%8.2f) %10.2f\n", name.substr(0, at).c_str(),
                threads.c_str(), embree.perCpuSecond / 1e6, embree.perWallSecond / 1e6,
                bvh.perCpuSecond / 1e6, bvh.perWallSecond / 1e6,
                bvh.perCpuSecond / embree.perCpuSecond);
  }
}

}  // namespace
}  // namespace bounce

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  bounce::registerAll();
  bounce::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  bounce::printSummary(reporter);
  // Build times are known only for scenes a selected benchmark used; ask for the large one
  // only then (building it takes seconds).
  bool millionUsed = false;
  for (const auto& [name, rate] : reporter.rates)
    millionUsed = millionUsed || name.find("/million/") != std::string::npos;
  if (millionUsed) {
    const auto& s = bounce::millionTriangles();
    std::printf("\nbuild, %zu triangles: embree %.3f s, bvh %.3f s\n", s.geometry.triangleCount(),
                s.buildSeconds[0], s.buildSeconds[1]);
  }
  benchmark::Shutdown();
  return 0;
}
