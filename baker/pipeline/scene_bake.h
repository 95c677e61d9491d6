// The bake of a whole scene as one library call: bakeScene runs the numbered stages (atlas, ray
// kernel, texel coverage, leak guard, irradiance, light visibility, filters, VPLs), reports each
// to a BakeObserver that can cancel (trace/stage_progress.h), and returns the bake folder's
// contents with its manifest, ready for writeBake. Nothing is written here: a cancelled or
// failed bake leaves no file. bounce-bake, the tests, the benchmarks and the viewer's re-bake
// call it. GL-free.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "bake/bake_folder.h"
#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "trace/stage_progress.h"

namespace bounce {

// bounce-bake's options, with its defaults (docs/baker.md).
struct SceneBakeSettings {
  float texelSize = 0.0f;  // m; 0: the density rule (atlas/texel_density.h)
  int texelBudget = 0;     // texels instead of the rule; 0: the rule
  int64_t maxTexels;       // cap (texel_density.h's default)
  int spp;                 // most samples per texel
  float targetError;       // relative standard error to stop a texel at; 0: always spp
  int maxDepth;
  uint32_t seed = 0;
  int threads = 0;  // 0: all cores
  RayBackend backend = RayBackend::Embree;
  bool denoise;
  int vpls;        // most VPLs; 0: none
  float vplError;  // relative standard error of the total VPL flux to stop at
  // Bytes the bake may take at its peak (bake_memory.h's estimate, after the atlas); 0: no limit.
  double maxMemory = 0.0;
  SceneBakeSettings();
};

// The estimate said the bake would go over SceneBakeSettings::maxMemory; nothing was baked.
struct BakeOverMemoryBudget : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SceneBake {
  Bake folder;                     // layout, lightmap, error map, VPLs, visibility and the manifest
  std::vector<std::string> notes;  // the atlas's (e.g. the texel cap) and the visibility's
  uint64_t coveredTexels = 0;
  double estimatedPeakBytes = 0.0;  // bake_memory.h, made after the atlas
  double measuredPeakBytes = 0.0;   // the process's peak resident set at the end
};

// The stages bakeScene will run for this scene and settings, in order (its StagePlan).
std::vector<std::string> sceneBakeStages(const Scene& scene, const SceneBakeSettings& settings);

// Throws BakeCancelled when `observer` cancels, std::runtime_error for a scene with nothing
// static to bake. `observer` may be null.
SceneBake bakeScene(const Scene& scene, const SceneBakeSettings& settings,
                    BakeObserver* observer = nullptr);

}  // namespace bounce
