// Stage 8 of the scene bake (scene_bake_stages.h): the VPLs, into the folder and bake.json.
#include "bake_folder/vpl_clamp.h"
#include "pipeline/scene_bake.h"
#include "pipeline/scene_bake_stages.h"
#include "scene/world_geometry.h"
#include "trace/stopwatch.h"
#include "vpl/vpl_generate.h"

namespace bounce {
namespace {

// bake.json's "vpls": what the vpls file holds (baker/vpl/vpl_generate.h, bake_folder/vpl.h).
// `area`: the static surface area the VPLs lie on, m².
BakeManifest::Vpls vplManifest(const VplSet& set, double area, const SceneBakeSettings& o) {
  BakeManifest::Vpls m;
  m.count = set.vpls.size();
  m.paths = set.paths;
  m.totalFlux = set.totalFlux();
  std::size_t last = 0;  // bounces after the deepest VPL are left out
  for (std::size_t k = 0; k < set.fluxPerBounce.size(); ++k)
    if (set.fluxPerBounce[k] != glm::dvec3(0.0)) last = k + 1;
  m.fluxPerBounce.assign(set.fluxPerBounce.begin(),
                         set.fluxPerBounce.begin() + static_cast<std::ptrdiff_t>(last));
  m.relativeError = set.relativeError;
  m.errorTarget = o.vplError;
  m.cap = o.vpls;
  m.clampDistance = vplClampDistance(area, set.vpls.size());
  return m;
}

}  // namespace

void vplStage(const StaticGeometry& statics, const SceneBakeSettings& o, const StagePlan& plan,
              SceneBake& result) {
  Stopwatch clock;
  if (o.vpls > 0) {
    const std::unique_ptr<StageProgress> stage =
        plan.begin(kStageVpls, static_cast<uint64_t>(o.vpls));
    VplSettings vplSettings;
    vplSettings.maxVpls = o.vpls;
    vplSettings.relativeError = o.vplError;
    vplSettings.seed = o.seed;
    vplSettings.threads = o.threads;
    vplSettings.progress = stage.get();
    // VPL paths run in the static scene too (baker/vpl/vpl_generate.h: staticScene).
    VplSet vpls = generateVpls(*statics.scene, *statics.geometry, *statics.kernel, vplSettings);
    const double area = staticSurfaceArea(*statics.scene, *statics.geometry);
    result.folder.manifest.vpls = vplManifest(vpls, area, o);
    result.folder.vpls = std::move(vpls.vpls);
  }
  result.folder.manifest.measured.seconds.vpls = clock.lap();
}

}  // namespace bounce
