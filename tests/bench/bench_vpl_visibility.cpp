// bench_vpl_visibility: what VPL visibility buys, GL-free (docs/vpl_measurements.md "Visibility").
// At receivers on a scene's floor, the indirect irradiance of a baked VPL set (bake_folder/vpl.h,
// clamped as baker/vpl/vpl_gather.h) with
//   exact   V = a ray between the receiver and every VPL (vpl_gather.h with the ray kernel),
//   none    V = 1 (what the renderer draws without VPL shadows),
//   groups  V = the visibility of the VPL's group, exact rays from one point of the group: the
//           renderer's K groups (vpl_runtime/vpl_groups.h), seen from the centroid or from the
//           member nearest it (what K shadow cubes give at best; the maps' own error is tested in
//           tests/render/vpl_shadow_test.cpp),
//   parts   V = the visibility of the VPL's part of its group, exact rays from the part's cube
//           origin (the renderer's cubes: vplShadowCubes, render/vpl_shadow_maps.h),
// against PathTracer::irradiance with PathSet::IndirectOnly (the same light: reflected at least
// once). Receivers are grouped by region: floor in the shadow of the blocks (the light's
// centre occluded), floor behind the tall block, open floor.
//
//   bench_vpl_visibility --scene content/cornell_box/cornell_box.gltf
//                        --vpls build/release/content/cornell_box/cornell_box.bake/vpls
//                        [--samples 4096] [--grid 0.02] [--groups 64] [--maps RESOLUTION]
//
// --maps: also "group V (maps)" and "parts V (maps)": the same visibility read from
// VplShadowMaps cubes of that resolution at each group's nearest member, and at each part's
// origin (what the renderer draws) (OSMesa, through VplVisibilityProbe), and the time to render
// all the maps of each arrangement.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "bake_folder/vpl_file.h"
#include "gl/context.h"
#include "gl/draw_state.h"
#include "render/gpu_scene.h"
#include "render/vpl_shadow_maps.h"
#include "render/vpl_visibility_probe.h"
#include "scene/load.h"
#include "trace/path_tracer.h"
#include "trace/sampling.h"
#include "vpl/vpl_gather.h"
#include "vpl_group_visibility.h"

namespace {

using namespace bounce;

struct Receiver {
  glm::vec3 position{0.0f}, normal{0.0f, 1.0f, 0.0f};
  int region = 0;  // 0 blocks' shadow, 1 behind the tall block, 2 open floor
  double exact = 0, none = 0, groups = 0, groupsMember = 0, groupsMap = 0, parts = 0, partsMap = 0,
         traced = 0, tracedVariance = 0;  // luminance, W/m²
};

const char* kRegionNames[3] = {"floor in the blocks' shadow", "floor behind the tall block",
                               "floor lit directly"};

}  // namespace

int main(int argc, char** argv) {
  std::string scenePath, vplPath;
  int samples = 4096, groupCount = 64, mapResolution = 0;
  float grid = 0.02f;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--scene" && hasValue)
      scenePath = argv[++i];
    else if (a == "--vpls" && hasValue)
      vplPath = argv[++i];
    else if (a == "--samples" && hasValue)
      samples = std::stoi(argv[++i]);
    else if (a == "--grid" && hasValue)
      grid = std::stof(argv[++i]);
    else if (a == "--groups" && hasValue)
      groupCount = std::stoi(argv[++i]);
    else if (a == "--maps" && hasValue)
      mapResolution = std::stoi(argv[++i]);
    else {
      std::fprintf(stderr,
                   "usage: bench_vpl_visibility --scene FILE --vpls FILE [--samples N] "
                   "[--grid METRES] [--groups K] [--maps RESOLUTION]\n");
      return a == "--help" ? 0 : 2;
    }
  }
  if (scenePath.empty() || vplPath.empty()) {
    std::fprintf(stderr, "bench_vpl_visibility: --scene and --vpls are required\n");
    return 2;
  }
  const Scene scene = loadScene(scenePath);
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const std::vector<Vpl> vpls = readVplFile(vplPath);
  const float r = vplClampDistance(surfaceArea(geometry), vpls.size());
  const test::VplGroupsCpu groups = test::groupVplsCpu(vpls, static_cast<std::size_t>(groupCount));
  const std::vector<Vpl>& reps = groups.representatives;
  const std::vector<Vpl>& nearestMember = groups.origins;
  std::vector<float> nearestDistance;
  for (std::size_t g = 0; g < reps.size(); ++g)
    nearestDistance.push_back(glm::length(nearestMember[g].position - reps[g].position));
  int inside = 0;
  for (std::size_t g = 0; g < reps.size(); ++g) inside += nearestDistance[g] > 0.02f ? 1 : 0;
  std::fprintf(stderr, "%d representatives lie more than 2 cm from every member\n", inside);

  // The floor (y = lowest) of the scene's box.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : geometry.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  TraceSettings settings;
  settings.paths = PathSet::IndirectOnly;
  const PathTracer tracer(scene, geometry, *kernel, settings);
  // The Cornell box's light hangs at the centre of the ceiling.
  const glm::vec3 lightCentre(0.5f * (lo.x + hi.x), hi.y - 1e-3f, 0.5f * (lo.z + hi.z));

  std::vector<Receiver> receivers;
  const glm::vec3 up(0, 1, 0);
  for (float x = lo.x + 0.5f * grid; x < hi.x; x += grid)
    for (float z = lo.z + 0.5f * grid; z < hi.z; z += grid) {
      Receiver rc;
      rc.position = {x, lo.y, z};
      // On the floor and not under a block: the floor is the first hit looking down.
      Ray down;
      down.origin = rc.position + glm::vec3(0.0f, 0.9f * (hi.y - lo.y), 0.0f);
      down.direction = -up;
      const Hit hit = kernel->intersect(down);
      if (!hit.valid() || std::abs(hit.t - 0.9f * (hi.y - lo.y)) > 1e-4f) continue;
      const bool lit = test::segmentVisible(*kernel, rc.position, up, lightCentre, -up);
      const bool behindTall = x > 0.40f && z > 0.40f;  // between the tall block and the walls
      rc.region = behindTall ? 1 : (lit ? 2 : 0);
      receivers.push_back(rc);
    }
  std::fprintf(stderr, "%zu VPLs, clamp r = %.4f m, %zu representatives, %zu receivers\n",
               vpls.size(), r, reps.size(), receivers.size());

  // Visibility from the shadow maps: mapVisible[g][i] for receiver i and cube g, cubes at the
  // groups' nearest members; partVisible the same with cubes at the parts' origins.
  std::vector<std::vector<float>> mapVisible, partVisible;
  std::unique_ptr<gl::Context> context;
  if (mapResolution > 0) {
    context = gl::createOSMesaContext();
    context->makeCurrent();
    std::vector<std::string> warnings;
    const GpuScene gpu(scene, warnings);
    std::vector<glm::vec3> positions, normals;
    for (const Receiver& rc : receivers) {
      positions.push_back(rc.position);
      normals.push_back(rc.normal);
    }
    const auto readMaps = [&](const std::vector<Vpl>& origins) {
      VplShadowSettings mapSettings;
      mapSettings.resolution = mapResolution;
      VplShadowMaps maps(mapSettings, gl::shaderDirectory());
      maps.setRepresentatives(origins);
      constexpr int kRuns = 5;
      double seconds = 0.0;
      ShadowDrawCount drawn;
      for (int run = 0; run < kRuns; ++run) {
        maps.setEnabled(false);
        maps.setEnabled(true);  // forces a redraw
        const auto start = std::chrono::steady_clock::now();
        drawn = maps.render(gpu);
        gl::finish();
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
      std::fprintf(stderr, "%zu maps of 6 x %d^2: %d faces, %d caster draws, %.1f ms per redraw\n",
                   origins.size(), mapResolution, drawn.views, drawn.casters,
                   1e3 * seconds / kRuns);
      VplVisibilityProbe probe(gl::shaderDirectory());
      std::vector<std::vector<float>> visible;
      for (std::size_t g = 0; g < origins.size(); ++g)
        visible.push_back(probe.read(maps, static_cast<int>(g), positions, normals));
      return visible;
    };
    mapVisible = readMaps(nearestMember);
    partVisible = readMaps(groups.cubes);
  }

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, receivers.size(), 4), [&](auto range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      Receiver& rc = receivers[i];
      rc.exact = luminance(
          glm::vec3(gatherVplIrradiance(vpls, rc.position, rc.normal, kernel.get(), r).irradiance));
      rc.none = luminance(
          glm::vec3(gatherVplIrradiance(vpls, rc.position, rc.normal, nullptr, r).irradiance));
      std::vector<float> repVisible(reps.size()), memberVisible(reps.size());
      for (std::size_t g = 0; g < reps.size(); ++g) {
        repVisible[g] =
            test::segmentVisible(*kernel, reps[g].position, reps[g].normal, rc.position, rc.normal)
                ? 1.0f
                : 0.0f;
        memberVisible[g] = test::segmentVisible(*kernel, nearestMember[g].position,
                                                nearestMember[g].normal, rc.position, rc.normal)
                               ? 1.0f
                               : 0.0f;
      }
      auto gather = [&](std::span<const float> visibility) {
        return luminance(glm::vec3(
            test::groupGather(groups.vpls, groups.group, visibility, rc.position, rc.normal, r)));
      };
      rc.groups = gather(repVisible);
      rc.groupsMember = gather(memberVisible);
      std::vector<float> partRays(groups.cubes.size());
      for (std::size_t c = 0; c < groups.cubes.size(); ++c)
        partRays[c] = test::segmentVisible(*kernel, groups.cubes[c].position,
                                           groups.cubes[c].normal, rc.position, rc.normal)
                          ? 1.0f
                          : 0.0f;
      const auto gatherParts = [&](std::span<const float> visibility) {
        return luminance(glm::vec3(
            test::groupGather(groups.vpls, groups.cube, visibility, rc.position, rc.normal, r)));
      };
      rc.parts = gatherParts(partRays);
      if (!mapVisible.empty()) {
        std::vector<float> fromMaps, fromPartMaps;
        for (std::size_t g = 0; g < reps.size(); ++g) fromMaps.push_back(mapVisible[g][i]);
        for (std::size_t c = 0; c < groups.cubes.size(); ++c)
          fromPartMaps.push_back(partVisible[c][i]);
        rc.groupsMap = gather(fromMaps);
        rc.partsMap = gatherParts(fromPartMaps);
      }
      SobolSampler sampler(7u, static_cast<uint32_t>(i));
      double mean = 0, m2 = 0;
      for (int s = 0; s < samples; ++s) {
        sampler.startSample(static_cast<uint32_t>(s));
        sampler.setDimension(1);
        const double value = luminance(tracer.irradiance(rc.position, rc.normal, sampler));
        const double delta = value - mean;
        mean += delta / (s + 1);
        m2 += delta * (value - mean);
      }
      rc.traced = mean;
      rc.tracedVariance = samples > 1 ? m2 / (samples - 1) / samples : 0.0;  // of the mean
    }
  });

  // Per region and estimator: mean E (luminance, W/m²), its bias against the tracer's mean, and
  // the RMS of the per-receiver relative error with the tracer's own noise subtracted.
  struct Column {
    const char* name;
    double Receiver::*value;
  };
  std::vector<Column> columns = {{"exact V", &Receiver::exact},
                                 {"group V, centroid", &Receiver::groups},
                                 {"group V, nearest member", &Receiver::groupsMember}};
  if (!mapVisible.empty()) columns.push_back({"group V, maps", &Receiver::groupsMap});
  columns.push_back({"part V, nearest member", &Receiver::parts});
  if (!partVisible.empty()) columns.push_back({"part V, maps", &Receiver::partsMap});
  columns.push_back({"no V", &Receiver::none});
  std::printf("| region | receivers | path tracer E (rel. SE) |");
  for (const Column& c : columns) std::printf(" %s: E, bias, RMS |", c.name);
  std::printf("\n");
  for (int region = 0; region < 3; ++region) {
    double n = 0, traced = 0, se2 = 0;
    std::vector<double> sum(columns.size(), 0.0), err(columns.size(), 0.0);
    for (const Receiver& rc : receivers) {
      if (rc.region != region || !(rc.traced > 0)) continue;
      n += 1;
      traced += rc.traced;
      const double t2 = rc.traced * rc.traced;
      se2 += rc.tracedVariance / t2;
      for (std::size_t k = 0; k < columns.size(); ++k) {
        const double v = rc.*columns[k].value;
        sum[k] += v;
        err[k] += (v - rc.traced) * (v - rc.traced) / t2;
      }
    }
    if (n == 0) continue;
    std::printf("| %s | %.0f | %.4f (%.1f%%) |", kRegionNames[region], n, traced / n,
                100 * std::sqrt(se2 / n));
    for (std::size_t k = 0; k < columns.size(); ++k)
      std::printf(" %.4f, %+.1f%%, %.1f%% |", sum[k] / n, 100 * (sum[k] / traced - 1),
                  100 * std::sqrt(std::max(0.0, (err[k] - se2) / n)));
    std::printf("\n");
  }
  return 0;
}
