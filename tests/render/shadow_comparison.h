// Comparing a forward render with the reference path tracer's, for the shadow measurements:
// box-filtered supersampling (the tracer averages each pixel's area, the rasterizer samples
// points), which pixels see an emitter, and the mean absolute relative error split into lit,
// penumbra and umbra pixels. Test and benchmark support, GL-free.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "image/image.h"
#include "image/image_compare.h"
#include "scene/scene.h"
#include "trace/camera_render.h"

namespace bounce::test {

using bounce::boxDownsample;  // engine/image/image.h

// Pixels (of the k-times smaller image) none of whose k×k samples in `supersampled` (a forward
// render) sees an emitter, i.e. has radiance of at least half the weakest emitter's.
inline std::vector<bool> nonEmitterPixels(const Scene& scene, const Image& supersampled, int k) {
  float weakest = 1e30f;
  for (const Material& m : scene.materials)
    if (m.isEmissive())
      weakest = std::min(weakest, std::max({m.emission.r, m.emission.g, m.emission.b}));
  const int w = supersampled.width / k, h = supersampled.height / k;
  std::vector<bool> mask(static_cast<std::size_t>(w * h), true);
  for (int y = 0; y < supersampled.height; ++y)
    for (int x = 0; x < supersampled.width; ++x) {
      const glm::vec3 c = supersampled.at(x, y);
      if (std::max({c.r, c.g, c.b}) >= 0.5f * weakest)
        mask[static_cast<std::size_t>((y / k) * w + x / k)] = false;
    }
  return mask;
}

struct ShadowError {
  double meanAbsRelative = 0.0;     // mean over masked pixels and channels of |f − r|/(r + ε)
  double noiseStandardError = 0.0;  // √Σ(σ_i/(r_i + ε))² / N: the tracer's share of its spread
  double noiseMean = 0.0;      // Σ σ_i/(r_i + ε) / N: bounds how much noise inflates the error
  double penumbraShare = 0.0;  // Σ over penumbra pixels of the error / Σ over all
  double umbraShare = 0.0;     // the same over umbra pixels
  double penumbraMean = 0.0;   // mean error over the penumbra pixels alone
  std::size_t pixels = 0, penumbraPixels = 0, umbraPixels = 0;
};

// `forward` against `traced` over `mask`; `unshadowed` (the forward render without shadows)
// classifies pixels by the traced visibility r/u (mean over channels): umbra below 5%, lit
// above 95%, penumbra between. ε = 0.01 W/(sr·m²), as bounce-compare (kRelErrorEpsilon).
inline ShadowError compareToReference(const Image& forward, const CameraRender& traced,
                                      const std::vector<bool>& mask, const Image& unshadowed,
                                      int spp) {
  const double eps = kRelErrorEpsilon;
  ShadowError out;
  double sum = 0.0, penumbra = 0.0, umbra = 0.0, noise = 0.0, noiseSum = 0.0;
  for (int y = 0; y < forward.height; ++y)
    for (int x = 0; x < forward.width; ++x) {
      if (!mask[forward.index(x, y)]) continue;
      const glm::dvec3 f(forward.at(x, y)), r(traced.radiance.at(x, y)), u(unshadowed.at(x, y));
      const glm::dvec3 var(traced.sampleVariance.at(x, y));
      double e = 0.0, ratio = 0.0;
      for (int c = 0; c < 3; ++c) {
        e += std::abs(f[c] - r[c]) / (std::abs(r[c]) + eps) / 3.0;
        const double sigma = std::sqrt(var[c] / spp) / (std::abs(r[c]) + eps) / 3.0;
        noise += sigma * sigma;  // the three channels' errors taken as independent
        noiseSum += sigma;
        ratio += (u[c] > 0.0 ? r[c] / u[c] : 1.0) / 3.0;
      }
      sum += e;
      ++out.pixels;
      if (ratio < 0.05) {
        umbra += e;
        ++out.umbraPixels;
      } else if (ratio <= 0.95) {
        penumbra += e;
        ++out.penumbraPixels;
      }
    }
  const double n = static_cast<double>(std::max<std::size_t>(out.pixels, 1));
  out.meanAbsRelative = sum / n;
  out.noiseStandardError = std::sqrt(noise) / n;
  out.noiseMean = noiseSum / n;
  out.penumbraShare = sum > 0.0 ? penumbra / sum : 0.0;
  out.umbraShare = sum > 0.0 ? umbra / sum : 0.0;
  out.penumbraMean =
      out.penumbraPixels > 0 ? penumbra / static_cast<double>(out.penumbraPixels) : 0.0;
  return out;
}

}  // namespace bounce::test
