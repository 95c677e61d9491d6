// The cost view (RenderMode::Cost): the frame holds, per pixel, the counts the fragment shader
// evaluated (shaders/cost.glsl): R lights, G VPLs, B shadow-map taps (means over a pixel's
// samples with multisampling; exact integers with one sample). This turns them into numbers and
// into a false-colour picture with its legend. GL-free.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "image/image.h"

namespace bounce {

// The values are the frame's channels: R lights, G VPLs, B shadow-map taps.
enum class CostCount { Lights = 0, Vpls = 1, ShadowTaps = 2 };

std::string_view costCountName(CostCount count);  // "lights", "vpls", "taps"
std::optional<CostCount> parseCostCount(std::string_view name);
float costCountOf(glm::vec3 pixel, CostCount count);

// Mean and largest count per pixel over the frame (every pixel; the background counts 0).
struct CostStats {
  double meanLights = 0.0, meanVpls = 0.0, meanShadowTaps = 0.0;
  float maxLights = 0.0f, maxVpls = 0.0f, maxShadowTaps = 0.0f;
};
CostStats costStats(const Image& counts);

// The false colour of count c on a scale of 0 to `scaleMax` (> 0): black at 0, then blue, cyan,
// green, yellow and red at scaleMax (a fifth of the scale each), white beyond it. Display values
// in [0, 1] (sRGB-encoded as they are).
glm::vec3 costColour(float c, float scaleMax);
// The smallest of 1, 2, 5 × 10^k at or above x (x ≤ 1: 1): the legend's end.
float costScaleMax(float x);

// One count of `counts` in false colour (display values), with the legend drawn into its bottom
// rows: a bar from 0 (left) to scaleMax (right) with white ticks at each quarter, above a
// black rule. The bar is max(4, height/16) rows tall (the whole image when that is less).
Image costFalseColour(const Image& counts, CostCount count, float scaleMax);
int costLegendRows(int height);

// The sentence that reads the legend, e.g. "vpls per pixel: bar at the bottom from 0 (left) to
// 200 (right), ticks at 0, 50, 100, 150, 200; black 0, blue, cyan, green, yellow, red at 200,
// white above".
std::string describeCostLegend(CostCount count, float scaleMax);

}  // namespace bounce
