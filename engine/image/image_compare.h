// Error metrics of a linear image `a` against a reference `ref` (same size), per channel and
// over all channels, restricted to a mask. With e = a − b per channel value (b = reference):
//   rmse            = sqrt(mean(e²))
//   relMse          = mean(e² / (b² + kRelMseEpsilon))          (ε = 1e-2, in b's units²)
//   meanAbsRelError = mean(|e| / (|b| + kRelErrorEpsilon))      (ε = 1e-2, in b's units)
//   bias            = mean(e)
//   p99AbsError     = 99th percentile of |e| (nearest rank: the ⌈0.99·n⌉-th smallest)
// The ε keep near-black reference pixels from dominating; 1e-2 is small against the radiance
// of a lit surface in the scenes (~0.1–10 W/(sr·m²)). "all" pools the three channels' values.
// Pixels where either image is not finite are excluded from the metrics and counted.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "image/image.h"

namespace bounce {

inline constexpr double kRelMseEpsilon = 1e-2;
inline constexpr double kRelErrorEpsilon = 1e-2;

struct ChannelError {
  double rmse = 0.0;
  double relMse = 0.0;
  double meanAbsRelError = 0.0;
  double bias = 0.0;
  double p99AbsError = 0.0;
};

struct ImageError {
  std::array<ChannelError, 3> channels;  // r, g, b
  ChannelError all;                      // over every channel value of the compared pixels
  std::size_t comparedPixels = 0;        // inside the mask, finite in both images
  std::size_t nonFinitePixels = 0;       // inside the mask, NaN/Inf in a or ref (excluded)
  std::size_t nonFiniteInImage = 0;      // of those, the ones NaN/Inf in a (a broken render)
  std::size_t nonFiniteInReference = 0;  // of those, the ones NaN/Inf in ref (a broken reference)
};

// Which pixels to compare: keep[i] != 0 compares pixel i (rows top first, like Image).
struct Mask {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> keep;
};

// Reads a mask image (PNG, …): a pixel whose colour channels are all 0 is excluded.
// Throws std::runtime_error naming the file and the reason.
Mask readMask(const std::filesystem::path& path);
// The same from decoded 8-bit pixels: 1 (grey), 2 (grey + alpha), 3 (RGB) or 4 (RGBA) channels.
// A pixel is kept when a colour channel is non-zero; alpha is ignored, so an opaque black
// pixel of an RGBA mask excludes its pixel.
Mask maskFromPixels(const unsigned char* pixels, int width, int height, int channels);

// Throws std::invalid_argument when the sizes of a, ref (and mask) differ.
ImageError compareImages(const Image& a, const Image& ref, const Mask* mask = nullptr);

// The per-pixel relative error r = mean over channels of |a − b| / (|b| + kRelErrorEpsilon).
// Masked-out and non-finite pixels are 0.
std::vector<float> relativeErrorMap(const Image& a, const Image& ref, const Mask* mask = nullptr);

// A display image (sRGB values in [0,1]) of r: a blue → cyan → green → yellow → red ramp with
// r = 0 blue and r >= scale red; masked-out pixels black.
Image falseColour(const std::vector<float>& relativeError, int width, int height, float scale,
                  const Mask* mask = nullptr);
// (Write it with writeDisplayPng, image/image_io.h.)

}  // namespace bounce
