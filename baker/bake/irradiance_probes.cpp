#include "bake/irradiance_probes.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "bake/baked_light.h"
#include "bake/texel_irradiance.h"   // kIrradianceBatch, kMinAdaptiveSpp, zeroSamplesToStop
#include "bake_folder/probe_file.h"  // kMaxProbeGridCount
#include "trace/sampling.h"
#include "trace/sobol_sampler.h"

namespace bounce {
namespace {

constexpr uint32_t kDimNormal = 0;  // then baked_light.h's dimensions

// Uniform direction on the unit sphere (pdf 1/(4π)).
glm::vec3 uniformSphere(glm::vec2 u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Direction i of a spherical Fibonacci set of n: nearly even over the sphere, fixed.
glm::vec3 fibonacciSphere(int i, int n) {
  const float golden = 2.39996322972865332f;  // π(3 − √5)
  const float z = 1.0f - (2.0f * static_cast<float>(i) + 1.0f) / static_cast<float>(n);
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = golden * static_cast<float>(i);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

struct InstanceBox {
  glm::vec3 lower{std::numeric_limits<float>::max()};
  glm::vec3 upper{std::numeric_limits<float>::lowest()};
  bool empty() const { return lower.x > upper.x; }
};

// Whether the point sees mostly back faces of single-sided triangles: inside a closed mesh, or
// behind a wall (as leak_guard.h judges a texel's point). Counts its rays in `rays`.
bool insideGeometry(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                    glm::vec3 p, uint64_t& rays) {
  int back = 0;
  for (int i = 0; i < kProbeTestRays; ++i) {
    Ray ray;
    ray.origin = p;
    ray.direction = fibonacciSphere(i, kProbeTestRays);
    ++rays;
    const Hit hit = kernel.intersect(ray);
    if (!hit.valid()) continue;
    const uint32_t material = geometry.triangleMaterial[hit.triangle];
    if (material < scene.materials.size() && scene.materials[material].doubleSided) continue;
    if (glm::dot(ray.direction, hit.geometricNormal) > 0.0f) ++back;
  }
  return static_cast<float>(back) >= kProbeInsideFraction * static_cast<float>(kProbeTestRays);
}

struct ProbeEstimate {
  ProbeIrradiance irradiance;
  uint32_t samples = 0, nonFinite = 0;
  float relativeError = 0.0f;
};

ProbeEstimate estimateProbe(const BakedLight& light, glm::vec3 position, uint32_t pattern,
                            const ProbeSettings& settings) {
  SobolSampler sampler(settings.seed, pattern);
  const int maxSpp = std::max(settings.maxSpp, 1);
  const bool adaptive = settings.targetError > 0.0f;
  const uint32_t zerosToStop = adaptive ? zeroSamplesToStop(settings.targetError, maxSpp) : maxSpp;
  const auto zerosToGiveUp = static_cast<uint32_t>(std::max(maxSpp / 4, 1));
  ShProjection projection;
  std::array<double, 4> mean{}, m2{};  // Welford on the luminance of each coefficient's samples
  ProbeEstimate out;
  uint32_t n = 0, reachedSurface = 0;
  while (n < static_cast<uint32_t>(maxSpp)) {
    const uint32_t batchEnd = std::min<uint32_t>(n + kIrradianceBatch, maxSpp);
    for (; n < batchEnd; ++n) {
      sampler.startSample(n);
      sampler.setDimension(kDimNormal);
      const glm::vec3 normal = uniformSphere(sampler.get2D());
      const BakedLight::Sample s = light.sample(position, normal, sampler);
      out.nonFinite += s.nonFinite;
      reachedSurface += s.reachedSurface ? 1 : 0;
      projection.add(normal, s.irradiance);
      // The luminance of each coefficient's sample 4π·Y(n)·E(n), for the error estimate.
      const std::array<float, 4> y = shBasisL1(normal);
      const double yE = luminance(s.irradiance);
      for (int k = 0; k < 4; ++k) {
        const double x = 4.0 * static_cast<double>(kPi) * y[k] * yE, delta = x - mean[k];
        mean[k] += delta / static_cast<double>(n + 1);
        m2[k] += delta * (x - mean[k]);
      }
    }
    const auto deviation = [&](int k) {
      return n > 1 ? std::sqrt(m2[k] / static_cast<double>(n - 1)) : 0.0;
    };
    const double l1 = std::sqrt(deviation(1) * deviation(1) + deviation(2) * deviation(2) +
                                deviation(3) * deviation(3));
    const double errorOfE =
        (kShY00 * deviation(0) + kShY1 * l1) / std::sqrt(static_cast<double>(n));
    const double meanE = kShY00 * mean[0];
    const double scale = std::max(meanE, settings.errorFloor);
    out.relativeError = meanE > 0.0 ? static_cast<float>(errorOfE / scale) : 0.0f;
    if (adaptive && n >= kMinAdaptiveSpp && meanE > 0.0 && out.relativeError < settings.targetError)
      break;
    if (adaptive && mean[0] == 0.0 && n >= kMinAdaptiveSpp &&
        (reachedSurface >= zerosToStop || n >= zerosToGiveUp))
      break;
  }
  out.samples = n;
  out.irradiance = projection.mean();
  return out;
}

}  // namespace

void ShProjection::add(glm::vec3 normal, glm::vec3 irradiance) {
  // 4π·Y(n)·E(n): the projection's integrand over the pdf 1/(4π).
  const std::array<float, 4> y = shBasisL1(normal);
  for (int k = 0; k < 4; ++k)
    sum_[k] += 4.0 * static_cast<double>(kPi) * y[k] * glm::dvec3(irradiance);
  ++samples_;
}

ProbeIrradiance ShProjection::mean() const {
  ProbeIrradiance p;
  if (samples_ == 0) return p;
  for (int k = 0; k < 4; ++k) p.sh[k] = glm::vec3(sum_[k] / static_cast<double>(samples_));
  return p;
}

namespace {

// Per instance (in `instances` order), its triangles.
std::vector<std::vector<uint32_t>> instanceTriangles(const WorldGeometry& geometry,
                                                     std::span<const ProbedInstance> instances) {
  uint32_t most = 0;
  for (const ProbedInstance& p : instances) most = std::max(most, p.tracedIndex + 1);
  std::vector<int64_t> slot(most, -1);
  for (std::size_t i = 0; i < instances.size(); ++i)
    slot[instances[i].tracedIndex] = static_cast<int64_t>(i);
  std::vector<std::vector<uint32_t>> triangles(instances.size());
  for (std::size_t t = 0; t < geometry.triangleCount(); ++t) {
    const uint32_t instance = geometry.triangleInstance[t];
    if (instance < most && slot[instance] >= 0)
      triangles[static_cast<std::size_t>(slot[instance])].push_back(static_cast<uint32_t>(t));
  }
  return triangles;
}

InstanceBox triangleBox(const WorldGeometry& geometry, uint32_t t) {
  InstanceBox box;
  for (int c = 0; c < 3; ++c) {
    const glm::vec3 p = geometry.positions[geometry.triangles[t][c]];
    box.lower = glm::min(box.lower, p);
    box.upper = glm::max(box.upper, p);
  }
  return box;
}

uint32_t probeIndex(const ProbeGrid& g, glm::uvec3 cell) {
  return g.first + cell.x + g.counts.x * (cell.y + g.counts.y * cell.z);
}

// Invalid needed probes take, ring by ring, the 1/d²-weighted mean of their 26 neighbours that
// hold a value (valid, or filled in an earlier ring). Returns the probes left without one.
uint64_t fillInvalid(const std::vector<ProbeGrid>& grids, const std::vector<uint8_t>& invalid,
                     const std::vector<uint8_t>& needed, std::vector<ProbeIrradiance>& probes) {
  std::vector<uint8_t> known(probes.size(), 0);
  for (std::size_t i = 0; i < probes.size(); ++i) known[i] = needed[i] && !invalid[i];
  uint64_t left = 0;
  for (const ProbeGrid& g : grids) {
    std::vector<glm::uvec3> todo;
    for (uint32_t z = 0; z < g.counts.z; ++z)
      for (uint32_t y = 0; y < g.counts.y; ++y)
        for (uint32_t x = 0; x < g.counts.x; ++x)
          if (invalid[probeIndex(g, {x, y, z})]) todo.push_back({x, y, z});
    while (!todo.empty()) {
      std::vector<std::pair<uint32_t, ProbeIrradiance>> ring;
      std::vector<glm::uvec3> rest;
      for (const glm::uvec3 c : todo) {
        std::array<glm::dvec3, 4> sum{};
        double weights = 0.0;
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const glm::ivec3 n = glm::ivec3(c) + glm::ivec3(dx, dy, dz);
              if (glm::any(glm::lessThan(n, glm::ivec3(0))) ||
                  glm::any(glm::greaterThanEqual(n, glm::ivec3(g.counts))))
                continue;
              const uint32_t j = probeIndex(g, glm::uvec3(n));
              if (!known[j]) continue;
              const glm::vec3 d = glm::vec3(dx, dy, dz) * g.spacing;
              const double w = 1.0 / static_cast<double>(glm::dot(d, d));
              for (int k = 0; k < 4; ++k) sum[k] += w * glm::dvec3(probes[j].sh[k]);
              weights += w;
            }
        if (weights == 0.0) {
          rest.push_back(c);
          continue;
        }
        ProbeIrradiance p;
        for (int k = 0; k < 4; ++k) p.sh[k] = glm::vec3(sum[k] / weights);
        ring.emplace_back(probeIndex(g, c), p);
      }
      if (ring.empty()) {
        left += rest.size();
        break;
      }
      for (const auto& [index, value] : ring) {
        probes[index] = value;
        known[index] = 1;
      }
      todo = std::move(rest);
    }
  }
  return left;
}

}  // namespace

std::vector<ProbeGrid> placeProbeGrids(const WorldGeometry& geometry,
                                       std::span<const ProbedInstance> instances,
                                       float maxSpacing) {
  const std::vector<std::vector<uint32_t>> triangles = instanceTriangles(geometry, instances);
  std::vector<ProbeGrid> grids;
  uint32_t first = 0;
  for (std::size_t i = 0; i < instances.size(); ++i) {
    InstanceBox box;
    for (const uint32_t t : triangles[i]) {
      const InstanceBox b = triangleBox(geometry, t);
      box.lower = glm::min(box.lower, b.lower);
      box.upper = glm::max(box.upper, b.upper);
    }
    if (box.empty()) continue;
    const glm::vec3 extent = box.upper - box.lower;
    const float longest = std::max(extent.x, std::max(extent.y, extent.z));
    const float h =
        std::clamp(0.5f * longest, kMinProbeSpacing, std::max(maxSpacing, kMinProbeSpacing));
    const float margin = std::max(0.25f * h, kMinProbeMargin);
    ProbeGrid grid;
    grid.instance = instances[i].fileIndex;
    grid.first = first;
    grid.origin = box.lower - glm::vec3(margin);
    grid.normalOffset = margin;
    for (int a = 0; a < 3; ++a) {
      const float span = extent[a] + 2.0f * margin;
      const auto count = static_cast<uint32_t>(std::lround(span / h)) + 1u;
      grid.counts[a] = std::clamp(count, 2u, kMaxProbeGridCount);
      grid.spacing[a] = span / static_cast<float>(grid.counts[a] - 1);
    }
    first += grid.probeCount();
    grids.push_back(grid);
  }
  return grids;
}

std::vector<uint8_t> neededProbes(const WorldGeometry& geometry,
                                  std::span<const ProbedInstance> instances,
                                  std::span<const ProbeGrid> grids) {
  const std::vector<std::vector<uint32_t>> triangles = instanceTriangles(geometry, instances);
  uint32_t total = 0;
  for (const ProbeGrid& g : grids) total += g.probeCount();
  std::vector<uint8_t> needed(total, 0);
  std::size_t next = 0;  // grids follow the instances that have triangles, in order
  for (std::size_t i = 0; i < instances.size() && next < grids.size(); ++i) {
    if (triangles[i].empty()) continue;
    const ProbeGrid& g = grids[next++];
    const glm::ivec3 top = glm::ivec3(g.counts) - 2;  // the last cell's lower corner
    for (const uint32_t t : triangles[i]) {
      const InstanceBox b = triangleBox(geometry, t);
      // The cells the shader can look in from this triangle: p + m·n for p on it.
      const glm::vec3 lo = (b.lower - glm::vec3(g.normalOffset) - g.origin) / g.spacing;
      const glm::vec3 hi = (b.upper + glm::vec3(g.normalOffset) - g.origin) / g.spacing;
      const glm::ivec3 c0 = glm::clamp(glm::ivec3(glm::floor(lo)), glm::ivec3(0), top);
      const glm::ivec3 c1 = glm::clamp(glm::ivec3(glm::floor(hi)), glm::ivec3(0), top);
      for (int z = c0.z; z <= c1.z + 1; ++z)
        for (int y = c0.y; y <= c1.y + 1; ++y)
          for (int x = c0.x; x <= c1.x + 1; ++x) needed[probeIndex(g, glm::uvec3(x, y, z))] = 1;
    }
  }
  return needed;
}

ProbeBake bakeIrradianceProbes(const Scene& scene, const WorldGeometry& geometry,
                               const RayKernel& kernel, std::span<const ProbedInstance> instances,
                               const ProbeSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  ProbeBake out;
  out.probes.grids = placeProbeGrids(geometry, instances, settings.maxSpacing);
  out.needed = neededProbes(geometry, instances, out.probes.grids);
  std::vector<glm::vec3> positions;
  for (const ProbeGrid& g : out.probes.grids)
    for (uint32_t z = 0; z < g.counts.z; ++z)
      for (uint32_t y = 0; y < g.counts.y; ++y)
        for (uint32_t x = 0; x < g.counts.x; ++x) positions.push_back(g.position({x, y, z}));
  const std::size_t count = positions.size();
  out.probes.probes.assign(count, ProbeIrradiance{});
  out.samples.assign(count, 0);
  out.relativeError.assign(count, 0.0f);
  out.invalid.assign(count, 0);
  std::vector<uint64_t> rays(count, 0), nonFinite(count, 0);

  TraceSettings trace;
  trace.maxDepth = settings.maxDepth;
  trace.seed = settings.seed;
  trace.lightChoice = settings.lightChoice;
  const BakedLight light(scene, geometry, kernel, trace, {settings.cache, settings.cache});
  StageProgress* progress = settings.progress;
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
      if (progress && progress->cancelled()) return;
      if (!out.needed[i]) {
        // Left 0: no surface reads it.
      } else if (insideGeometry(scene, geometry, kernel, positions[i], rays[i])) {
        out.invalid[i] = 1;
      } else {
        const ProbeEstimate e =
            estimateProbe(light, positions[i], kProbePatterns + static_cast<uint32_t>(i), settings);
        out.probes.probes[i] = e.irradiance;
        out.samples[i] = e.samples;
        out.relativeError[i] = e.relativeError;
        nonFinite[i] = e.nonFinite;
      }
      if (progress) progress->advance(1, out.samples[i]);
    });
  });
  if (progress) progress->throwIfCancelled();

  out.unfilled = fillInvalid(out.probes.grids, out.invalid, out.needed, out.probes.probes);
  for (std::size_t i = 0; i < count; ++i) {
    out.totalSamples += out.samples[i];
    out.rays += rays[i];
    out.nonFiniteSamples += nonFinite[i];
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace bounce
