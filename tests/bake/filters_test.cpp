// Dilation, chart labels, seam stitching and the denoiser on small images.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include <tbb/task_arena.h>

#include "bake/lightmap_filters.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

TEST(Dilation, FillsOneRingWithTheMeanOfFilledNeighbours) {
  Image image(5, 5);
  std::vector<uint8_t> filled(25, 0);
  image.at(1, 2) = glm::vec3(2.0f);
  image.at(3, 2) = glm::vec3(4.0f);
  filled[image.index(1, 2)] = filled[image.index(3, 2)] = 1;
  EXPECT_EQ(dilateOnce(image, filled), 13u);  // two 3×3 rings sharing column 2's three texels
  EXPECT_FLOAT_EQ(image.at(2, 2).x, 3.0f);    // both neighbours
  EXPECT_FLOAT_EQ(image.at(0, 2).x, 2.0f);
  EXPECT_FLOAT_EQ(image.at(4, 1).x, 4.0f);
  EXPECT_FALSE(filled[image.index(0, 0)]);  // two steps away: next round
  dilateOnce(image, filled);
  EXPECT_TRUE(filled[image.index(0, 0)]);
}

TEST(Dilation, LabelsKeepChartsApart) {
  // Texel 1 touches a filled texel of its own chart (1) and one of another chart (5).
  Image image(3, 1);
  std::vector<uint8_t> filled = {1, 0, 1};
  image.at(0, 0) = glm::vec3(1.0f);
  image.at(2, 0) = glm::vec3(5.0f);
  const std::vector<uint32_t> labels = {1, 1, 2};
  dilateOnce(image, filled, &labels);
  EXPECT_FLOAT_EQ(image.at(1, 0).x, 1.0f);  // not (1 + 5)/2
}

// Texels the zero rule stopped at 0 take their lit neighbours' mean within two rings, inside
// their label only, and their relative error becomes 1; farther ones stay 0. An invalid texel
// (the leak guard's, still 0) is no source and is not filled: texel 1's mean is 2, not 1.
TEST(UnresolvedZeros, FilledFromLitNeighboursOfTheirChartWithinTwoRings) {
  Image image(8, 2);
  std::vector<uint8_t> unresolved(16, 0), invalid(16, 0);
  for (int x = 1; x < 5; ++x) unresolved[image.index(x, 0)] = 1;
  invalid[image.index(1, 1)] = 1;
  std::vector<uint32_t> labels(16, 0);
  for (int x = 0; x < 8; ++x) labels[image.index(x, 0)] = x < 5 ? 1 : 2;
  labels[image.index(1, 1)] = 1;
  std::vector<float> error(16, 0.05f);
  image.at(0, 0) = glm::vec3(2.0f);
  for (int x = 5; x < 8; ++x) image.at(x, 0) = glm::vec3(9.0f);  // another chart, lit
  EXPECT_EQ(fillUnresolvedZeros(image, unresolved, invalid, labels, error), 2u);
  EXPECT_EQ(image.at(1, 1), glm::vec3(0.0f));
  EXPECT_EQ(error[image.index(1, 1)], 0.05f);
  EXPECT_EQ(image.at(1, 0), glm::vec3(2.0f));
  EXPECT_EQ(image.at(2, 0), glm::vec3(2.0f));
  EXPECT_EQ(image.at(3, 0), glm::vec3(0.0f));  // three rings away from chart 1's light
  EXPECT_EQ(image.at(4, 0), glm::vec3(0.0f));  // beside chart 2's 9, which must not leak in
  EXPECT_EQ(error[1], 1.0f);
  EXPECT_EQ(error[3], 0.05f);
}

TEST(ChartLabels, ComponentsSeparatedByPadding) {
  const std::vector<uint8_t> mask = {1, 1, 0, 0, 1,  //
                                     0, 1, 0, 0, 1,  //
                                     0, 0, 0, 1, 0};
  const auto labels = labelCharts(5, 3, mask);
  EXPECT_EQ(labels[0], labels[6]);
  EXPECT_EQ(labels[4], labels[13]);  // diagonal neighbours join
  EXPECT_NE(labels[0], labels[4]);
  EXPECT_EQ(labels[2], 0u);
}

// Two charts of one flat strip, cut along a 3D edge: chart A fills columns 0–2 (value 1),
// chart B columns 6–8 (value 3). The cut is A's right border x = 3 and B's left border x = 6.
TEST(SeamStitching, BilinearLookupsAgreeAcrossTheSeam) {
  Image image(9, 4);
  std::vector<uint8_t> filled(36, 0);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 3; ++x) image.at(x, y) = glm::vec3(1.0f), filled[image.index(x, y)] = 1;
    for (int x = 6; x < 9; ++x) image.at(x, y) = glm::vec3(3.0f), filled[image.index(x, y)] = 1;
  }
  std::vector<uint32_t> labels(36);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 9; ++x) labels[image.index(x, y)] = x < 5 ? 1 : 2;
  dilateOnce(image, filled, &labels);
  const std::vector<Seam> seams = {{{3, 0}, {3, 4}, {6, 0}, {6, 4}}};
  const float before = largestSeamJump(image, seams);
  EXPECT_NEAR(before, luminance(glm::vec3(2.0f)), 1e-5f);
  const float mismatch = stitchSeams(image, seams);
  EXPECT_LT(mismatch, 1e-3f);
  EXPECT_LT(largestSeamJump(image, seams), 1e-3f * luminance(glm::vec3(3.0f)));
  // The two sides meet in between, and texels away from the seam are untouched.
  const float met = bilinear(image, {3.0f, 2.0f}).x;
  EXPECT_GT(met, 1.5f);
  EXPECT_LT(met, 2.5f);
  EXPECT_FLOAT_EQ(image.at(0, 1).x, 1.0f);
  EXPECT_FLOAT_EQ(image.at(8, 1).x, 3.0f);
}

TEST(Denoiser, SmoothsNoiseWithinAChartButNeverAcrossCharts) {
  // Two 8×8 charts side by side (no padding, to provoke mixing): noisy 1 ± 0.2 and exact 10.
  const int w = 16, h = 8;
  Image image(w, h);
  DenoiseGuide guide;
  guide.texelSize = 0.1f;
  guide.position.resize(w * h);
  guide.normal.assign(w * h, glm::vec3(0, 0, 1));
  guide.label.resize(w * h);
  guide.relativeError.resize(w * h);
  double noisy = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = image.index(x, y);
      guide.position[i] = glm::vec3(0.1f * x, 0.1f * y, 0);
      guide.label[i] = x < 8 ? 1 : 2;
      const float v = x < 8 ? 1.0f + 0.2f * (((x * 7 + y * 3) % 5) - 2) / 2.0f : 10.0f;
      image.pixels[i] = glm::vec3(v);
      guide.relativeError[i] = x < 8 ? 0.2f : 0.5f;  // loose enough to mix without labels
      if (x < 8) noisy += (v - 1.0) * (v - 1.0);
    }
  }
  denoise(image, guide);
  double after = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float v = image.at(x, y).x;
      if (x < 8)
        after += (v - 1.0) * (v - 1.0);
      else
        EXPECT_FLOAT_EQ(v, 10.0f) << x << "," << y;  // no light from the other chart
    }
  }
  EXPECT_LT(after, 0.25 * noisy);
}

// The denoiser's passes run over rows in parallel, every texel reading the last pass's values:
// the same bytes in a 1- and a 4-thread arena. A 96 × 64 map of two charts with noise (relative
// error 0.2), and a map carried alongside it.
TEST(Denoiser, SameBytesAtAnyThreadCount) {
  const int w = 96, h = 64;
  Image image(w, h), alongside(w, h);
  DenoiseGuide guide;
  guide.texelSize = 0.05f;
  guide.position.resize(w * h);
  guide.normal.assign(w * h, glm::vec3(0, 0, 1));
  guide.label.resize(w * h);
  guide.relativeError.assign(w * h, 0.2f);
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(1.0f, 0.2f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = image.index(x, y);
      guide.position[i] = glm::vec3(0.05f * x, 0.05f * y, 0);
      guide.label[i] = x < 40 ? 1 : 2;
      image.pixels[i] = glm::vec3(noise(rng), noise(rng), noise(rng)) * (x < 40 ? 1.0f : 3.0f);
      alongside.pixels[i] = glm::vec3(noise(rng));
    }
  const auto filter = [&](int threads) {
    std::pair<Image, Image> maps(image, alongside);
    tbb::task_arena(threads).execute([&] { denoise(maps.first, guide, &maps.second); });
    return maps;
  };
  const auto [map1, other1] = filter(1);
  const auto [map4, other4] = filter(4);
  EXPECT_EQ(0, std::memcmp(map1.pixels.data(), map4.pixels.data(),
                           map1.pixels.size() * sizeof(glm::vec3)));
  EXPECT_EQ(0, std::memcmp(other1.pixels.data(), other4.pixels.data(),
                           other1.pixels.size() * sizeof(glm::vec3)));
}

// A light edge whose step is well beyond the noise is kept: one 48×16 chart (2 cm texels) lit
// E = 1 W/m² on the left half and 2 W/m² on the right, each texel with 10% Gaussian noise (the
// default target error). The step, 1 W/m², is 4.5 combined standard errors of two texels across
// it (√(0.1² + 0.2²) = 0.22 W/m²). Averaged along the edge (16 texels), the column on each side
// of it has a standard error of 10%/4 = 2.5% before denoising; a filter without the luminance
// weight would pull it ~25% towards the other side. Bound: within 5% of its side's value.
TEST(Denoiser, KeepsALightEdgeWellBeyondTheNoise) {
  const int w = 48, h = 16;
  Image image(w, h);
  DenoiseGuide guide;
  guide.texelSize = 0.02f;
  guide.position.resize(w * h);
  guide.normal.assign(w * h, glm::vec3(0, 0, 1));
  guide.label.assign(w * h, 1);
  guide.relativeError.assign(w * h, 0.1f);
  std::mt19937 random(7);
  std::normal_distribution<float> noise(0.0f, 0.1f);
  auto truth = [](int x) { return x < 24 ? 1.0f : 2.0f; };
  double noisy = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = image.index(x, y);
      guide.position[i] = glm::vec3(0.02f * x, 0.02f * y, 0);
      image.pixels[i] = glm::vec3(truth(x) * (1.0f + noise(random)));
      noisy += std::pow(image.pixels[i].x / truth(x) - 1.0, 2);
    }
  denoise(image, guide);
  double after = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) after += std::pow(image.at(x, y).x / truth(x) - 1.0, 2);
  for (const int x : {23, 24}) {
    double column = 0.0;
    for (int y = 0; y < h; ++y) column += image.at(x, y).x / h;
    EXPECT_NEAR(column / truth(x), 1.0, 0.05) << "column " << x;
  }
  EXPECT_LT(after, 0.25 * noisy);  // and the noise away from the edge is smoothed
}

}  // namespace
}  // namespace bounce
