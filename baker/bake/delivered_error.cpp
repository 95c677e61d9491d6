#include "bake/delivered_error.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include <tbb/parallel_invoke.h>

#include "bake/error_summary.h"
#include "bake/lightmap_filters.h"
#include "trace/rng.h"
#include "trace/sampling.h"

namespace bounce {

namespace {
// Keeps the split's hash apart from other hashes of (seed, texel, sample).
constexpr uint32_t kSplitSalt = 0x5eed5a17u;
}  // namespace

float splitSign(uint32_t seed, uint32_t texel, uint32_t sample) {
  return (hashKeys(seed ^ kSplitSalt, texel, sample) & 1u) != 0u ? 1.0f : -1.0f;
}

glm::vec3 HalfSplit::difference(glm::dvec3 mean, uint32_t n) const {
  if (n == 0) return glm::vec3(0.0f);
  return glm::vec3((signedSum - mean * signs) / static_cast<double>(n));
}

void denoiseWithErrorDraw(Image& map, Image& draw, const DenoiseGuide& guide) {
  // The halves' maps full ± D (for equal halves exactly A and B), each with the standard error of
  // half the samples, √2 the full map's: the denoiser is told so.
  Image a = map, b = map;
  for (std::size_t t = 0; t < map.pixels.size(); ++t) {
    a.pixels[t] += draw.pixels[t];
    b.pixels[t] -= draw.pixels[t];
  }
  DenoiseGuide halves = guide;
  for (float& e : halves.relativeError) e *= std::numbers::sqrt2_v<float>;
  Image again = map;
  tbb::parallel_invoke([&] { denoise(map, guide); }, [&] { denoise(a, halves); },
                       [&] { denoise(b, halves); });
  for (std::size_t t = 0; t < map.pixels.size(); ++t)
    draw.pixels[t] = 0.5f * (a.pixels[t] - b.pixels[t]);
  a = Image();
  b = Image();
  // The denoiser's bias: the weights it used on the map (the same inputs give the same weights)
  // applied to the denoised map.
  Image twice = map;
  denoise(again, guide, &twice);
  for (std::size_t t = 0; t < map.pixels.size(); ++t)
    draw.pixels[t] += twice.pixels[t] - map.pixels[t];
}

std::vector<float> stoppingBias(const Image& full, const std::vector<float>& prefixLuminance,
                                const std::vector<uint8_t>& mask,
                                const std::vector<uint32_t>& labels) {
  struct Sums {
    double difference = 0, light = 0;
    std::size_t texels = 0;
  };
  std::unordered_map<uint32_t, Sums> charts;
  Sums all;
  for (std::size_t t = 0; t < full.pixels.size(); ++t) {
    const double light = luminance(full.pixels[t]);
    if (!mask[t] || !(light > 0.0)) continue;
    Sums& chart = charts[labels[t]];
    for (Sums* s : {&chart, &all}) {
      s->difference += light - prefixLuminance[t];
      s->light += light;
      ++s->texels;
    }
  }
  const double global = all.light > 0.0 ? all.difference / all.light : 0.0;
  std::vector<float> bias(full.pixels.size(), static_cast<float>(global));
  for (std::size_t t = 0; t < bias.size(); ++t) {
    const auto it = charts.find(labels[t]);
    if (it != charts.end() && it->second.texels >= kStopBiasChartTexels)
      bias[t] = static_cast<float>(it->second.difference / it->second.light);
  }
  return bias;
}

void addStoppingBias(Image& draw, const Image& map, const std::vector<float>& bias) {
  for (std::size_t t = 0; t < draw.pixels.size(); ++t) draw.pixels[t] += bias[t] * map.pixels[t];
}

DeliveredError deliveredError(const Image& map, const Image& difference,
                              const std::vector<uint8_t>& mask,
                              const std::vector<uint8_t>& unknown) {
  DeliveredError out;
  out.perTexel.assign(map.pixels.size(), -1.0f);
  std::vector<float> errors;
  double errorSum = 0.0, lightSum = 0.0;
  for (std::size_t t = 0; t < map.pixels.size(); ++t) {
    const float light = luminance(map.pixels[t]);
    if (!mask[t] || !(light > 0.0f)) continue;
    if (unknown[t]) {
      out.perTexel[t] = 1.0f;
      ++out.unknownTexels;
      continue;
    }
    const float error = std::abs(luminance(difference.pixels[t]));
    out.perTexel[t] = error / light;
    errors.push_back(error / light);
    errorSum += error;
    lightSum += light;
  }
  if (errors.empty()) return out;
  out.luminanceWeighted = static_cast<float>(errorSum / lightSum);
  const ErrorSummary summary = summariseErrors(std::move(errors));
  out.mean = summary.mean;
  out.p95 = summary.p95;
  return out;
}

}  // namespace bounce
