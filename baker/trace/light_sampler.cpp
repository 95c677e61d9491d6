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
  if (vpls.empty()) addNearby(scene, emitters);
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

void LightSampler::addNearby(const Scene& scene, const EmitterTable& emitters) {
  for (uint32_t c = 0; c < emitters.clusters().size(); ++c) {
    const EmitterCluster& cluster = emitters.clusters()[c];
    Nearby n;
    n.kind = LightKind::Area;
    n.index = c;
    n.type = LightType::Point;
    n.position = cluster.centre;
    n.direction = glm::vec3(0.0f);
    n.radius = cluster.radius;
    n.power = static_cast<float>(cluster.power);
    n.intensity = static_cast<float>(cluster.power / kPi);
    if (n.power > 0.0f && std::isfinite(n.power) && isFinite(n.position)) nearby_.push_back(n);
  }
  for (uint32_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    const float power = punctualPower(light, sceneRadius_);
    if (!(power > 0.0f)) continue;
    Nearby n;
    n.kind = LightKind::Punctual;
    n.index = i;
    n.type = light.type;
    n.position = light.position;
    const float len = glm::length(light.direction);
    n.direction = len > 0.0f ? light.direction / len : glm::vec3(0.0f);
    n.power = power;
    if (light.type == LightType::Directional) {
      n.intensity = luminance(light.irradiance);
    } else {
      n.intensity = luminance(light.intensity);
    }
    if (light.type == LightType::Spot) {
      n.cosOuter = std::cos(std::clamp(light.outerConeAngle, 0.0f, kPi));
    }
    nearby_.push_back(n);
  }
  if (nearby_.size() > kMaxNearbyLights) nearby_.clear();
}

void LightSampler::nearbyWeights(glm::vec3 position, glm::vec3 normal, float* w, float& weightSum,
                                 float& powerSum) const {
  constexpr float kMinDistance2 = 1e-4f;  // (1 cm)², m²
  weightSum = 0.0f;
  powerSum = 0.0f;
  for (std::size_t i = 0; i < nearby_.size(); ++i) {
    const Nearby& n = nearby_[i];
    float weight = 0.0f;
    if (n.kind == LightKind::Punctual && n.type == LightType::Directional) {
      if (glm::dot(normal, -n.direction) > 0.0f) weight = n.intensity;
    } else {
      const glm::vec3 toLight = n.position - position;
      const float dist2 = glm::dot(toLight, toLight);
      // Below the plane: every point of the light (the cluster's sphere) has n·(x − p) ≤ 0.
      bool reaches = glm::dot(normal, toLight) > -n.radius;
      if (n.kind == LightKind::Punctual && n.type == LightType::Spot) {
        reaches = reaches && dist2 > 0.0f &&
                  glm::dot(n.direction, -toLight) > n.cosOuter * std::sqrt(dist2);
      }
      if (reaches) weight = n.intensity / std::max({dist2, n.radius * n.radius, kMinDistance2});
    }
    if (!(weight > 0.0f) || !std::isfinite(weight)) weight = 0.0f;
    w[i] = weight;
    if (weight > 0.0f) {
      weightSum += weight;
      powerSum += n.power;
    }
  }
}

float LightSampler::nearbyPmf(std::size_t i, const float* w, float weightSum,
                              float powerSum) const {
  if (!(w[i] > 0.0f) || !(weightSum > 0.0f) || !std::isfinite(weightSum)) return 0.0f;
  return (1.0f - kPowerShare) * (w[i] / weightSum) + kPowerShare * (nearby_[i].power / powerSum);
}

LightPick LightSampler::pickAt(float u, glm::vec3 position, glm::vec3 normal) const {
  if (nearby_.empty()) return pick(u);
  float w[kMaxNearbyLights];
  float weightSum = 0.0f, powerSum = 0.0f;
  nearbyWeights(position, normal, w, weightSum, powerSum);
  LightPick p;
  if (!(weightSum > 0.0f) || !std::isfinite(weightSum)) return p;  // pmf 0: nothing reaches
  // Inverse CDF over the lights that reach; the last one that reaches takes what rounding
  // leaves.
  float below = 0.0f, pmf = 0.0f;
  std::size_t last = nearby_.size();
  for (std::size_t i = 0; i < nearby_.size(); ++i) {
    const float pmfI = nearbyPmf(i, w, weightSum, powerSum);
    if (!(pmfI > 0.0f)) continue;
    if (last != nearby_.size()) below += pmf;
    last = i;
    pmf = pmfI;
    if (u < below + pmf) break;
  }
  p.kind = nearby_[last].kind;
  p.index = nearby_[last].index;
  p.pmf = pmf;
  p.remapped = std::clamp((u - below) / pmf, 0.0f, 0x1.fffffep-1f);
  return p;
}

float LightSampler::clusterPmfAt(uint32_t cluster, glm::vec3 position, glm::vec3 normal) const {
  if (nearby_.empty()) return 0.0f;
  float w[kMaxNearbyLights];
  float weightSum = 0.0f, powerSum = 0.0f;
  nearbyWeights(position, normal, w, weightSum, powerSum);
  // Clusters come first in nearby_, in cluster order; clusters with no power are absent.
  for (std::size_t i = 0; i < nearby_.size() && nearby_[i].kind == LightKind::Area; ++i) {
    if (nearby_[i].index == cluster) return nearbyPmf(i, w, weightSum, powerSum);
  }
  return 0.0f;
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
