// libFuzzer target: bytes → an .exr file → readExr (engine/image/image_io.h), the reader of
// bounce-compare. Allowed: an Image of width × height finite-or-not floats, or a
// std::runtime_error naming the file; anything else aborts.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "fuzz_input_file.h"
#include "image/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::filesystem::path path = bounce::fuzz::writeInput(data, size, "input.exr");
  try {
    const bounce::Image image = bounce::readExr(path);
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() !=
            static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
      std::fprintf(stderr, "readExr returned an image of inconsistent size\n");
      std::abort();
    }
  } catch (const std::runtime_error& e) {
    if (std::strstr(e.what(), path.filename().c_str()) == nullptr) {
      std::fprintf(stderr, "error does not name the file: %s\n", e.what());
      std::abort();
    }
  }
  return 0;
}
