// How much memory a scene bake will take at its peak, estimated before its large allocations
// (after the atlas, which fixes the texel count), so that a bake over a budget is refused before
// it starts (bounce-bake --max-memory). GL-free.
//
//   peak ≈ max(the peak so far (the atlas may have been it), resident now (the loaded scene,
//              the atlas, the program)
//        + geometry: W·T, T static triangles, W = world triangles and vertices, the ray
//          kernel's BVH (Embree: about kKernelBytesPerTriangle) and the static scene's copy
//        + texels: A·B, A = atlas texels, B = the per-texel arrays of the bake and its output
//        + points: C·P·sizeof(TexelPoint), C covered texels, P sample points per texel
//        + visibility: A·V when the scene has static area lights
//        + VPLs: N·sizeof(Vpl)·2 (the set and the folder's copy))
// The per-texel and per-point figures are the sizes of the structures the bake allocates
// (baker/bake/lightmap_bake.h, texel_coverage.h); the kernel's per-triangle figure was measured
// (docs/baker.md, "Memory").
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

namespace bounce {

struct LightmapLayout;
struct Scene;
struct SceneBakeSettings;

inline constexpr double kKernelBytesPerTriangle = 160.0;  // Embree 3 BVH4 + its triangle copy

struct BakeMemoryEstimate {
  double resident = 0;   // bytes, the process now
  double peakSoFar = 0;  // bytes, the process's peak until now
  double geometry = 0, texels = 0, points = 0, visibility = 0, vpls = 0;
  double peak() const {
    return std::max(peakSoFar, resident + geometry + texels + points + visibility + vpls);
  }
  // "1.23 GB (resident 210 MB, geometry 52 MB, texels 30 MB, sample points 95 MB, ...)".
  std::string describe() const;
};

BakeMemoryEstimate estimateBakeMemory(const Scene& scene, const LightmapLayout& layout,
                                      double utilisation, const SceneBakeSettings& settings);

// The process's resident set now and its peak so far (bytes; 0 where /proc cannot tell).
double residentBytes();
double peakResidentBytes();

// "512M", "4G", "1.5G", "800k" or a plain byte count; throws std::invalid_argument otherwise.
double parseMemorySize(const std::string& text);
std::string formatBytes(double bytes);

}  // namespace bounce
