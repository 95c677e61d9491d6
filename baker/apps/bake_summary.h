// The end of a bake in bounce-bake (a whole one or a merge): the folder written whole, a PNG of
// the map when asked, and what the user reads: the notes, one summary line and the warnings.
#pragma once

#include <chrono>
#include <filesystem>

namespace bounce {

struct SceneBake;

struct BakeOutput {
  std::filesystem::path folder;
  std::filesystem::path scene;
  std::filesystem::path png;  // empty: none
  float exposure = 0.0f;      // the PNG's, EV
  double loadSeconds = 0.0;   // the scene's
  std::chrono::steady_clock::time_point start;
};

// Throws std::runtime_error naming the folder when it cannot be written (nothing of it is then
// written).
void writeBakeAndReport(SceneBake& baked, const BakeOutput& out);

}  // namespace bounce
