// What the renderer pays each time a dynamic instance moves, side by side in one run, for
// content/cornell_box_dynamic with the sphere at its glTF place (cap 4096 and 16384 VPLs, error
// target off):
//   vplAliveMask  cutting the bake's light paths (VPLs of its static scene) at the sphere
//                 (vpl_runtime/vpl_occlusion.h, --dynamic-vpls cut);
//   vplRetrace    tracing the light paths again with the sphere in place: the scene flattened,
//                 an Embree kernel built, the paths traced (vpl/vpl_retrace.h, --dynamic-vpls
//                 retrace, the default), on one thread and on all.
// The sphere's triangle count is printed. Run by hand:
//   build/release/bin/bench_vpl_occlusion
#include <benchmark/benchmark.h>

#include <map>

#include "ray/ray_kernel.h"
#include "scene/load.h"
#include "scene/static_scene.h"
#include "vpl/vpl_generate.h"
#include "vpl/vpl_retrace.h"
#include "vpl_runtime/vpl_occlusion.h"

namespace {

struct Setup {
  bounce::Scene scene =
      bounce::loadScene(BOUNCE_SOURCE_DIR "/content/cornell_box_dynamic/cornell_box_dynamic.gltf");
  std::map<int, std::vector<bounce::Vpl>> vpls;  // by cap

  const std::vector<bounce::Vpl>& set(int cap) {
    auto found = vpls.find(cap);
    if (found != vpls.end()) return found->second;
    const bounce::Scene statics = bounce::staticScene(scene);
    const bounce::WorldGeometry geometry = bounce::flatten(statics);
    const auto kernel = bounce::makeRayKernel(geometry, bounce::RayBackend::Bvh);
    bounce::VplSettings settings;
    settings.maxVpls = cap;
    settings.relativeError = 0.0f;
    return vpls.emplace(cap, bounce::generateVpls(statics, geometry, *kernel, settings).vpls)
        .first->second;
  }
};

Setup& setup() {
  static Setup s;
  return s;
}

void vplAliveMask(benchmark::State& state) {
  Setup& s = setup();
  const std::vector<bounce::Vpl>& vpls = s.set(static_cast<int>(state.range(0)));
  const std::vector<bounce::VplOccluder> occluders = bounce::dynamicVplOccluders(s.scene);
  std::size_t alive = 0;
  for (auto _ : state) {
    const std::vector<uint8_t> mask = bounce::vplAliveMask(vpls, occluders);
    alive = 0;
    for (const uint8_t a : mask) alive += a;
    benchmark::DoNotOptimize(alive);
  }
  state.counters["vpls"] = static_cast<double>(vpls.size());
  state.counters["alive"] = static_cast<double>(alive);
  state.counters["triangles"] =
      occluders.empty() ? 0.0 : static_cast<double>(occluders.front().corners.size() / 3);
}
BENCHMARK(vplAliveMask)->Arg(4096)->Arg(16384)->Unit(benchmark::kMillisecond);

// Args: cap, threads (0: all cores).
void vplRetrace(benchmark::State& state) {
  Setup& s = setup();
  bounce::VplSettings settings;
  settings.maxVpls = static_cast<int>(state.range(0));
  settings.relativeError = 0.0f;
  settings.threads = static_cast<int>(state.range(1));
  bounce::PlacedVplTracer tracer(s.scene, settings);
  std::vector<glm::mat4> transforms;
  for (const bounce::Instance& instance : s.scene.instances)
    transforms.push_back(instance.transform);
  std::size_t count = 0;
  for (auto _ : state) {
    count = tracer.trace(transforms).size();
    benchmark::DoNotOptimize(count);
  }
  state.counters["vpls"] = static_cast<double>(count);
}
BENCHMARK(vplRetrace)
    ->Args({4096, 1})
    ->Args({16384, 1})
    ->Args({4096, 0})
    ->Args({16384, 0})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
