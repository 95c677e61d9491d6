#include "bake/light_visibility_bake.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "trace/denormals_flushed.h"
#include "trace/rng.h"
#include "trace/sampling.h"
#include "trace/sobol_sampler.h"  // reverseBits: the base-2 radical inverse

namespace bounce {
namespace {

constexpr uint32_t kVisibilitySalt = 0x5bd1e995u;

struct LightEstimate {
  uint16_t light = 0;
  double irradiance = 0.0;  // unshadowed, luminance, W/m² (up to the common factor)
  double visible = 1.0;     // V
};

}  // namespace

BakedVisibility bakeLightVisibility(const AreaLightSet& lights, const RayKernel& kernel,
                                    const TexelCoverage& coverage,
                                    const VisibilityBakeSettings& settings,
                                    VisibilityBakeReport& report) {
  BakedVisibility out;
  out.width = coverage.width;
  out.height = coverage.height;
  out.lightCount = static_cast<uint32_t>(lights.staticCount());
  out.texels.assign(coverage.texelCount(), TexelVisibility{});
  report = {};
  report.lights = out.lightCount;
  const int samples = std::max(settings.samplesPerLight, 1);
  std::atomic<uint64_t> rays{0}, reached{0}, over{0};
  std::vector<double> otherShare(coverage.texelCount(), 0.0), total(coverage.texelCount(), 0.0);
  const auto start = std::chrono::steady_clock::now();
  StageProgress* progress = settings.progress;

  auto bakeTexel = [&](std::size_t texel) {
    const uint32_t begin = coverage.first[texel];
    const uint32_t points = coverage.first[texel + 1] - begin;
    if (points == 0 || out.lightCount == 0) return;
    std::vector<LightEstimate> estimates;
    uint64_t texelRays = 0;
    for (uint32_t l = 0; l < out.lightCount; ++l) {
      const AreaLight& light = lights.lights[l];
      if (light.bakeDirect) continue;  // in the lightmap: the renderer never draws it live
      const uint32_t key =
          hashKeys(settings.seed ^ kVisibilitySalt, static_cast<uint32_t>(texel), l);
      const glm::vec2 rotation(uniformFloat(key, 0), uniformFloat(key, 1));
      double sumW = 0.0, sumVisible = 0.0;
      for (int k = 0; k < samples; ++k) {
        const TexelPoint& x = coverage.points[begin + static_cast<uint32_t>(k) % points];
        glm::vec2 u((static_cast<float>(k) + rotation.x) / static_cast<float>(samples),
                    unitFloat(reverseBits(static_cast<uint32_t>(k))) + rotation.y);
        u.y -= std::floor(u.y);
        const glm::vec3 y = pointOnLight(lights, l, u);
        const glm::vec3 d = y - x.position;
        const float r2 = glm::dot(d, d);
        if (!(r2 > 0.0f)) continue;
        const float cosX = glm::dot(x.shadingNormal, d);
        float cosY = -glm::dot(light.normal, d);
        if (light.doubleSided || light.normal == glm::vec3(0.0f)) cosY = std::abs(cosY);
        if (cosX <= 0.0f || cosY <= 0.0f) continue;
        const double w = static_cast<double>(cosX) * cosY / (static_cast<double>(r2) * r2);
        Ray ray;
        ray.origin = offsetRayOrigin(x.position, x.geometricNormal, d);
        ray.direction = y - ray.origin;
        ray.tmax = 1.0f - 1e-4f;  // stop short of the light's own surface
        ++texelRays;
        sumW += w;
        if (!kernel.occluded(ray)) sumVisible += w;
      }
      if (sumW <= 0.0) continue;
      // E = L·A·mean(cosθ_x·cosθ_y/r²) for points y uniform over the light's area A.
      const double e =
          luminance(lights.triangles[light.first].radiance) * light.area * sumW / samples;
      estimates.push_back({static_cast<uint16_t>(l), e, sumVisible / sumW});
    }
    rays += texelRays;
    if (estimates.empty()) return;
    ++reached;
    std::stable_sort(
        estimates.begin(), estimates.end(),
        [](const LightEstimate& a, const LightEstimate& b) { return a.irradiance > b.irradiance; });
    TexelVisibility& record = out.texels[texel];
    const std::size_t named =
        estimates.size() <= kVisibilitySlots ? estimates.size() : kVisibilitySlots - 1;
    for (std::size_t s = 0; s < named; ++s) {
      record.light[s] = estimates[s].light;
      record.visible[s] = static_cast<float>(estimates[s].visible);
    }
    double all = 0.0;
    for (const LightEstimate& e : estimates) all += e.irradiance;
    total[texel] = all;
    if (named < estimates.size()) {
      ++over;
      double rest = 0.0, restVisible = 0.0;
      for (std::size_t s = named; s < estimates.size(); ++s) {
        rest += estimates[s].irradiance;
        restVisible += estimates[s].irradiance * estimates[s].visible;
      }
      record.light[kVisibilitySlots - 1] = kOtherLights;
      record.visible[kVisibilitySlots - 1] =
          static_cast<float>(std::clamp(restVisible / rest, 0.0, 1.0));
      otherShare[texel] = rest;
    }
  };

  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, coverage.height, 1),
                      [&](const tbb::blocked_range<int>& range) {
                        const DenormalsFlushed flushed;
                        for (int y = range.begin(); y != range.end(); ++y) {
                          if (progress && progress->cancelled()) return;
                          for (int x = 0; x < coverage.width; ++x)
                            bakeTexel(static_cast<std::size_t>(y) * coverage.width + x);
                          if (progress) progress->advance(1);
                        }
                      });
  });
  if (progress) progress->throwIfCancelled();
  report.rays = rays;
  report.texelsWithLight = reached;
  report.texelsOverSlots = over;
  const double all = std::accumulate(total.begin(), total.end(), 0.0);
  report.otherLightsShare =
      all > 0.0 ? std::accumulate(otherShare.begin(), otherShare.end(), 0.0) / all : 0.0;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void fillVisibility(BakedVisibility& visibility, std::vector<uint8_t> filled,
                    const std::vector<uint32_t>* labels) {
  const int w = visibility.width, h = visibility.height;
  const int offsets[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  for (const bool sameLabel : {true, false}) {
    if (sameLabel && !labels) continue;
    for (;;) {
      std::vector<std::pair<std::size_t, std::size_t>> copies;  // (to, from)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const std::size_t t = static_cast<std::size_t>(y) * w + x;
          if (filled[t]) continue;
          for (const auto& o : offsets) {
            const int nx = x + o[0], ny = y + o[1];
            if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
            const std::size_t n = static_cast<std::size_t>(ny) * w + nx;
            if (!filled[n] || (sameLabel && (*labels)[n] != (*labels)[t])) continue;
            copies.emplace_back(t, n);
            break;
          }
        }
      if (copies.empty()) break;
      for (const auto& [to, from] : copies) {
        visibility.texels[to] = visibility.texels[from];
        filled[to] = 1;
      }
    }
  }
}

}  // namespace bounce
