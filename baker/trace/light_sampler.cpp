#include "trace/light_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "trace/sampling.h"

namespace bounce {

float boundingSphereRadius(const WorldGeometry& geometry) {
  glm::vec3 lo(std::numeric_limits<float>::max());
  glm::vec3 hi(-std::numeric_limits<float>::max());
  bool any = false;
  for (const glm::vec3& p : geometry.positions) {
    if (!isFinite(p)) continue;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    any = true;
  }
  return any ? 0.5f * glm::length(hi - lo) : 0.0f;
}

float LightSampler::punctualPower(const Light& light, float sceneRadius) {
  float power = 0.0f;
  switch (light.type) {
    case LightType::Point:
      if (!isFinite(light.position)) return 0.0f;
      power = 4.0f * kPi * luminance(light.intensity);
      break;
    case LightType::Spot: {
      if (!isFinite(light.position) || !(glm::length(light.direction) > 0.0f)) return 0.0f;
      const float cosOuter = std::cos(std::clamp(light.outerConeAngle, 0.0f, kPi));
      power = 2.0f * kPi * (1.0f - cosOuter) * luminance(light.intensity);
      break;
    }
    case LightType::Directional: {
      const float len = glm::length(light.direction);
      if (!(len > 0.0f) || !std::isfinite(len)) return 0.0f;
      power = luminance(light.irradiance) * kPi * sceneRadius * sceneRadius;
      break;
    }
  }
  return power > 0.0f && std::isfinite(power) ? power : 0.0f;
}

LightSampler::LightSampler(const Scene& scene, const WorldGeometry& geometry,
                           const EmitterTable& emitters, std::span<const Vpl> vpls)
    : sceneRadius_(boundingSphereRadius(geometry)) {
  std::vector<double> weights;
  const auto add = [&](LightKind kind, uint32_t index, double weight) {
    if (!(weight > 0.0) || !std::isfinite(weight)) return;
    entries_.push_back({kind, index});
    weights.push_back(weight);
  };
  if (!emitters.empty()) add(LightKind::Area, 0, luminance(emitters.power()));
  for (uint32_t i = 0; i < scene.lights.size(); ++i) {
    add(LightKind::Punctual, i, punctualPower(scene.lights[i], sceneRadius_));
  }
  for (uint32_t i = 0; i < vpls.size(); ++i) {
    const Vpl& v = vpls[i];
    if (!isFinite(v.position) || !isFinite(v.normal)) continue;
    add(LightKind::Virtual, i, luminance(v.flux));
  }
  double total = 0.0;
  for (double w : weights) total += w;
  if (!(total > 0.0) || !std::isfinite(total)) {
    entries_.clear();
    return;
  }
  cdf_.reserve(weights.size() + 1);
  cdf_.push_back(0.0);
  double running = 0.0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    running += weights[i];
    pmf_.push_back(static_cast<float>(weights[i] / total));
    cdf_.push_back(i + 1 == weights.size() ? 1.0 : running / total);
    if (entries_[i].kind == LightKind::Area) areaPmf_ = pmf_.back();
  }
}

LightPick LightSampler::pick(float u) const {
  // The first entry whose upper CDF bound exceeds u; zero-width entries are never chosen.
  const auto it = std::upper_bound(cdf_.begin() + 1, cdf_.end(), static_cast<double>(u));
  const std::size_t i =
      std::min(static_cast<std::size_t>(it - (cdf_.begin() + 1)), entries_.size() - 1);
  LightPick p;
  p.kind = entries_[i].kind;
  p.index = entries_[i].index;
  p.pmf = pmf_[i];
  const double width = cdf_[i + 1] - cdf_[i];
  const double r = width > 0.0 ? (static_cast<double>(u) - cdf_[i]) / width : 0.0;
  p.remapped = std::clamp(static_cast<float>(r), 0.0f, 0x1.fffffep-1f);
  return p;
}

}  // namespace bounce
