#include "vpl/vpl_retrace.h"

#include <algorithm>
#include <memory>

#include <nlohmann/json.hpp>

#include "ray/ray_kernel.h"
#include "scene/world_geometry.h"

namespace bounce {

VplSettings vplSettingsOfBake(const std::string& manifestJson) {
  VplSettings settings;
  const nlohmann::json manifest = nlohmann::json::parse(manifestJson, nullptr, false);
  if (!manifest.is_object()) return settings;
  if (const auto vpls = manifest.find("vpls"); vpls != manifest.end() && vpls->is_object()) {
    if (const auto cap = vpls->find("cap"); cap != vpls->end() && cap->is_number_integer())
      settings.maxVpls = std::max(1, cap->get<int>());
    if (const auto error = vpls->find("errorTarget");
        error != vpls->end() && error->is_number() && error->get<double>() > 0.0)
      settings.relativeError = error->get<float>();
  }
  if (const auto bakeSettings = manifest.find("settings");
      bakeSettings != manifest.end() && bakeSettings->is_object())
    if (const auto seed = bakeSettings->find("seed");
        seed != bakeSettings->end() && seed->is_number_unsigned())
      settings.seed = seed->get<uint32_t>();
  return settings;
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

std::function<std::vector<Vpl>(std::span<const glm::mat4>)> placedVplTracer(
    const Scene& scene, const std::string& manifestJson) {
  auto tracer = std::make_shared<PlacedVplTracer>(scene, vplSettingsOfBake(manifestJson));
  return [tracer](std::span<const glm::mat4> transforms) { return tracer->trace(transforms); };
}

}  // namespace bounce
