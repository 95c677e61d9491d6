// The error and validity views' colours (bake_folder/texel_error.h), texel by texel.
#include <gtest/gtest.h>

#include "bake_folder/bake_folder.h"
#include "bake_folder/texel_error.h"

namespace bounce {
namespace {

TEST(TexelError, FalseColourRunsBlueGreenRedAgainstTheTarget) {
  EXPECT_EQ(errorFalseColour(0.0f, 0.1f), glm::vec3(0, 0, 1));
  EXPECT_EQ(errorFalseColour(0.1f, 0.1f), glm::vec3(0, 1, 0));
  EXPECT_EQ(errorFalseColour(0.05f, 0.1f), glm::vec3(0, 0.5f, 0.5f));
  EXPECT_EQ(errorFalseColour(0.9f, 0.1f), glm::vec3(1, 0, 0));
  EXPECT_EQ(errorFalseColour(kNoErrorEstimate, 0.1f), glm::vec3(0.05f));
  BakeManifest manifest;
  EXPECT_EQ(bakeErrorTarget(manifest), kDefaultErrorTarget);  // a hand-made manifest: 0
  manifest.estimatedError.target = 0.25;
  EXPECT_EQ(bakeErrorTarget(manifest), 0.25f);
  manifest.estimatedError.target = -1.0;
  EXPECT_EQ(bakeErrorTarget(manifest), kDefaultErrorTarget);
}

// Sampled where the texel has an estimate, filled where a chart covers it without one, padding
// where no chart covers it.
TEST(TexelError, ValiditySeparatesSampledFilledAndPadding) {
  Image error(3, 1, glm::vec3(kNoErrorEstimate));
  error.at(0, 0) = glm::vec3(0.07f);
  Image charts(3, 1, glm::vec3(0.0f));
  charts.at(0, 0) = charts.at(1, 0) = glm::vec3(0.3f, 0.6f, 0.2f);
  const Image v = texelValidityImage(error, charts);
  EXPECT_EQ(v.at(0, 0), kValidTexel);
  EXPECT_EQ(v.at(1, 0), kFilledTexel);
  EXPECT_EQ(v.at(2, 0), kPaddingTexel);
}

}  // namespace
}  // namespace bounce
