#include "image/image_compare.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "io/regular_file.h"

namespace bounce {
namespace {

void requireSameSize(const Image& a, const Image& ref, const Mask* mask) {
  auto size = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
  if (a.width != ref.width || a.height != ref.height) {
    throw std::invalid_argument("image sizes differ: " + size(a.width, a.height) +
                                " vs reference " + size(ref.width, ref.height));
  }
  if (mask && (mask->width != ref.width || mask->height != ref.height)) {
    throw std::invalid_argument("mask size " + size(mask->width, mask->height) +
                                " differs from the images' " + size(ref.width, ref.height));
  }
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b);
}

// Running sums of one set of values; the percentile keeps all |e|.
struct Accumulator {
  double sumSq = 0.0, sumRelSq = 0.0, sumAbsRel = 0.0, sum = 0.0;
  std::vector<double> absErrors;

  void add(double a, double b) {
    const double e = a - b;
    sumSq += e * e;
    sumRelSq += e * e / (b * b + kRelMseEpsilon);
    sumAbsRel += std::abs(e) / (std::abs(b) + kRelErrorEpsilon);
    sum += e;
    absErrors.push_back(std::abs(e));
  }

  ChannelError finish() {
    ChannelError out;
    const std::size_t n = absErrors.size();
    if (n == 0) return out;
    const auto dn = static_cast<double>(n);
    out.rmse = std::sqrt(sumSq / dn);
    out.relMse = sumRelSq / dn;
    out.meanAbsRelError = sumAbsRel / dn;
    out.bias = sum / dn;
    // Nearest rank: the ⌈0.99·n⌉-th smallest value (1-based).
    const auto rank = static_cast<std::size_t>(std::ceil(0.99 * dn));
    const auto nth =
        absErrors.begin() + static_cast<std::ptrdiff_t>(std::max<std::size_t>(rank, 1) - 1);
    std::nth_element(absErrors.begin(), nth, absErrors.end());
    out.p99AbsError = *nth;
    return out;
  }
};

glm::vec3 ramp(float t) {
  static const glm::vec3 stops[5] = {{0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
  const float x = std::clamp(t, 0.0f, 1.0f) * 4.0f;
  const int i = std::min(static_cast<int>(x), 3);
  return glm::mix(stops[i], stops[i + 1], x - static_cast<float>(i));
}

}  // namespace

Mask readMask(const std::filesystem::path& path) {
  const std::vector<unsigned char> bytes = readRegularFile(path);
  if (bytes.size() > static_cast<std::size_t>(INT32_MAX))
    throw std::runtime_error(path.string() + ": cannot read mask: larger than 2 GiB");
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()),
                                                &width, &height, &channels, 0);
  if (pixels == nullptr) {
    throw std::runtime_error(path.string() + ": cannot read mask: " + stbi_failure_reason());
  }
  Mask mask = maskFromPixels(pixels, width, height, channels);
  stbi_image_free(pixels);
  return mask;
}

Mask maskFromPixels(const unsigned char* pixels, int width, int height, int channels) {
  Mask mask{
      width, height,
      std::vector<uint8_t>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height))};
  const auto stride = static_cast<std::size_t>(channels);
  const std::size_t colours = channels >= 3 ? 3 : 1;  // grey(+alpha) or RGB(+alpha)
  for (std::size_t i = 0; i < mask.keep.size(); ++i) {
    bool any = false;
    for (std::size_t k = 0; k < colours; ++k) any = any || pixels[i * stride + k] != 0;
    mask.keep[i] = any ? 1 : 0;
  }
  return mask;
}

ImageError compareImages(const Image& a, const Image& ref, const Mask* mask) {
  requireSameSize(a, ref, mask);
  ImageError result;
  std::array<Accumulator, 3> channel;
  Accumulator all;
  for (std::size_t i = 0; i < ref.pixels.size(); ++i) {
    if (mask && mask->keep[i] == 0) continue;
    const glm::vec3 pa = a.pixels[i], pb = ref.pixels[i];
    if (!finite(pa) || !finite(pb)) {
      ++result.nonFinitePixels;
      if (!finite(pa)) ++result.nonFiniteInImage;
      if (!finite(pb)) ++result.nonFiniteInReference;
      continue;
    }
    ++result.comparedPixels;
    for (int c = 0; c < 3; ++c) {
      channel[static_cast<std::size_t>(c)].add(pa[c], pb[c]);
      all.add(pa[c], pb[c]);
    }
  }
  for (std::size_t c = 0; c < 3; ++c) result.channels[c] = channel[c].finish();
  result.all = all.finish();
  return result;
}

std::vector<float> relativeErrorMap(const Image& a, const Image& ref, const Mask* mask) {
  requireSameSize(a, ref, mask);
  std::vector<float> r(ref.pixels.size(), 0.0f);
  for (std::size_t i = 0; i < r.size(); ++i) {
    if ((mask && mask->keep[i] == 0) || !finite(a.pixels[i]) || !finite(ref.pixels[i])) continue;
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
      sum += std::abs(static_cast<double>(a.pixels[i][c]) - ref.pixels[i][c]) /
             (std::abs(static_cast<double>(ref.pixels[i][c])) + kRelErrorEpsilon);
    }
    r[i] = static_cast<float>(sum / 3.0);
  }
  return r;
}

Image falseColour(const std::vector<float>& relativeError, int width, int height, float scale,
                  const Mask* mask) {
  Image out(width, height);
  if (relativeError.size() != out.pixels.size()) {
    throw std::invalid_argument("error map size differs from the image size");
  }
  for (std::size_t i = 0; i < out.pixels.size(); ++i) {
    if (mask && mask->keep[i] == 0) continue;  // black
    out.pixels[i] = ramp(scale > 0.0f ? relativeError[i] / scale : 1.0f);
  }
  return out;
}

}  // namespace bounce
