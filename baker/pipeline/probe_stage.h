// bakeScene's probe stage (bake/irradiance_probes.h) as one call: the static instances the atlas
// left without a lightmap region get their baked light as irradiance probes, with the same
// estimator, seed, depth, light choice, sample cap and error target as the lightmap's texels.
// Like the VPL stage it runs once the lightmap is whole (in a merge or on the keeper, not in a
// shard) and is not journalled: every probe is a function of the scene, the settings and its
// index, so the file is byte-identical at any thread count and whichever way the bake ran.
// GL-free.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "bake_folder/bake_manifest.h"
#include "bake_folder/irradiance_probes.h"
#include "pipeline/scene_bake_settings.h"
#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/stage_progress.h"

namespace bounce {

class IndirectCache;

inline constexpr char kStageProbes[] = "probes";

struct ProbeStage {
  IrradianceProbes probes;         // empty (no grid) when no static instance lacks a region
  BakeManifest::Probes manifest;   // bake.json's "probes"
  std::vector<std::string> notes;  // e.g. grids left dark
  double seconds = 0.0;
  // The static lights' visibility per corner of the same instances (corner_visibility_bake.h):
  // occlusion rays traced and seconds, 0 without static lights to bake.
  uint64_t visibilityRays = 0;
  uint64_t visibilityVertices = 0;  // the corners' world vertices, each estimated once
  double visibilitySeconds = 0.0;
};

// `scene` is the scene file's, `statics` = staticScene(scene) that `geometry` and `kernel` trace;
// `withoutRegion` the file indices of the static instances without a lightmap region
// (Atlas::vplLitInstances). `lightmap`, when given, is where the probes' paths end after their
// first reflection (ProbeSettings::cache); `errorFloor` (W/m²) the probes' (ProbeSettings). Throws
// BakeCancelled when the plan's observer cancels.
ProbeStage runProbeStage(const Scene& scene, const Scene& statics, const WorldGeometry& geometry,
                         const RayKernel& kernel, std::span<const uint32_t> withoutRegion,
                         const IndirectCache* lightmap, double errorFloor,
                         const SceneBakeSettings& settings, const StagePlan& plan);

}  // namespace bounce
