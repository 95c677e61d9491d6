#include "render/light_cutoff.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "image/tonemap.h"

namespace bounce {

float steepestDisplaySlope() {
  // D is steepest where the filmic output leaves sRGB's linear toe (x ≈ 0.01) and flattens
  // beyond (its slope at x = 1 is 0.11, under 2% of the peak): forward differences on a 10⁻⁵
  // grid over [0, 1].
  static const float slope = [] {
    const auto display = [](double x) {
      return static_cast<double>(srgbEncode(filmicCurve(static_cast<float>(x))));
    };
    const double h = 1e-5;
    double best = 0.0;
    for (double x = 0.0; x < 1.0; x += h) best = std::max(best, (display(x + h) - display(x)) / h);
    return static_cast<float>(best);
  }();
  return slope;
}

float irradianceFloorForExposure(float exposureEV) {
  const double pi = 3.14159265358979323846;
  return static_cast<float>(pi * std::exp2(-static_cast<double>(exposureEV)) *
                            kCulledLightDisplayStep / steepestDisplaySlope());
}

float cutoffDistance(float intensity, float floor) {
  if (!(intensity > 0.0f)) return 0.0f;
  if (!(floor > 0.0f)) return std::numeric_limits<float>::infinity();
  return std::sqrt(intensity / floor);
}

}  // namespace bounce
