#include "bake/light_visibility_bake.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include <tbb/task_arena.h>

#include "bake/texel_coverage.h"
#include "ray/ray_kernel.h"
#include "scene/light_falloff.h"
#include "trace/rng.h"
#include "trace/sampling.h"
#include "trace/sobol_sampler.h"  // reverseBits: the base-2 radical inverse
#include "trace/stage_progress.h"

namespace bounce {
namespace {

constexpr uint32_t kVisibilitySalt = 0x5bd1e995u;

struct LightEstimate {
  uint16_t light = 0;
  double irradiance = 0.0;  // unshadowed, luminance, W/m² (up to the common factor)
  double visible = 1.0;     // V
};

}  // namespace

bool hasBakeableVisibility(const AreaLightSet& lights, std::span<const Light> punctual) {
  if (lights.staticCount() > 0) return true;
  return std::any_of(punctual.begin(), punctual.end(), [](const Light& light) {
    return light.mobility == Mobility::Static && !light.bakeDirect;
  });
}

PointSetVisibility estimatePointSetVisibility(const AreaLightSet& lights,
                                              std::span<const Light> punctual,
                                              const RayKernel& kernel,
                                              std::span<const TexelPoint> points, uint32_t salt,
                                              uint32_t seed, uint32_t index, int samplesPerLight) {
  PointSetVisibility result;
  const auto points32 = static_cast<uint32_t>(points.size());
  const auto lightCount = static_cast<uint32_t>(lights.staticCount());
  if (points.empty()) return result;
  const int samples = std::max(samplesPerLight, 1);
  std::vector<LightEstimate> estimates;
  uint64_t rays = 0;
  for (uint32_t l = 0; l < lightCount; ++l) {
    const AreaLight& light = lights.lights[l];
    if (light.bakeDirect) continue;  // in the lightmap: the renderer never draws it live
    const uint32_t key = hashKeys(seed ^ salt, index, l);
    const glm::vec2 rotation(uniformFloat(key, 0), uniformFloat(key, 1));
    double sumW = 0.0, sumVisible = 0.0;
    for (int k = 0; k < samples; ++k) {
      const TexelPoint& x = points[static_cast<uint32_t>(k) % points32];
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
      ++rays;
      sumW += w;
      if (!kernel.occluded(ray)) sumVisible += w;
    }
    if (sumW <= 0.0) continue;
    // E = L·A·mean(cosθ_x·cosθ_y/r²) for points y uniform over the light's area A.
    const double e =
        luminance(lights.triangles[light.first].radiance) * light.area * sumW / samples;
    estimates.push_back({static_cast<uint16_t>(l), e, sumVisible / sumW});
  }
  const uint32_t pairs = std::min(static_cast<uint32_t>(samples), points32);
  for (std::size_t p = 0; p < punctual.size(); ++p) {
    const Light& light = punctual[p];
    if (light.mobility == Mobility::Dynamic || light.bakeDirect) continue;
    const bool directional = light.type == LightType::Directional;
    double sumW = 0.0, sumVisible = 0.0;
    for (uint32_t k = 0; k < pairs; ++k) {
      const TexelPoint& x = points[k];
      // d: towards the light; for a point or spot light its length is the distance r.
      const glm::vec3 d = directional ? -light.direction : light.position - x.position;
      const float r2 = glm::dot(d, d);
      if (!(r2 > 0.0f)) continue;
      const float cosX = glm::dot(x.shadingNormal, d) / std::sqrt(r2);
      if (cosX <= 0.0f) continue;
      double w = cosX;
      if (!directional) {
        w /= r2;
        if (light.type == LightType::Spot)
          w *= spotFalloff(light, glm::dot(-d, light.direction) / std::sqrt(r2));
      }
      if (w <= 0.0) continue;
      Ray ray;
      ray.origin = offsetRayOrigin(x.position, x.geometricNormal, d);
      if (directional) {
        ray.direction = d;  // unbounded: anything above the texel hides the sun
      } else {
        ray.direction = light.position - ray.origin;
        ray.tmax = 1.0f - 1e-4f;
      }
      ++rays;
      sumW += w;
      if (!kernel.occluded(ray)) sumVisible += w;
    }
    if (sumW <= 0.0) continue;
    const glm::vec3 power = directional ? light.irradiance : light.intensity;
    const double e = luminance(power) * sumW / pairs;
    if (!(e > 0.0)) continue;
    estimates.push_back({static_cast<uint16_t>(lightCount + p), e, sumVisible / sumW});
  }
  result.rays = static_cast<uint32_t>(rays);
  if (estimates.empty()) return result;
  std::stable_sort(
      estimates.begin(), estimates.end(),
      [](const LightEstimate& a, const LightEstimate& b) { return a.irradiance > b.irradiance; });
  TexelVisibility& record = result.record;
  const std::size_t named =
      estimates.size() <= kVisibilitySlots ? estimates.size() : kVisibilitySlots - 1;
  for (std::size_t s = 0; s < named; ++s) {
    record.light[s] = estimates[s].light;
    record.visible[s] = static_cast<float>(estimates[s].visible);
  }
  for (const LightEstimate& e : estimates) result.irradiance += e.irradiance;
  if (named < estimates.size()) {
    double rest = 0.0, restVisible = 0.0;
    for (std::size_t s = named; s < estimates.size(); ++s) {
      rest += estimates[s].irradiance;
      restVisible += estimates[s].irradiance * estimates[s].visible;
    }
    record.light[kVisibilitySlots - 1] = kOtherLights;
    record.visible[kVisibilitySlots - 1] =
        static_cast<float>(std::clamp(restVisible / rest, 0.0, 1.0));
    result.otherIrradiance = rest;
  }
  return result;
}

VisibilityTexels bakeVisibilityTexels(const AreaLightSet& lights, std::span<const Light> punctual,
                                      const RayKernel& kernel, const TexelCoverage& coverage,
                                      const VisibilityBakeSettings& settings) {
  VisibilityTexels result;
  BakedVisibility& out = result.map;
  out.width = coverage.width;
  out.height = coverage.height;
  out.lightCount = static_cast<uint32_t>(lights.staticCount());
  out.punctualCount = static_cast<uint32_t>(punctual.size());
  if (out.indexCount() > kOtherLights - 1u)
    throw std::invalid_argument(std::to_string(out.lightCount) + " static area lights and " +
                                std::to_string(out.punctualCount) +
                                " punctual lights: baked visibility can name at most 65533");
  out.texels.assign(coverage.texelCount(), TexelVisibility{});
  result.rays.assign(coverage.texelCount(), 0);
  result.irradiance.assign(coverage.texelCount(), 0.0);
  result.otherIrradiance.assign(coverage.texelCount(), 0.0);
  const int samples = std::max(settings.samplesPerLight, 1);
  StageProgress* progress = settings.progress;

  auto bakeTexel = [&](std::size_t texel) {
    const uint32_t begin = coverage.first[texel];
    const uint32_t points = coverage.first[texel + 1] - begin;
    if (points == 0 || out.indexCount() == 0) return;
    const PointSetVisibility v = estimatePointSetVisibility(
        lights, punctual, kernel, std::span(coverage.points).subspan(begin, points),
        kVisibilitySalt, settings.seed, static_cast<uint32_t>(texel), samples);
    result.rays[texel] = v.rays;
    out.texels[texel] = v.record;
    result.irradiance[texel] = v.irradiance;
    result.otherIrradiance[texel] = v.otherIrradiance;
  };

  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    forEachTileRow(
        settings.work, coverage.width, coverage.height,
        [&](int y, int x0, int x1) {
          for (int x = x0; x < x1; ++x) bakeTexel(static_cast<std::size_t>(y) * coverage.width + x);
          if (progress) progress->advance(1);
        },
        [&](uint32_t tile) {
          if (settings.tileDone) settings.tileDone(tile, result);
        },
        [&] { return progress && progress->cancelled(); });
  });
  if (progress) progress->throwIfCancelled();
  return result;
}

VisibilityBakeReport summariseVisibility(const VisibilityTexels& texels) {
  VisibilityBakeReport report;
  report.lights = texels.map.lightCount;
  report.punctualLights = texels.map.punctualCount;
  for (const uint32_t r : texels.rays) report.rays += r;
  for (const TexelVisibility& record : texels.map.texels) {
    report.texelsWithLight += record.light[0] != kNoLight ? 1 : 0;
    report.texelsOverSlots += record.light[kVisibilitySlots - 1] == kOtherLights ? 1 : 0;
  }
  const double all = std::accumulate(texels.irradiance.begin(), texels.irradiance.end(), 0.0);
  report.otherLightsShare =
      all > 0.0
          ? std::accumulate(texels.otherIrradiance.begin(), texels.otherIrradiance.end(), 0.0) / all
          : 0.0;
  return report;
}

BakedVisibility bakeLightVisibility(const AreaLightSet& lights, std::span<const Light> punctual,
                                    const RayKernel& kernel, const TexelCoverage& coverage,
                                    const VisibilityBakeSettings& settings,
                                    VisibilityBakeReport& report) {
  const auto start = std::chrono::steady_clock::now();
  VisibilityTexels texels = bakeVisibilityTexels(lights, punctual, kernel, coverage, settings);
  report = summariseVisibility(texels);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::move(texels.map);
}

void fillVisibility(BakedVisibility& visibility, std::vector<uint8_t> filled,
                    const std::vector<uint32_t>* labels) {
  const int w = visibility.width, h = visibility.height;
  const int offsets[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  for (const bool sameLabel : {true, false}) {
    if (sameLabel && !labels) continue;
    if (!sameLabel && labels) {
      TexelVisibility dark;
      dark.light[0] = kOtherLights;
      dark.visible[0] = 0.0f;
      for (std::size_t t = 0; t < filled.size(); ++t)
        if (!filled[t] && (*labels)[t] != 0) {
          visibility.texels[t] = dark;
          filled[t] = 1;
        }
    }
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
