#include "render/cost_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace bounce {
namespace {

// The ramp's stops from 0 to scaleMax, evenly spaced.
constexpr std::array<glm::vec3, 6> kRamp = {glm::vec3(0.0f),
                                            glm::vec3(0.0f, 0.0f, 1.0f),
                                            glm::vec3(0.0f, 1.0f, 1.0f),
                                            glm::vec3(0.0f, 1.0f, 0.0f),
                                            glm::vec3(1.0f, 1.0f, 0.0f),
                                            glm::vec3(1.0f, 0.0f, 0.0f)};

std::string formatCount(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(value));
  return text;
}

}  // namespace

std::string_view costCountName(CostCount count) {
  switch (count) {
    case CostCount::Lights:
      return "lights";
    case CostCount::Vpls:
      return "vpls";
    case CostCount::ShadowTaps:
      return "taps";
  }
  return "vpls";
}

std::optional<CostCount> parseCostCount(std::string_view name) {
  for (const CostCount count : {CostCount::Lights, CostCount::Vpls, CostCount::ShadowTaps})
    if (costCountName(count) == name) return count;
  return std::nullopt;
}

float costCountOf(glm::vec3 pixel, CostCount count) {
  return count == CostCount::Lights ? pixel.r : count == CostCount::Vpls ? pixel.g : pixel.b;
}

CostStats costStats(const Image& counts) {
  CostStats stats;
  for (const glm::vec3& p : counts.pixels) {
    stats.meanLights += p.r;
    stats.meanVpls += p.g;
    stats.meanShadowTaps += p.b;
    stats.maxLights = std::max(stats.maxLights, p.r);
    stats.maxVpls = std::max(stats.maxVpls, p.g);
    stats.maxShadowTaps = std::max(stats.maxShadowTaps, p.b);
  }
  const double n = static_cast<double>(std::max<std::size_t>(counts.pixels.size(), 1));
  stats.meanLights /= n;
  stats.meanVpls /= n;
  stats.meanShadowTaps /= n;
  return stats;
}

glm::vec3 costColour(float c, float scaleMax) {
  if (!(c > 0.0f)) return kRamp[0];
  if (c > scaleMax) return glm::vec3(1.0f);
  const float x = c / scaleMax * static_cast<float>(kRamp.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(x), kRamp.size() - 2);
  return glm::mix(kRamp[i], kRamp[i + 1], x - static_cast<float>(i));
}

float costScaleMax(float x) {
  float decade = 1.0f;
  for (;;) {
    for (const float step : {1.0f, 2.0f, 5.0f})
      if (step * decade >= x) return step * decade;
    decade *= 10.0f;
  }
}

int costLegendRows(int height) {
  return std::min(height, std::max(4, height / 16));
}

Image costFalseColour(const Image& counts, CostCount count, float scaleMax) {
  Image out(counts.width, counts.height);
  for (std::size_t i = 0; i < counts.pixels.size(); ++i)
    out.pixels[i] = costColour(costCountOf(counts.pixels[i], count), scaleMax);
  const int rows = costLegendRows(counts.height);
  const int w = counts.width;
  for (int y = counts.height - rows; y < counts.height; ++y)
    for (int x = 0; x < w; ++x) {
      const float at = w > 1 ? static_cast<float>(x) / static_cast<float>(w - 1) : 0.0f;
      glm::vec3 colour = costColour(at * scaleMax, scaleMax);
      if (at == 0.0f) colour = kRamp[0];
      // Ticks at 0, ¼, ½, ¾ and 1 of the scale; a black rule above the bar.
      for (int q = 0; q <= 4; ++q)
        if (x == (w - 1) * q / 4) colour = glm::vec3(1.0f);
      if (y == counts.height - rows && rows > 1) colour = glm::vec3(0.0f);
      out.at(x, y) = colour;
    }
  return out;
}

std::string describeCostLegend(CostCount count, float scaleMax) {
  std::string text = std::string(costCountName(count)) + " per pixel: bar at the bottom from 0 " +
                     "(left) to " + formatCount(scaleMax) + " (right), ticks at";
  for (int q = 0; q <= 4; ++q)
    text += (q ? ", " : " ") + formatCount(scaleMax * static_cast<float>(q) / 4.0f);
  return text + "; black 0, then blue, cyan, green, yellow, red at " + formatCount(scaleMax) +
         ", white above";
}

}  // namespace bounce
