#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "image/image_io.h"
#include "io/atomic_file.h"

namespace fs = std::filesystem;
using bounce::Image;

namespace {

fs::path freshDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("bounce_image_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

int countEntries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST(ImageIo, ExrRoundTripIsExactFloat32) {
  Image image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x)
      image.at(x, y) = {x * 0.1f + 1e-7f, y * 123.456f, 1.0f / (1 + x + y)};
  const fs::path file = freshDir("exr") / "a.exr";
  bounce::writeExr(file, image);
  const Image back = bounce::readExr(file);
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    EXPECT_EQ(back.pixels[i], image.pixels[i]) << i;
}

TEST(ImageIo, PngFailureLeavesNoPartialFile) {
  const fs::path dir = freshDir("png_fail");
  // The target name is taken by a folder: the rename must fail and leave nothing else behind.
  fs::create_directories(dir / "taken.png" / "inside");
  EXPECT_THROW(bounce::writePng(dir / "taken.png", Image(4, 4, glm::vec3(1)), 0.0f),
               std::runtime_error);
  EXPECT_EQ(countEntries(dir), 1);
  EXPECT_TRUE(fs::is_directory(dir / "taken.png"));
}

TEST(ImageIo, PngReplacesAnExistingFileWhole) {
  const fs::path dir = freshDir("png_ok");
  bounce::writePng(dir / "a.png", Image(64, 64, glm::vec3(0.5f)), 0.0f);
  const auto first = fs::file_size(dir / "a.png");
  bounce::writePng(dir / "a.png", Image(2, 2, glm::vec3(0.5f)), 0.0f);
  EXPECT_LT(fs::file_size(dir / "a.png"), first);
  EXPECT_EQ(countEntries(dir), 1);  // no temporary left over
}

TEST(ImageIo, UnknownExtensionAndBadSizeAreRefused) {
  const fs::path dir = freshDir("ext");
  EXPECT_THROW(bounce::writeImage(dir / "a.bmp", Image(2, 2), 0.0f), std::runtime_error);
  EXPECT_THROW(bounce::writeExr(dir / "b.exr", Image()), std::runtime_error);
  EXPECT_EQ(countEntries(dir), 0);
}

TEST(ImageIo, MissingExrIsAnErrorNamingTheFile) {
  try {
    bounce::readExr("/nonexistent/x.exr");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.exr"), std::string::npos);
  }
}

// A write that fails at the flush (here: a file-size limit of 100 bytes, met only when stdio
// flushes its buffer) reports the real reason and leaves nothing behind.
TEST(ImageIo, FailedFlushReportsItsReasonAndLeavesNoFile) {
  const fs::path dir = freshDir("fsize");
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);  // get EFBIG, not a signal
  rlimit small = saved;
  small.rlim_cur = 100;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    bounce::writeFileAtomically(dir / "big.bin", std::vector<unsigned char>(1000, 7));
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previousHandler);
  EXPECT_NE(message.find("big.bin"), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_EQ(countEntries(dir), 0);
}
