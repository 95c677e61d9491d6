// libFuzzer target: bytes → a scene file → loadScene (engine/scene/load.h). Built once per
// format (BOUNCE_FUZZ_EXTENSION ".gltf" or ".obj"; a glTF input that starts with "glTF" is
// written as .glb). The only allowed outcomes are a Scene that keeps scene_invariants.h or a
// LoadError naming the file; anything else (a crash, a sanitizer report, another exception,
// a broken invariant) aborts, which libFuzzer records as a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "fuzz_input_file.h"
#include "scene/load.h"
#include "support/scene_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::string extension = BOUNCE_FUZZ_EXTENSION;
  if (extension == ".gltf" && size >= 4 && std::memcmp(data, "glTF", 4) == 0) extension = ".glb";
  const std::filesystem::path path = bounce::fuzz::writeInput(data, size, "input" + extension);
  try {
    const bounce::Scene scene = bounce::loadScene(path);
    if (const std::string broken = bounce::test::brokenInvariant(scene); !broken.empty()) {
      std::fprintf(stderr, "loaded scene breaks an invariant: %s\n", broken.c_str());
      std::abort();
    }
  } catch (const bounce::LoadError& e) {
    if (std::strstr(e.what(), path.filename().c_str()) == nullptr) {
      std::fprintf(stderr, "LoadError does not name the file: %s\n", e.what());
      std::abort();
    }
  }
  return 0;
}
