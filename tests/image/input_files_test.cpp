// Image inputs and outputs at their edges: UINT EXR channels, inputs that are not
// regular files, a 250-byte output name, all-or-nothing writes of several outputs.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <tinyexr.h>
#include <unistd.h>

#include <fcntl.h>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <future>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "io/atomic_file.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

class InputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("bounce-input-files-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// A 2×1 EXR whose R, G, B channels are UINT with the values 1, 2, 3.
void writeUintExr(const fs::path& path) {
  std::vector<uint32_t> planes[3] = {{3, 3}, {2, 2}, {1, 1}};  // B, G, R
  unsigned char* pointers[3] = {reinterpret_cast<unsigned char*>(planes[0].data()),
                                reinterpret_cast<unsigned char*>(planes[1].data()),
                                reinterpret_cast<unsigned char*>(planes[2].data())};
  EXRHeader header;
  InitEXRHeader(&header);
  EXRImage image;
  InitEXRImage(&image);
  image.num_channels = 3;
  image.images = pointers;
  image.width = 2;
  image.height = 1;
  EXRChannelInfo channels[3] = {};
  int types[3] = {TINYEXR_PIXELTYPE_UINT, TINYEXR_PIXELTYPE_UINT, TINYEXR_PIXELTYPE_UINT};
  const char* names[3] = {"B", "G", "R"};
  for (int c = 0; c < 3; ++c)
    std::snprintf(channels[c].name, sizeof channels[c].name, "%s", names[c]);
  header.num_channels = 3;
  header.channels = channels;
  header.pixel_types = types;
  header.requested_pixel_types = types;
  const char* err = nullptr;
  ASSERT_EQ(SaveEXRImageToFile(&image, &header, path.c_str(), &err), TINYEXR_SUCCESS)
      << (err ? err : "");
}

TEST_F(InputFiles, UintExrChannelsAreRefused) {
  // They were read as float bit patterns (1 → 1.4e-45): a confident, wrong comparison.
  writeUintExr(dir_ / "uint.exr");
  try {
    readExr(dir_ / "uint.exr");
    ADD_FAILURE() << "a UINT EXR was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("uint.exr: cannot read EXR: channel 'B' holds UINT"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(InputFiles, ReadersRefuseWhatIsNotARegularFile) {
  ASSERT_EQ(::mkfifo((dir_ / "fifo.exr").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((dir_ / "fifo.png").c_str(), 0600), 0);
  fs::create_directory(dir_ / "folder.exr");
  auto expectRefused = [&](auto read, const fs::path& path, const std::string& reason) {
    auto attempt = std::async(std::launch::async, [&] {
      try {
        read(path);
        ADD_FAILURE() << path << " was read";
      } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string() + ": " + reason), std::string::npos)
            << e.what();
      }
    });
    if (attempt.wait_for(std::chrono::seconds(10)) == std::future_status::timeout) {
      ADD_FAILURE() << "reading " << path << " blocked";
      const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);  // release the reader
      if (fd >= 0) ::close(fd);
    }
    attempt.get();
  };
  expectRefused([](const fs::path& p) { readExr(p); }, dir_ / "fifo.exr", "is a FIFO");
  expectRefused([](const fs::path& p) { readExr(p); }, dir_ / "folder.exr", "is a directory");
  expectRefused([](const fs::path& p) { readMask(p); }, dir_ / "fifo.png", "is a FIFO");
}

TEST_F(InputFiles, LongestLegalOutputNameIsWritten) {
  // A 250-byte name plus the old ".tmp-<pid>" suffix passed NAME_MAX (255) and was refused.
  // (Appended, not `std::string(246, 'n') + ".exr"`: g++ 12 -O3 reports a false -Warray-bounds
  // on that temporary when the tests' precompiled header is in use.)
  std::string name(246, 'n');
  name.append(".exr");
  const fs::path out = dir_ / name;
  ASSERT_EQ(out.filename().string().size(), 250u);
  writeExr(out, Image(2, 2, glm::vec3(0.25f)));
  EXPECT_EQ(readExr(out).at(1, 1), glm::vec3(0.25f));
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1);  // no temporary file left
}

TEST_F(InputFiles, SeveralOutputsAreAllOrNothing) {
  // The second target is a folder: the first must not be written either.
  fs::create_directory(dir_ / "taken.png");
  const Image image(2, 2, glm::vec3(0.5f));
  const ImageOutput outputs[] = {{dir_ / "first.exr", &image, 0.0f},
                                 {dir_ / "taken.png", &image, 0.0f}};
  try {
    writeImages(outputs);
    ADD_FAILURE() << "writing over a folder succeeded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("taken.png"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "first.exr"));
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1);  // only the folder: no temporary file left
}

}  // namespace
}  // namespace bounce
