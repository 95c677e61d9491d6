// bounce-compare end to end: files in, numbers and exit codes out.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "support/tool_run.h"

namespace bounce {
namespace {

class CompareCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::temp_directory_path() / ("bounce_compare_cli_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  int run(const std::string& args) {
    const std::string command = std::string(BOUNCE_BIN_DIR) + "/bounce-compare " + args + " > " +
                                (dir_ / "stdout.txt").string() + " 2> " +
                                (dir_ / "stderr.txt").string();
    return test::exitCode(std::system(command.c_str()));
  }
  std::string read(const std::string& name) { return test::readText(dir_ / name); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

TEST_F(CompareCli, JsonMetricsMaskAndErrorImage) {
  // Reference 0.5 everywhere; the image is 0.5 + 0.25 on the left column, 0.5 elsewhere.
  // The mask keeps only the left column, so bias = RMSE = 0.25 in every channel.
  Image ref(4, 4, glm::vec3(0.5f)), a = ref;
  Image mask(4, 4);
  for (int y = 0; y < 4; ++y) {
    a.at(0, y) = glm::vec3(0.75f);
    mask.at(0, y) = glm::vec3(1.0f);
  }
  writeExr(path("a.exr"), a);
  writeExr(path("b.exr"), ref);
  writeDisplayPng(path("mask.png"), mask);
  ASSERT_EQ(run(path("a.exr") + " " + path("b.exr") + " --json --mask " + path("mask.png") +
                " --error-image " + path("error.png")),
            0)
      << read("stderr.txt");
  const nlohmann::json out = nlohmann::json::parse(read("stdout.txt"));
  EXPECT_EQ(out["comparedPixels"], 4);
  EXPECT_NEAR(out["all"]["bias"].get<double>(), 0.25, 1e-7);
  EXPECT_NEAR(out["channels"]["g"]["rmse"].get<double>(), 0.25, 1e-7);
  EXPECT_TRUE(std::filesystem::exists(path("error.png")));
  EXPECT_GT(out["errorImage"]["redAt"].get<double>(), 0.0);
}

TEST_F(CompareCli, SizeMismatchFailsWithAMessage) {
  writeExr(path("a.exr"), Image(4, 4));
  writeExr(path("b.exr"), Image(4, 3));
  EXPECT_NE(run(path("a.exr") + " " + path("b.exr")), 0);
  EXPECT_NE(read("stderr.txt").find("sizes differ"), std::string::npos) << read("stderr.txt");
  EXPECT_NE(run(path("absent.exr") + " " + path("b.exr")), 0);
}

// A broken render must not pass as "no error": all-NaN fails (nothing to compare), partly NaN
// fails unless --allow-nonfinite, and the message names the image.
TEST_F(CompareCli, NonFiniteImageFails) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  writeExr(path("ref.exr"), Image(4, 4, glm::vec3(1.0f)));
  writeExr(path("nan.exr"), Image(4, 4, glm::vec3(nan)));
  EXPECT_NE(run(path("nan.exr") + " " + path("ref.exr")), 0);
  EXPECT_NE(read("stderr.txt").find("nan.exr"), std::string::npos) << read("stderr.txt");

  Image half(4, 4, glm::vec3(1.0f));
  for (int x = 0; x < 4; ++x) half.at(x, 0) = glm::vec3(nan);
  writeExr(path("half.exr"), half);
  EXPECT_NE(run(path("half.exr") + " " + path("ref.exr")), 0);
  EXPECT_NE(read("stderr.txt").find("half.exr"), std::string::npos) << read("stderr.txt");
  EXPECT_EQ(run(path("half.exr") + " " + path("ref.exr") + " --json --allow-nonfinite"), 0);
  const nlohmann::json out = nlohmann::json::parse(read("stdout.txt"));
  EXPECT_EQ(out["comparedPixels"], 12);
  EXPECT_EQ(out["nonFiniteInImage"], 4);
}

// NaN pixels in the reference were dropped without a word (exit 0): now they fail like the
// image's, naming the reference, and are counted apart in the JSON.
TEST_F(CompareCli, NonFiniteReferenceFails) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  writeExr(path("a.exr"), Image(4, 4, glm::vec3(1.0f)));
  Image ref(4, 4, glm::vec3(1.0f));
  ref.at(2, 2) = glm::vec3(nan);
  writeExr(path("ref.exr"), ref);
  EXPECT_EQ(run(path("a.exr") + " " + path("ref.exr")), 1);
  EXPECT_NE(read("stderr.txt").find(path("ref.exr") + ": 1 reference pixels are NaN/Inf"),
            std::string::npos)
      << read("stderr.txt");
  EXPECT_EQ(run(path("a.exr") + " " + path("ref.exr") + " --json --allow-nonfinite"), 0);
  const nlohmann::json out = nlohmann::json::parse(read("stdout.txt"));
  EXPECT_EQ(out["nonFiniteInReference"], 1);
  EXPECT_EQ(out["nonFiniteInImage"], 0);
}

// A mask of the wrong size: the message names the mask, not only the images.
TEST_F(CompareCli, MaskSizeErrorNamesTheMask) {
  writeExr(path("a.exr"), Image(4, 4));
  writeExr(path("b.exr"), Image(4, 4));
  writeDisplayPng(path("small_mask.png"), Image(2, 2, glm::vec3(1.0f)));
  EXPECT_EQ(run(path("a.exr") + " " + path("b.exr") + " --mask " + path("small_mask.png")), 1);
  EXPECT_NE(read("stderr.txt").find(path("small_mask.png") + ": mask size 2x2"), std::string::npos)
      << read("stderr.txt");
}

}  // namespace
}  // namespace bounce
