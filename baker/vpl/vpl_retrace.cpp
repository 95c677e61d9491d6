#include "vpl/vpl_retrace.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>

#include "bake_folder/bake_folder.h"
#include "ray/ray_kernel.h"
#include "scene/world_geometry.h"

namespace bounce {

VplSettings vplSettingsOfBake(const BakeManifest& manifest, std::size_t bakeVplCount) {
  VplSettings settings;
  const auto held = [&] {
    const std::size_t limit = 2 * std::min<std::size_t>(bakeVplCount, 1u << 28) + kVplBatch;
    settings.maxVpls = static_cast<int>(
        std::min<std::size_t>(static_cast<std::size_t>(std::max(settings.maxVpls, 1)), limit));
    return settings;
  };
  // A hand-made manifest leaves cap and errorTarget 0: the defaults hold.
  if (manifest.vpls) {
    if (manifest.vpls->cap > 0)
      settings.maxVpls =
          static_cast<int>(std::min<int64_t>(manifest.vpls->cap, std::numeric_limits<int>::max()));
    if (manifest.vpls->errorTarget > 0.0)
      settings.relativeError = static_cast<float>(manifest.vpls->errorTarget);
  }
  settings.seed = manifest.settings.seed;
  return held();
}

PlacedVplTracer::PlacedVplTracer(const Scene& scene, const VplSettings& settings)
    : scene_(scene), settings_(settings) {}

std::vector<Vpl> PlacedVplTracer::trace(std::span<const glm::mat4> transforms) {
  const std::size_t n = std::min(transforms.size(), scene_.instances.size());
  for (std::size_t i = 0; i < n; ++i) scene_.instances[i].transform = transforms[i];
  const WorldGeometry geometry = flatten(scene_);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  return generateVpls(scene_, geometry, *kernel, settings_).vpls;
}

std::function<std::vector<Vpl>(std::span<const glm::mat4>)> placedVplTracer(const Scene& scene,
                                                                            const Bake& bake) {
  auto tracer = std::make_shared<PlacedVplTracer>(
      scene, vplSettingsOfBake(bake.manifest, bake.vpls ? bake.vpls->size() : 0));
  return [tracer](std::span<const glm::mat4> transforms) { return tracer->trace(transforms); };
}

}  // namespace bounce
