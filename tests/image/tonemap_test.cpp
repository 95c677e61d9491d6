#include <gtest/gtest.h>

#include <cmath>

#include "image/tonemap.h"

TEST(ToneMap, SrgbTransferIsContinuousAndHitsEndpoints) {
  EXPECT_FLOAT_EQ(bounce::srgbEncode(0.0f), 0.0f);
  EXPECT_NEAR(bounce::srgbEncode(1.0f), 1.0f, 1e-6f);
  // The linear and power segments meet at 0.0031308 (IEC 61966-2-1).
  EXPECT_NEAR(bounce::srgbEncode(0.0031308f), 0.0031308f * 12.92f, 1e-5f);
  EXPECT_NEAR(bounce::srgbEncode(0.0031309f), 0.0031308f * 12.92f, 1e-5f);
  EXPECT_NEAR(bounce::srgbEncode(0.5f), 0.735356983f, 1e-5f);  // 1.055·0.5^(1/2.4) − 0.055
}

TEST(ToneMap, FilmicCurveIsMonotonicFromZeroToOne) {
  EXPECT_FLOAT_EQ(bounce::filmicCurve(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(bounce::filmicCurve(1e6f), 1.0f);
  float previous = 0.0f;
  for (float x = 0.001f; x < 100.0f; x *= 1.1f) {
    const float y = bounce::filmicCurve(x);
    EXPECT_GE(y, previous) << x;
    previous = y;
  }
}

// Pinned values of the curve x(2.51x+0.03)/(x(2.43x+0.59)+0.14), computed by hand.
TEST(ToneMap, FilmicCurveHasItsClosedForm) {
  EXPECT_NEAR(bounce::filmicCurve(1.0f), 2.54f / 3.16f, 1e-6f);
  EXPECT_NEAR(bounce::filmicCurve(0.5f), 0.5f * 1.285f / (0.5f * 1.805f + 0.14f), 1e-6f);
  EXPECT_NEAR(bounce::filmicCurve(0.18f), 0.18f * 0.4818f / (0.18f * 1.0274f + 0.14f), 1e-6f);
}

TEST(ToneMap, ExposureDoublesPerEv) {
  // +1 EV on radiance L equals EV 0 on 2L.
  const glm::vec3 a = bounce::toneMap(glm::vec3(0.2f, 0.4f, 0.1f), 1.0f);
  const glm::vec3 b = bounce::toneMap(glm::vec3(0.4f, 0.8f, 0.2f), 0.0f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6f);
}
