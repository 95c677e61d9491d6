// What a bake is, in the lines the viewer's panel shows: its folder, atlas, texel size, samples,
// estimated error, what it holds and its age. Read from the Bake (layout, VPLs, visibility) and
// from its manifest where bounce-bake wrote the figures (a hand-made manifest, without a
// settingsHash, has none: those lines are then left out). GL-free.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bake_folder/bake_folder.h"

namespace bounce {

struct BakeFacts {
  std::filesystem::path dir;
  int atlasWidth = 0, atlasHeight = 0;  // texels
  float texelSize = 0.0f;               // m, where lightmapScale is 1
  std::optional<double> utilisation;    // covered / atlas texels
  std::optional<long long> charts;
  std::optional<double> samplesPerTexel;                   // mean
  std::optional<double> errorMean, errorP95, errorTarget;  // relative standard error
  std::optional<double> bakeSeconds;                       // wall time of the bake
  std::size_t vpls = 0;
  std::size_t probes = 0, probeGrids = 0;  // irradiance probes, one grid per instance
  std::size_t bakedAreaLights = 0;         // static area lights with baked visibility
  std::size_t punctualLights = 0;          // punctual lights the visibility indexes (static: baked)
  bool errorMap = false;                   // error.exr present
  std::optional<double> ageSeconds;        // since bake.json was written
};

// `dir` is the folder the bake was read from (for its name and bake.json's time); empty for a
// bake held in memory only.
BakeFacts bakeFacts(const Bake& bake, const std::filesystem::path& dir);

// One line each, e.g. "atlas 276 x 72 texels, 85% used, 16 charts", "texel 1.09 cm".
std::vector<std::string> bakeFactLines(const BakeFacts& facts);

// "12 s", "4 min", "3 h", "2 days".
std::string ageText(double seconds);

}  // namespace bounce
