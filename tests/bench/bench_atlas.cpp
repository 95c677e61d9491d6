// Lightmap atlas build time (baker/atlas): buildAtlas on the Cornell box, the McGuire Cornell
// box with spheres and the conference room (331k triangles), default settings, the scene loaded
// once outside the timing.
//
//   bench_atlas [--benchmark_filter=REGEX] [--benchmark_min_time=SECONDS]
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <string>

#include "atlas/atlas.h"
#include "scene/load.h"

namespace bounce {
namespace {

const Scene& sceneAt(const std::string& path) {
  static std::map<std::string, Scene> loaded;
  auto it = loaded.find(path);
  if (it == loaded.end()) it = loaded.emplace(path, loadScene(path)).first;
  return it->second;
}

void buildAtlasOf(benchmark::State& state, const std::string& path) {
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("no scene at " + path).c_str());
    return;
  }
  const Scene& scene = sceneAt(path);
  Atlas atlas;
  for (auto _ : state) {
    atlas = buildAtlas(scene, AtlasSettings{});
    benchmark::DoNotOptimize(atlas.layout.width);
  }
  state.counters["charts"] = atlas.layout.chartCount;
  state.counters["utilisation"] = atlas.layout.utilisation;
  state.counters["triangles"] = static_cast<double>(scene.triangleCount());
}

BENCHMARK_CAPTURE(buildAtlasOf, cornell_box,
                  std::string(BOUNCE_SOURCE_DIR) + "/content/cornell_box/cornell_box.gltf")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(buildAtlasOf, mcguire_sphere,
                  std::string(BOUNCE_SHARED_SCENES) + "/mcguire_cornell_box/CornellBox-Sphere.obj")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(buildAtlasOf, conference,
                  std::string(BOUNCE_SHARED_SCENES) + "/conference/conference.obj")
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace bounce

BENCHMARK_MAIN();
