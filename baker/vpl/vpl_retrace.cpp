#include "vpl/vpl_retrace.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>

#include <nlohmann/json.hpp>

#include "ray/ray_kernel.h"
#include "scene/world_geometry.h"

namespace bounce {

VplSettings vplSettingsOfBake(const std::string& manifestJson, std::size_t bakeVplCount) {
  VplSettings settings;
  const auto held = [&] {
    const std::size_t limit = 2 * std::min<std::size_t>(bakeVplCount, 1u << 28) + kVplBatch;
    settings.maxVpls = static_cast<int>(
        std::min<std::size_t>(static_cast<std::size_t>(std::max(settings.maxVpls, 1)), limit));
    return settings;
  };
  const nlohmann::json manifest = nlohmann::json::parse(manifestJson, nullptr, false);
  if (!manifest.is_object()) return held();
  if (const auto vpls = manifest.find("vpls"); vpls != manifest.end() && vpls->is_object()) {
    if (const auto cap = vpls->find("cap"); cap != vpls->end() && cap->is_number_integer())
      settings.maxVpls = static_cast<int>(
          std::clamp<int64_t>(cap->get<int64_t>(), 1, std::numeric_limits<int>::max()));
    if (const auto error = vpls->find("errorTarget");
        error != vpls->end() && error->is_number() && error->get<double>() > 0.0)
      settings.relativeError = error->get<float>();
  }
  if (const auto bakeSettings = manifest.find("settings");
      bakeSettings != manifest.end() && bakeSettings->is_object())
    if (const auto seed = bakeSettings->find("seed");
        seed != bakeSettings->end() && seed->is_number_unsigned())
      settings.seed = seed->get<uint32_t>();
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
      scene, vplSettingsOfBake(bake.manifestJson, bake.vpls ? bake.vpls->size() : 0));
  return [tracer](std::span<const glm::mat4> transforms) { return tracer->trace(transforms); };
}

}  // namespace bounce
