// Image metrics (image_compare.h) against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image/image_compare.h"

namespace bounce {
namespace {

TEST(CompareImages, ConstantOffsetGivesBiasAndRmse) {
  // a = b + d everywhere: e = d for every value, so bias = d, RMSE = |d|, p99 = |d|,
  // relMSE = d²/(b²+ε), meanAbsRel = |d|/(|b|+ε), in every channel and over all.
  const glm::vec3 b(1.0f, 0.5f, 2.0f);
  const float d = -0.25f;
  const Image ref(8, 4, b);
  const Image a(8, 4, b + glm::vec3(d));
  const ImageError error = compareImages(a, ref);
  EXPECT_EQ(error.comparedPixels, 32u);
  for (int c = 0; c < 3; ++c) {
    const ChannelError& e = error.channels[static_cast<std::size_t>(c)];
    EXPECT_NEAR(e.bias, d, 1e-7);
    EXPECT_NEAR(e.rmse, std::abs(d), 1e-7);
    EXPECT_NEAR(e.p99AbsError, std::abs(d), 1e-7);
    EXPECT_NEAR(e.relMse, d * d / (b[c] * b[c] + kRelMseEpsilon), 1e-7);
    EXPECT_NEAR(e.meanAbsRelError, std::abs(d) / (b[c] + kRelErrorEpsilon), 1e-7);
  }
  EXPECT_NEAR(error.all.bias, d, 1e-7);
  EXPECT_NEAR(error.all.rmse, std::abs(d), 1e-7);
  // Over all channels relMSE is the mean of the three channels' values.
  const double expected = (d * d / (1.0 + kRelMseEpsilon) + d * d / (0.25 + kRelMseEpsilon) +
                           d * d / (4.0 + kRelMseEpsilon)) /
                          3.0;
  EXPECT_NEAR(error.all.relMse, expected, 1e-7);
}

TEST(CompareImages, IdenticalImagesHaveZeroError) {
  const Image a(5, 5, glm::vec3(0.3f));
  const ImageError error = compareImages(a, a);
  EXPECT_EQ(error.all.rmse, 0.0);
  EXPECT_EQ(error.all.relMse, 0.0);
  EXPECT_EQ(error.all.p99AbsError, 0.0);
}

TEST(CompareImages, Percentile99IsNearestRank) {
  // 100 pixels with red error 1, 2, …, 100: the 99th percentile (nearest rank ⌈0.99·100⌉ = 99)
  // is 99; mean error 50.5; RMSE sqrt(Σk²/100) = sqrt(3383.5).
  Image ref(100, 1), a(100, 1);
  for (int x = 0; x < 100; ++x) a.at(x, 0).r = static_cast<float>(x + 1);
  const ImageError error = compareImages(a, ref);
  EXPECT_DOUBLE_EQ(error.channels[0].p99AbsError, 99.0);
  EXPECT_DOUBLE_EQ(error.channels[0].bias, 50.5);
  EXPECT_NEAR(error.channels[0].rmse, std::sqrt(3383.5), 1e-9);
  EXPECT_EQ(error.channels[1].rmse, 0.0);
  // Over all 300 values (200 zeros from green and blue, then 1…100), nearest rank
  // ⌈0.99·300⌉ = 297 is the 97th non-zero value: 97.
  EXPECT_DOUBLE_EQ(error.all.p99AbsError, 97.0);
}

TEST(CompareImages, MaskExcludesPixels) {
  // Left half differs by 1, right half by 3; masking out the left half leaves bias 3.
  Image ref(4, 2), a(4, 2);
  Mask mask{4, 2, std::vector<uint8_t>(8, 1)};
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; ++x) {
      a.at(x, y) = glm::vec3(x < 2 ? 1.0f : 3.0f);
      if (x < 2) mask.keep[a.index(x, y)] = 0;
    }
  }
  EXPECT_DOUBLE_EQ(compareImages(a, ref).all.bias, 2.0);
  const ImageError masked = compareImages(a, ref, &mask);
  EXPECT_EQ(masked.comparedPixels, 4u);
  EXPECT_DOUBLE_EQ(masked.all.bias, 3.0);
}

TEST(CompareImages, NonFinitePixelsAreCountedAndExcluded) {
  Image ref(2, 1, glm::vec3(1.0f)), a(2, 1, glm::vec3(2.0f));
  a.at(0, 0).g = std::numeric_limits<float>::quiet_NaN();
  const ImageError error = compareImages(a, ref);
  EXPECT_EQ(error.nonFinitePixels, 1u);
  EXPECT_EQ(error.comparedPixels, 1u);
  EXPECT_DOUBLE_EQ(error.all.bias, 1.0);
}

TEST(CompareImages, SizeMismatchIsAnError) {
  EXPECT_THROW(compareImages(Image(4, 4), Image(4, 5)), std::invalid_argument);
  const Mask mask{3, 3, std::vector<uint8_t>(9, 1)};
  EXPECT_THROW(compareImages(Image(4, 4), Image(4, 4), &mask), std::invalid_argument);
}

TEST(CompareImages, FalseColourRamp) {
  // Relative errors 0, scale/2, ≥ scale map to blue, green, red.
  const Image ref(3, 1, glm::vec3(1.0f));
  Image a(3, 1, glm::vec3(1.0f));
  const float scale = 0.2f;
  a.at(1, 0) = glm::vec3(1.0f + 0.5f * scale * (1.0f + static_cast<float>(kRelErrorEpsilon)));
  a.at(2, 0) = glm::vec3(5.0f);
  const std::vector<float> r = relativeErrorMap(a, ref);
  EXPECT_NEAR(r[1], 0.5f * scale, 1e-6f);
  const Image colours = falseColour(r, 3, 1, scale);
  EXPECT_EQ(colours.at(0, 0), glm::vec3(0, 0, 1));
  EXPECT_LT(glm::distance(colours.at(1, 0), glm::vec3(0, 1, 0)), 1e-4f);
  EXPECT_EQ(colours.at(2, 0), glm::vec3(1, 0, 0));
}

// Masks keep a pixel when a colour channel is non-zero; alpha never keeps it (an opaque black
// RGBA pixel is excluded), for every channel layout stb can return.
TEST(CompareImages, MaskIgnoresAlpha) {
  const unsigned char grey[] = {0, 255};
  const unsigned char greyAlpha[] = {0, 255, 255, 255};
  const unsigned char rgb[] = {0, 0, 0, 0, 9, 0};
  const unsigned char rgba[] = {0, 0, 0, 255, 255, 255, 255, 255};
  for (const auto& [pixels, channels] :
       {std::pair{grey, 1}, std::pair{greyAlpha, 2}, std::pair{rgb, 3}, std::pair{rgba, 4}}) {
    const Mask mask = maskFromPixels(pixels, 2, 1, channels);
    EXPECT_EQ(mask.keep[0], 0) << channels << " channels";
    EXPECT_EQ(mask.keep[1], 1) << channels << " channels";
  }
}

}  // namespace
}  // namespace bounce
