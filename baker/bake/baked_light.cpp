#include "bake/baked_light.h"

namespace bounce {
namespace {

TraceSettings withPaths(TraceSettings trace, PathSet paths) {
  trace.paths = paths;
  return trace;
}

}  // namespace

bool holdsBakedDirect(const Scene& scene) {
  for (const Light& light : scene.lights)
    if (light.bakeDirect) return true;
  for (const Material& material : scene.materials)
    if (material.bakeDirect && material.isEmissive()) return true;
  return false;
}

Scene bakedDirectScene(const Scene& scene) {
  Scene copy = scene;
  copy.lights.clear();
  for (const Light& light : scene.lights)
    if (light.bakeDirect) copy.lights.push_back(light);
  for (Material& m : copy.materials)
    if (!m.bakeDirect) m.emission = glm::vec3(0.0f);
  return copy;
}

BakedLight::BakedLight(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                       TraceSettings trace, std::array<const IndirectCache*, 2> cache,
                       bool bakedDirect, PathSet gathered)
    : directScene_(bakedDirectScene(scene)),
      anyBakedDirect_(bakedDirect && holdsBakedDirect(scene)),
      indirect_(scene, geometry, kernel, withPaths(trace, gathered)),
      bakedDirect_(directScene_, geometry, kernel, withPaths(trace, PathSet::DirectOnly)) {
  indirect_.setCache(cache[0]);
  if (cache[1] != cache[0]) {
    indirectB_ = std::make_unique<PathTracer>(scene, geometry, kernel, withPaths(trace, gathered));
    indirectB_->setCache(cache[1]);
  }
}

BakedLight::Sample BakedLight::sample(glm::vec3 position, glm::vec3 normal, SobolSampler& sampler,
                                      int half) const {
  Sample s;
  if (anyBakedDirect_) {
    sampler.setDimension(kDimBakedDirect);
    bool bad = false;
    s.irradiance += bakedDirect_.irradiance(position, normal, sampler, &bad);
    s.nonFinite += bad ? 1 : 0;
  }
  sampler.setDimension(kDimIndirect);
  bool bad = false;
  const PathTracer& indirect = half == 1 && indirectB_ ? *indirectB_ : indirect_;
  s.irradiance += indirect.irradiance(position, normal, sampler, &bad, &s.reachedSurface);
  s.nonFinite += bad ? 1 : 0;
  return s;
}

}  // namespace bounce
