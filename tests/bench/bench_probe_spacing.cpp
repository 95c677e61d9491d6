// The irradiance probes' error against their spacing (issue 27): a scene's probe-lit instances
// (those the atlas leaves without a lightmap region) get probe grids at several largest spacings
// h (irradiance_probes.h's clamp), and the baked light the renderer would read at points of their
// surfaces (probes.glsl's weighted trilinear L1 read, replayed here) is compared with the same
// light path traced at those points (BakedLight, the lightmap's own estimator, many samples).
//
// Usage: bench_probe_spacing [SCENE] [--points N] [--spp M] [--spacing H ...]
// Prints one CSV row per spacing: spacing_m, probes, sampled, seconds, rel_rms, rel_rms_noise,
// mean_rel, median_rel, bias_rel. rel_rms is sqrt(Σ(a − b)² / Σ b²) over the points (luminance,
// W/m²), with the reference's own noise (Σ σ_b²) taken out; mean_rel and median_rel are of
// |a − b| / (b + 0.01·b̄). The points are uniform over the probe-lit surfaces, hidden ones too
// (a seat's underside against its frame, where probes in the air over-light a contact shadow):
// a frame weighs what it shows.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "atlas/atlas.h"
#include "bake/baked_light.h"
#include "bake/irradiance_probes.h"
#include "bake_folder/irradiance_probes.h"
#include "ray/ray_kernel.h"
#include "scene/load.h"
#include "scene/static_scene.h"
#include "scene/world_geometry.h"
#include "trace/rng.h"
#include "trace/sampling.h"
#include "trace/sobol_sampler.h"

namespace bounce {
namespace {

struct SurfaceSample {
  glm::vec3 position, normal;
  double reference = 0.0, referenceVariance = 0.0;  // luminance E (W/m²) and its mean's variance
};

// E read as probes.glsl reads it (weighted trilinear over the cell's 8 probes at p + m·n).
glm::vec3 probeRead(const IrradianceProbes& probes, const ProbeGrid& g, glm::vec3 p, glm::vec3 n) {
  const glm::vec3 q = p + g.normalOffset * n;
  const glm::vec3 top = glm::vec3(g.counts) - 1.0f;
  const glm::vec3 c = glm::clamp((q - g.origin) / g.spacing, glm::vec3(0.0f), top);
  const glm::uvec3 base = glm::min(glm::uvec3(c), g.counts - 2u);
  const glm::vec3 f = c - glm::vec3(base);
  glm::vec3 sum(0.0f);
  float weights = 0.0f;
  for (uint32_t i = 0; i < 8; ++i) {
    const glm::uvec3 corner(i & 1u, (i >> 1) & 1u, i >> 2);
    const glm::uvec3 cell = base + corner;
    const glm::vec3 along = glm::mix(1.0f - f, f, glm::vec3(corner));
    const glm::vec3 toProbe = g.position(cell) - p;
    const float facing = glm::dot(toProbe, toProbe) > 0.0f
                             ? 0.5f * (glm::dot(glm::normalize(toProbe), n) + 1.0f)
                             : 1.0f;
    const float w = along.x * along.y * along.z * (facing * facing + 0.05f);
    const uint32_t index = g.first + cell.x + g.counts.x * (cell.y + g.counts.y * cell.z);
    sum += w * glm::max(probeIrradianceAt(probes.probes[index], n), glm::vec3(0.0f));
    weights += w;
  }
  return weights > 0.0f ? sum / weights : glm::vec3(0.0f);
}

int run(int argc, char** argv) {
  std::string path = std::string(BOUNCE_SOURCE_DIR) + "/content/conference/conference_panels.json";
  int pointCount = 400, spp = 4096;
  std::vector<float> spacings;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--points" && i + 1 < argc)
      pointCount = std::atoi(argv[++i]);
    else if (a == "--spp" && i + 1 < argc)
      spp = std::atoi(argv[++i]);
    else if (a == "--spacing" && i + 1 < argc)
      spacings.push_back(std::strtof(argv[++i], nullptr));
    else if (a[0] != '-')
      path = a;
    else {
      std::fprintf(stderr,
                   "usage: bench_probe_spacing [SCENE] [--points N] [--spp M] "
                   "[--spacing H ...]\n");
      return 2;
    }
  }
  if (spacings.empty()) spacings = {0.15f, 0.25f, 0.4f, 0.6f, 1.0f};
  const Scene scene = loadScene(path);
  const Atlas atlas = buildAtlas(scene, AtlasSettings{});
  const Scene statics = staticScene(scene);
  const WorldGeometry geometry = flatten(statics);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const std::vector<uint32_t> traced = staticInstanceNumbers(scene);
  std::vector<ProbedInstance> instances;
  for (uint32_t i = 0; i < scene.instances.size(); ++i)
    if (traced[i] != kNotStatic &&
        std::binary_search(atlas.vplLitInstances.begin(), atlas.vplLitInstances.end(), i))
      instances.push_back({.fileIndex = i, .tracedIndex = traced[i]});
  // Points by area over the probe-lit triangles, on their front side.
  std::vector<uint32_t> triangles, owner;  // world triangle, its instance's slot
  std::vector<double> cumulative;
  double area = 0.0;
  for (uint32_t t = 0; t < geometry.triangleCount(); ++t)
    for (std::size_t k = 0; k < instances.size(); ++k)
      if (geometry.triangleInstance[t] == instances[k].tracedIndex) {
        const double a = 0.5 * glm::length(geometry.triangleCross(t));
        if (!(a > 0.0) || !std::isfinite(a)) break;
        area += a;
        triangles.push_back(t);
        owner.push_back(static_cast<uint32_t>(k));
        cumulative.push_back(area);
        break;
      }
  if (triangles.empty()) {
    std::fprintf(stderr, "bench_probe_spacing: %s has no probe-lit instance\n", path.c_str());
    return 1;
  }
  std::vector<SurfaceSample> points;
  std::vector<uint32_t> pointOwner;
  TraceSettings trace;
  const BakedLight light(statics, geometry, *kernel, trace);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < pointCount; ++i) {
    const auto key = static_cast<uint32_t>(i);
    const double u = uniformFloat(hashKeys(7, key, 0), 0) * area;
    const std::size_t at = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin(),
        triangles.size() - 1);
    const uint32_t t = triangles[at];
    float b1 = uniformFloat(hashKeys(7, key, 1), 0), b2 = uniformFloat(hashKeys(7, key, 2), 0);
    if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
    const glm::uvec3 tri = geometry.triangles[t];
    SurfaceSample s;
    s.position = (1.0f - b1 - b2) * geometry.positions[tri.x] + b1 * geometry.positions[tri.y] +
                 b2 * geometry.positions[tri.z];
    const glm::vec3 ng = glm::normalize(geometry.triangleCross(t));
    glm::vec3 n = (1.0f - b1 - b2) * geometry.normals[tri.x] + b1 * geometry.normals[tri.y] +
                  b2 * geometry.normals[tri.z];
    n = glm::length(n) > 0.0f ? glm::normalize(n) : ng;
    s.normal = glm::dot(n, ng) > 0.0f ? n : ng;
    const glm::vec3 origin = s.position + 1e-4f * ng;
    double sum = 0.0, sum2 = 0.0;
    SobolSampler sampler(0x5eed, 0x40000000u + key);
    for (int k = 0; k < spp; ++k) {
      sampler.startSample(static_cast<uint32_t>(k));
      sampler.setDimension(1);
      const double e = luminance(light.sample(origin, s.normal, sampler).irradiance);
      sum += e;
      sum2 += e * e;
    }
    s.reference = sum / spp;
    s.referenceVariance = std::max(0.0, sum2 / spp - s.reference * s.reference) / (spp - 1);
    points.push_back(s);
    pointOwner.push_back(owner[at]);
  }
  const double referenceSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double meanReference = 0.0;
  for (const SurfaceSample& s : points) meanReference += s.reference / points.size();
  std::fprintf(stderr,
               "bench_probe_spacing: %s: %zu probe-lit instances, %zu triangles, %.2f m^2; "
               "%d points x %d samples in %.1f s, mean E %.4g W/m^2\n",
               path.c_str(), instances.size(), triangles.size(), area, pointCount, spp,
               referenceSeconds, meanReference);
  std::printf(
      "spacing_m,probes,sampled,seconds,rel_rms,rel_rms_noise,mean_rel,median_rel,bias_rel\n");
  for (const float h : spacings) {
    ProbeSettings settings;
    settings.maxSpacing = h;
    const ProbeBake bake = bakeIrradianceProbes(statics, geometry, *kernel, instances, settings);
    // Grid of each instance slot (grids follow the instances with triangles, in order).
    std::vector<const ProbeGrid*> gridOf(instances.size(), nullptr);
    for (const ProbeGrid& g : bake.probes.grids)
      for (std::size_t k = 0; k < instances.size(); ++k)
        if (instances[k].fileIndex == g.instance) gridOf[k] = &g;
    double d2 = 0.0, b2 = 0.0, noise = 0.0, rel = 0.0, bias = 0.0, sumB = 0.0;
    std::vector<double> relative;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const ProbeGrid* g = gridOf[pointOwner[i]];
      const double a =
          g ? luminance(probeRead(bake.probes, *g, points[i].position, points[i].normal)) : 0.0;
      const double b = points[i].reference;
      d2 += (a - b) * (a - b);
      b2 += b * b;
      noise += points[i].referenceVariance;
      rel += std::abs(a - b) / (b + 0.01 * meanReference);
      relative.push_back(std::abs(a - b) / (b + 0.01 * meanReference));
      bias += a - b;
      sumB += b;
    }
    std::sort(relative.begin(), relative.end());
    const double median = relative[relative.size() / 2];
    uint64_t sampled = 0;
    for (const uint32_t n : bake.samples) sampled += n > 0 ? 1 : 0;
    std::printf("%.3f,%zu,%llu,%.2f,%.5f,%.5f,%.5f,%.5f,%.5f\n", h, bake.probes.probes.size(),
                static_cast<unsigned long long>(sampled), bake.seconds,
                std::sqrt(std::max(0.0, d2 - noise) / b2), std::sqrt(noise / b2),
                rel / static_cast<double>(points.size()), median, bias / sumB);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace bounce

int main(int argc, char** argv) {
  return bounce::run(argc, argv);
}
