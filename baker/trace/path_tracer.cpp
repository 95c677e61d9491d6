#include "trace/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "bake_folder/vpl.h"
#include "scene/light_falloff.h"
#include "trace/sampling.h"

namespace bounce {

namespace {

// Sampler dimensions (2D pairs) used at each path vertex, relative to 4·reflections.
constexpr uint32_t kDimLightPick = 0;   // light (CDF) then emitter triangle (alias bin + coin)
constexpr uint32_t kDimLightPoint = 1;  // point on the emitter triangle
constexpr uint32_t kDimBrdf = 2;        // cosine-weighted direction
constexpr uint32_t kDimRoulette = 3;    // Russian roulette
constexpr uint32_t kDimsPerVertex = 4;

// A shadow ray is shortened by this fraction so that it stops short of its (offset) target.
constexpr float kShadowShorten = 1e-4f;

bool finiteRay(const Ray& ray) {
  return isFinite(ray.origin) && isFinite(ray.direction) && !std::isnan(ray.tmin) &&
         !std::isnan(ray.tmax) && glm::dot(ray.direction, ray.direction) > 0.0f;
}

}  // namespace

PathTracer::PathTracer(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                       const TraceSettings& settings, std::vector<Vpl> vpls)
    : scene_(scene),
      geometry_(geometry),
      kernel_(kernel),
      settings_(settings),
      emitters_(scene, geometry),
      vpls_(std::move(vpls)),
      lights_(scene, geometry, emitters_, vpls_) {
  settings_.maxDepth = std::max(settings_.maxDepth, 0);
  byPlace_ = settings_.lightChoice == LightChoice::ByPlace && lights_.choosesByPlace();
  minReflections_ = settings_.paths == PathSet::IndirectOnly ? 2 : 0;
  maxReflections_ =
      settings_.paths == PathSet::DirectOnly ? std::min(1, settings_.maxDepth) : settings_.maxDepth;
}

bool PathTracer::visible(glm::vec3 from, glm::vec3 fromNormal, glm::vec3 to,
                         glm::vec3 toNormal) const {
  Ray ray;
  ray.origin = offsetRayOrigin(from, fromNormal, to - from);
  // A target on a surface is lifted off it too (towards `from`), so it never occludes itself.
  const glm::vec3 target =
      glm::dot(toNormal, toNormal) > 0.0f ? offsetRayOrigin(to, toNormal, from - to) : to;
  ray.direction = target - ray.origin;
  ray.tmin = 0.0f;
  ray.tmax = 1.0f - kShadowShorten;
  if (!finiteRay(ray)) return false;
  return !kernel_.occluded(ray);
}

glm::vec3 PathTracer::sampleLight(const SurfacePoint& point, SobolSampler& sampler) const {
  if (lights_.empty()) return glm::vec3(0.0f);
  const uint32_t base = sampler.dimension();
  sampler.setDimension(base + kDimLightPick);
  const glm::vec2 u = sampler.get2D();
  const LightPick pick =
      byPlace_ ? lights_.pickAt(u.x, point.position, point.geometricNormal) : lights_.pick(u.x);
  if (!(pick.pmf > 0.0f)) return glm::vec3(0.0f);
  switch (pick.kind) {
    case LightKind::Area:
      // BRDF-only estimates count area emitters only where bounce rays hit them.
      if (settings_.strategy == LightStrategy::BrdfOnly) return glm::vec3(0.0f);
      sampler.setDimension(base + kDimLightPoint);
      return sampleAreaLight(point, pick, u.y, sampler);
    case LightKind::Punctual:
      return deltaLight(point, scene_.lights[pick.index]) / pick.pmf;
    case LightKind::Virtual:
      return virtualLight(point, vpls_[pick.index]) / pick.pmf;
  }
  return glm::vec3(0.0f);
}

glm::vec3 PathTracer::sampleAreaLight(const SurfacePoint& point, const LightPick& pick, float coin,
                                      SobolSampler& sampler) const {
  const glm::vec2 onTriangle = sampler.get2D();
  // A pick by place names a cluster; the pmf of the set times the triangle's within it.
  const EmitterSample light =
      byPlace_ ? emitters_.sampleCluster(pick.index, {pick.remapped, coin}, onTriangle)
               : emitters_.sample({pick.remapped, coin}, onTriangle);
  const float setPmf = pick.pmf;

  const glm::vec3 toLight = light.position - point.position;
  const float dist2 = glm::dot(toLight, toLight);
  if (!(dist2 > 0.0f) || !std::isfinite(dist2)) return glm::vec3(0.0f);
  const glm::vec3 wi = toLight / std::sqrt(dist2);
  float cosLight = glm::dot(light.normal, -wi);
  if (light.doubleSided) cosLight = std::abs(cosLight);
  const float cosSurface = glm::dot(point.shadingNormal, wi);
  if (cosLight <= 0.0f || cosSurface <= 0.0f || glm::dot(point.geometricNormal, wi) <= 0.0f) {
    return glm::vec3(0.0f);
  }
  // Area density (the set's pick pmf × the triangle's) → solid angle density: dω = dA cosθ'/r².
  const float pdfLight = setPmf * light.pdfArea * dist2 / cosLight;
  if (!(pdfLight > 0.0f) || !std::isfinite(pdfLight)) return glm::vec3(0.0f);
  const glm::vec3 lightNormal = glm::dot(light.normal, -wi) > 0.0f ? light.normal : -light.normal;
  if (!visible(point.position, point.geometricNormal, light.position, lightNormal)) {
    return glm::vec3(0.0f);
  }
  const float weight = settings_.strategy == LightStrategy::Mis
                           ? powerHeuristic(pdfLight, cosineHemispherePdf(cosSurface))
                           : 1.0f;
  return point.albedo * kInvPi * light.radiance * (cosSurface * weight / pdfLight);
}

float PathTracer::lightPdfArea(const SurfacePoint& point, uint32_t triangle) const {
  if (!byPlace_) return lights_.areaPmf() * emitters_.pdfArea(triangle);
  const EmitterTable::InCluster in = emitters_.inCluster(triangle);
  if (!(in.pdfArea > 0.0f)) return 0.0f;
  return lights_.clusterPmfAt(in.cluster, point.position, point.geometricNormal) * in.pdfArea;
}

glm::vec3 PathTracer::deltaLight(const SurfacePoint& point, const Light& light) const {
  glm::vec3 wi;
  glm::vec3 incident;  // irradiance at normal incidence, W/m²
  bool reachable = false;
  if (light.type == LightType::Directional) {
    const float len = glm::length(light.direction);
    if (!(len > 0.0f) || !std::isfinite(len)) return glm::vec3(0.0f);
    wi = -light.direction / len;
    incident = light.irradiance;
    if (maxComponent(incident) <= 0.0f || !isFinite(incident)) return glm::vec3(0.0f);
    if (glm::dot(point.shadingNormal, wi) <= 0.0f || glm::dot(point.geometricNormal, wi) <= 0.0f)
      return glm::vec3(0.0f);
    Ray ray;
    ray.origin = offsetRayOrigin(point.position, point.geometricNormal, wi);
    ray.direction = wi;
    reachable = finiteRay(ray) && !kernel_.occluded(ray);
  } else {
    const glm::vec3 toLight = light.position - point.position;
    const float dist2 = glm::dot(toLight, toLight);
    if (!(dist2 > 0.0f) || !std::isfinite(dist2)) return glm::vec3(0.0f);
    wi = toLight / std::sqrt(dist2);
    glm::vec3 intensity = light.intensity;  // W/sr towards the point
    if (light.type == LightType::Spot) {
      const float len = glm::length(light.direction);
      if (!(len > 0.0f)) return glm::vec3(0.0f);
      intensity *= spotFalloff(light, glm::dot(light.direction / len, -wi));
    }
    incident = intensity / dist2;  // inverse-square law
    if (maxComponent(incident) <= 0.0f || !isFinite(incident)) return glm::vec3(0.0f);
    if (glm::dot(point.shadingNormal, wi) <= 0.0f || glm::dot(point.geometricNormal, wi) <= 0.0f)
      return glm::vec3(0.0f);
    reachable = visible(point.position, point.geometricNormal, light.position, glm::vec3(0.0f));
  }
  if (!reachable) return glm::vec3(0.0f);
  return point.albedo * kInvPi * incident * glm::dot(point.shadingNormal, wi);
}

// L = ρ_x/π · E with E the VPL's irradiance (bake_folder/vpl.h vplIrradiance, unclamped), a cosine
// emitter of intensity Φ/π·cosθ; the VPL must also lie in front of the geometric surface.
glm::vec3 PathTracer::virtualLight(const SurfacePoint& point, const Vpl& vpl) const {
  const std::optional<VplIrradiance> e =
      vplIrradiance(vpl, glm::dvec3(point.position), glm::dvec3(point.shadingNormal), 0.0);
  if (!e || !(glm::dot(point.geometricNormal, vpl.position - point.position) > 0.0f))
    return glm::vec3(0.0f);
  if (!visible(point.position, point.geometricNormal, vpl.position, vpl.normal))
    return glm::vec3(0.0f);
  return point.albedo * kInvPi * glm::vec3(e->irradiance);
}

glm::vec3 PathTracer::reflected(SurfacePoint point, glm::vec3 throughput, int depth,
                                uint32_t baseDim, SobolSampler& sampler,
                                bool* reachedSurface) const {
  if (reachedSurface != nullptr) *reachedSurface = false;
  glm::vec3 radiance(0.0f);
  glm::vec3 beta = throughput;
  glm::vec3 previous = point.position;  // the vertex `point` was reached from (none at depth 0)
  // Invariant: `point` is reached after `depth` reflections and its emission is counted.
  for (; depth < maxReflections_; ++depth) {
    const uint32_t dim = baseDim + kDimsPerVertex * static_cast<uint32_t>(depth);
    // A cache of the total light (indirect_cache.h): the light leaving y after depth + 1 or more
    // reflections is ρ/π·E_total; the path ends here.
    if (cache_ != nullptr && cache_->holdsDirect() && depth >= 1 && depth + 1 >= minReflections_) {
      if (const std::optional<glm::vec3> total = cache_->irradianceAt(point, previous)) {
        radiance += beta * point.albedo * kInvPi * *total;
        break;
      }
    }
    // Next-event estimation: light after depth + 1 reflections.
    if (depth + 1 >= minReflections_) {
      sampler.setDimension(dim);
      radiance += beta * sampleLight(point, sampler);
    }
    // The cache (indirect_cache.h): the light after depth + 2 or more reflections, ρ/π·E_indirect;
    // the path then ends after this vertex's BRDF-sampled ray has looked for emission.
    std::optional<glm::vec3> cached;
    if (cache_ != nullptr && !cache_->holdsDirect() && depth >= 1 && depth + 1 >= minReflections_)
      cached = cache_->irradianceAt(point, previous);
    if (cached) radiance += beta * point.albedo * kInvPi * *cached;

    // Continue the path by sampling the BRDF: f·cosθ/pdf = (ρ/π)·cosθ / (cosθ/π) = ρ.
    sampler.setDimension(dim + kDimBrdf);
    const glm::vec3 local = sampleCosineHemisphere(sampler.get2D());
    const glm::vec3 wi = Frame(point.shadingNormal).toWorld(local);
    const float pdfBrdf = cosineHemispherePdf(local.z);
    // Directions below the geometric surface (possible with shading normals) end the path.
    if (!(pdfBrdf > 0.0f) || glm::dot(wi, point.geometricNormal) <= 0.0f) break;
    beta *= point.albedo;
    if (maxComponent(beta) <= 0.0f) break;

    // Russian roulette on the throughput: survive with q = min(1, max β), reweight by 1/q. Not
    // on a cached vertex's last ray: it only looks for emission.
    if (depth >= settings_.rouletteDepth && !cached) {
      const float survive = std::min(1.0f, maxComponent(beta));
      sampler.setDimension(dim + kDimRoulette);
      if (sampler.get1D() >= survive) break;
      beta /= survive;
    }

    Ray ray;
    ray.origin = offsetRayOrigin(point.position, point.geometricNormal, wi);
    ray.direction = wi;
    if (!finiteRay(ray)) break;
    const Hit hit = kernel_.intersect(ray);
    if (!hit.valid()) break;
    SurfacePoint next;
    if (!makeSurfacePoint(scene_, geometry_, ray, hit, next)) break;
    if (reachedSurface != nullptr) *reachedSurface = true;

    // Emission found by the BRDF-sampled ray: depth + 1 reflections.
    if (maxComponent(next.emitted) > 0.0f && depth + 1 >= minReflections_ &&
        settings_.strategy != LightStrategy::LightOnly) {
      float weight = 1.0f;
      // The light strategy's density includes the pick of the area set or cluster
      // (trace/light_sampler.h), made at `point`.
      const float pdfArea = lightPdfArea(point, next.triangle);
      if (settings_.strategy == LightStrategy::Mis && pdfArea > 0.0f) {
        const glm::vec3 d = next.position - point.position;
        const float cosLight = glm::dot(next.geometricNormal, -wi);
        if (cosLight > 0.0f) weight = powerHeuristic(pdfBrdf, pdfArea * glm::dot(d, d) / cosLight);
      }
      radiance += beta * next.emitted * weight;
    }
    if (cached) break;
    previous = point.position;
    point = next;
  }
  return radiance;
}

glm::vec3 PathTracer::clamped(glm::vec3 radiance) const {
  const float limit = settings_.clampRadiance;
  const float peak = maxComponent(radiance);
  return limit > 0.0f && peak > limit ? radiance * (limit / peak) : radiance;
}

glm::vec3 PathTracer::Li(const Ray& ray, SobolSampler& sampler, bool* nonFinite) const {
  if (nonFinite != nullptr) *nonFinite = false;
  const uint32_t baseDim = sampler.dimension();
  if (!finiteRay(ray)) return glm::vec3(0.0f);
  const Hit hit = kernel_.intersect(ray);
  if (!hit.valid()) return glm::vec3(0.0f);
  SurfacePoint point;
  if (!makeSurfacePoint(scene_, geometry_, ray, hit, point)) return glm::vec3(0.0f);
  // Emitters seen directly count fully (no other strategy can find them).
  const glm::vec3 seen = minReflections_ == 0 ? point.emitted : glm::vec3(0.0f);
  const glm::vec3 rest = clamped(reflected(point, glm::vec3(1.0f), 0, baseDim, sampler));
  const glm::vec3 radiance = seen + rest;
  if (isFinite(radiance)) return radiance;
  if (nonFinite != nullptr) *nonFinite = true;
  return glm::vec3(0.0f);
}

glm::vec3 PathTracer::irradiance(glm::vec3 position, glm::vec3 normal, SobolSampler& sampler,
                                 bool* nonFinite, bool* reachedSurface) const {
  if (nonFinite != nullptr) *nonFinite = false;
  // A white (ρ = 1) Lambertian surface reflects Lo = E/π in every direction.
  SurfacePoint point;
  point.position = position;
  point.geometricNormal = normal;
  point.shadingNormal = normal;
  point.albedo = glm::vec3(1.0f);
  const glm::vec3 lo =
      clamped(reflected(point, glm::vec3(1.0f), 0, sampler.dimension(), sampler, reachedSurface));
  const glm::vec3 e = kPi * lo;
  if (isFinite(e)) return e;
  if (nonFinite != nullptr) *nonFinite = true;
  return glm::vec3(0.0f);
}

}  // namespace bounce
