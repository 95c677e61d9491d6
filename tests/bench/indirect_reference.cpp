#include "indirect_reference.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "image/image_io.h"

namespace bounce::test {

Reference cachedReference(const Scene& scene, const Camera& camera, int width, int height, int spp,
                          PathSet paths, const std::string& file, const char* program) {
  namespace fs = std::filesystem;
  const fs::path seFile = fs::path(file).replace_extension(".se.exr");
  if (!file.empty() && fs::exists(file) && fs::exists(seFile)) {
    Reference reference{readExr(file), readExr(seFile)};
    if (reference.radiance.width != width || reference.radiance.height != height) {
      std::string message = file;
      message += " is not " + std::to_string(width) + "x" + std::to_string(height);
      throw std::runtime_error(message);
    }
    std::fprintf(stderr, "%s: reference %s\n", program, file.c_str());
    return reference;
  }
  std::fprintf(stderr, "%s: tracing the %dx%d reference at %d spp\n", program, width, height, spp);
  const auto start = std::chrono::steady_clock::now();
  Reference reference = traceReference(scene, camera, width, height, spp, paths);
  std::fprintf(stderr, "%s: reference traced in %.0f s\n", program,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (!file.empty()) {
    writeExr(file, reference.radiance);
    writeExr(seFile, reference.stdError);
  }
  return reference;
}

}  // namespace bounce::test
